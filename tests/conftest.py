"""What the tests share: the checkout's root, one OpenGL context fixture, sea states (real spectra,
real FFTs, a real EGL context; nothing mocked), a wake cache of their own, and the few helpers more
than one test file uses (the command in this process or its own, scenario files, offscreen frames, RAO
tables).
Test files import them with ``from conftest import ...``."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np
import pytest

from marinesim.angles import wave_beta_from_compass
from marinesim.errors import MarinesimError
from marinesim.sea import Cos2s, Jonswap, SeaState, WaveSystem

# One BLAS thread a process: pytest-xdist runs one worker a core, and BLAS threads beyond the cores spin against
# each other (a 28-step block product of 17,800 wave components took 6 times as long with two threads a worker on
# the 2-core VM). A plugin has loaded numpy in this process already; the workers and subprocesses, started after
# this line, inherit the variable before they load it. A value the caller set is kept.
for _variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")

ROOT = Path(__file__).resolve().parents[1]
"""The checkout: its rao/, hulls/, configs/ and shaders/ are the files the tests read."""
DEFAULT = ROOT / "configs" / "default.toml"
RENDER_SIZE = (320, 180)
"""Offscreen frames are small: a software renderer draws them."""

SEA_SCENARIO = """
[[sea]]
type = "jonswap"
hs_m = 3.0
tp_s = 9.0
from_deg = 45.0
spreading_s = 10.0

[run]
duration_s = 60.0
dt_s = 0.5
seed = 3
"""
"""A wind sea alone, no vessel: 60 s at dt 0.5 s, seed 3."""

VESSEL_SCENARIO = f"""
[ocean]
resolution = 64
tiles = 3

[[sea]]
type = "jonswap"
hs_m = 4.0
tp_s = 10.0
from_deg = 200.0
spreading_s = 10.0

[vessel]
rao = "{ROOT / 'rao' / 'tanker' / 'tanker.4'}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
speed_kn = 6.0
heading_deg = 30.0

[vessel.points]
bridge = [-100.0, 0.0, 30.0]
bow = [120.0, 0.0, 12.0]

[run]
duration_s = 120.0
dt_s = 0.1
seed = 11
"""
"""The WAMIT tanker (RAOs and hull) at 6 kn in a small ocean: 120 s at dt 0.1 s, seed 11."""


def write(tmp_path: Path, text: str, name: str = "scenario.toml") -> Path:
    """``text`` written to ``tmp_path / name``; its path."""
    path = tmp_path / name
    path.write_text(text)
    return path


def cli(*args: str, cwd: Path | str | None = None, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    """``marinesim *args`` run in this process (:func:`marinesim.cli.main`, the entry point a user's command calls)
    in the folder ``cwd`` with the environment ``env`` (default: this one), as a finished process: its exit status,
    and what it printed on stdout and stderr (warnings logged by marinesim included, as a user's terminal shows
    them, and Python warnings under Python's own default filters, as a process of its own prints them). Without a new
    interpreter's start-up it costs only the command's own work. Where a test needs a real process (signals, locks
    held across processes, start-up imports, a pipe for a stream, state kept once per process), it uses
    :func:`cli_process`."""
    import io
    import logging
    import os
    import warnings
    from contextlib import chdir, redirect_stderr, redirect_stdout

    from marinesim.cli import main

    out, err = io.StringIO(), io.StringIO()
    logger, handler = logging.getLogger("marinesim"), logging.StreamHandler(err)
    handler.setLevel(logging.WARNING)  # what Python's last-resort handler prints in a process of its own
    saved_env, propagate = dict(os.environ), logger.propagate
    if env is not None:
        os.environ.clear()
        os.environ.update(env)
    logger.addHandler(handler)
    logger.propagate = False
    try:
        with chdir(cwd or os.getcwd()), redirect_stdout(out), redirect_stderr(err), _as_a_new_process(), \
                warnings.catch_warnings(record=True) as caught:
            _python_warning_filters()
            try:
                status = main([str(arg) for arg in args])
            except SystemExit as exit:  # argparse: --help, --version, a usage error
                status = exit.code if isinstance(exit.code, int) else (0 if exit.code is None else 2)
            finally:
                for w in caught:
                    err.write(warnings.formatwarning(w.message, w.category, w.filename, w.lineno, w.line))
    finally:
        logger.removeHandler(handler)
        logger.propagate = propagate
        if env is not None:
            os.environ.clear()
            os.environ.update(saved_env)
    return subprocess.CompletedProcess(["marinesim", *args], status, out.getvalue(), err.getvalue())


@contextlib.contextmanager
def _as_a_new_process() -> Iterator[None]:
    """What marinesim does once per process set as a new process has it (the cache's one warning not yet given, the
    FFTW wisdom not yet read, no wake kept for want of a cache) for the block, and as it was after: a command run
    in-process warns, and computes, as a user's would."""
    import marinesim.cache
    import marinesim.sea.fft
    import marinesim.wake.cache
    from marinesim.recent import Newest

    saved = marinesim.cache._warned, marinesim.sea.fft._wisdom_read, marinesim.wake.cache._unstored
    marinesim.cache._warned = marinesim.sea.fft._wisdom_read = False
    marinesim.wake.cache._unstored = Newest(marinesim.wake.cache.UNSTORED_KEPT)
    try:
        yield
    finally:
        marinesim.cache._warned, marinesim.sea.fft._wisdom_read, marinesim.wake.cache._unstored = saved


def _python_warning_filters() -> None:
    """The warning filters a Python process starts with (no ``-W``): each warning shown once per place, deprecations
    only from ``__main__``, import and resource warnings never (pytest's own filters replaced)."""
    import warnings

    warnings.resetwarnings()
    warnings.simplefilter("default")
    for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
        warnings.simplefilter("ignore", category)
    warnings.filterwarnings("default", category=DeprecationWarning, module="__main__")


def cli_process(*args: str, cwd=None, timeout: float = 600, **kwargs) -> subprocess.CompletedProcess:
    """``python -m marinesim *args`` in a process of its own, as a user runs it; its output as text. ``timeout`` (s)
    only stops a hung command: a whole command on a loaded machine stays far below it."""
    return subprocess.run([sys.executable, "-m", "marinesim", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=timeout, **kwargs)


@pytest.fixture(scope="module")
def gl_context():
    """A headless OpenGL 4.3 context (EGL: Mesa's llvmpipe without a GPU) for one test module, released
    after it; the module's tests are skipped where no such context can be made."""
    from marinesim.gl import GraphicsError, standalone_context

    try:
        context = standalone_context()
    except GraphicsError as error:
        pytest.skip(str(error))
    yield context
    context.release()


@pytest.fixture(scope="module")
def default():
    """The shipped default scenario (configs/default.toml)."""
    from marinesim.scenario import load_scenario

    return load_scenario(DEFAULT)


@pytest.fixture(scope="module")
def underway(tmp_path_factory):
    """The default scenario with the tanker at 14 kn (Fn 0.145): a Kelvin wake worth drawing."""
    from marinesim.scenario import load_scenario

    text = DEFAULT.read_text().replace("speed_kn = 4.0", "speed_kn = 14.0").replace('"../', f'"{ROOT.as_posix()}/')
    path = tmp_path_factory.mktemp("scenario") / "underway.toml"
    path.write_text(text)
    return load_scenario(path)


def offscreen(scenario, size=RENDER_SIZE, **options):
    """An Offscreen view of ``scenario`` (the viewer's Session without a window); the calling test is
    skipped where no EGL OpenGL 4.3 context can be made."""
    from marinesim.gl import GraphicsError
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.renderer import RenderOptions

    solver = "on" if options.get("solver") else "off"
    try:
        return Offscreen(scenario, size, solver=solver, options=RenderOptions(**options))
    except GraphicsError as error:
        pytest.skip(f"no EGL OpenGL 4.3 here: {error}")


def luminance(image: np.ndarray) -> np.ndarray:
    """Rec. 709 luminance of an RGB image."""
    return image.astype(float) @ [0.2126, 0.7152, 0.0722]


def raw_wamit(path: Path) -> dict[tuple[float, float], np.ndarray]:
    """(period, beta_deg) -> six complex values (RE + i IM) straight from the file's columns."""
    rows = np.loadtxt(path)
    out: dict[tuple[float, float], np.ndarray] = {}
    for per, beta, mode, _, _, re, im in rows:
        out.setdefault((per, beta), np.zeros(6, complex))[int(mode) - 1] = re + 1j * im
    return out


def synthetic_table():
    """A table whose Re/Im are bilinear in omega and beta (so interpolation is exact)."""
    from marinesim.vessel.rao import make_table

    omega = np.linspace(0.2, 2.0, 10)
    beta = np.radians(np.arange(0.0, 181.0, 15.0))
    coefficient = np.array([0.3 + 0.1j, 0.2 - 0.4j, 1.0 + 0.2j, 0.02 - 0.01j, 0.03 + 0.02j, -0.01 + 0.005j])
    values = (coefficient[None, None, :] * (1.5 - 0.5 * omega)[None, :, None]
              * (1.0 + 0.3 * beta)[:, None, None])[None]
    return make_table(omega, beta, [0.0], values, source="synthetic", source_format="synthetic"), coefficient


@pytest.fixture(scope="session")
def north_sea() -> SeaState:
    """A North Sea design-ish state: Hs 4 m, Tp 10 s, gamma 3.3, from 030 deg, cos-2s s = 15."""
    return SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), wave_beta_from_compass(30.0), Cos2s(15.0)),))


@pytest.fixture(scope="session")
def finite_depth_sea() -> SeaState:
    return SeaState((WaveSystem(Jonswap(3.0, 9.0, 3.3), 0.7, Cos2s(10.0)),), depth=40.0)


def close_angle_deg(a: float, b: float) -> float:
    """Smallest difference of two compass angles (deg)."""
    return abs((a - b + 180.0) % 360.0 - 180.0)


__all__ = ["DEFAULT", "RENDER_SIZE", "ROOT", "SEA_SCENARIO", "VESSEL_SCENARIO", "cli", "close_angle_deg", "luminance",
           "offscreen", "raw_wamit", "synthetic_table", "write"]


LONGEST_FIRST = ("test_scenario_training_exercises.py",)
"""Files whose slow tests take longest (the shipped exercises over twenty seeds, a quarter of an hour each on the
2-core VM): they go first of all."""


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The files holding slow tests run first (:data:`LONGEST_FIRST` before the others), each file's tests together
    and in their order. pytest-xdist hands tests out one at a time (pyproject's ``--maxschedchunk=1``), so the long
    runs go side by side on the workers; last (the exercises sort late) they kept one worker busy for half an hour
    after the others had finished."""
    slow = {item.path for item in items if item.get_closest_marker("slow")}
    items.sort(key=lambda item: (item.path not in slow, item.path.name not in LONGEST_FIRST))


@pytest.fixture(scope="session", autouse=True)
def wake_cache(tmp_path_factory):
    """Wakes computed by the tests are cached in a temporary folder, and session logs are signed with a key in
    another: never the user's cache or configuration (subprocesses inherit both)."""
    folders = {"MARINESIM_CACHE_DIR": tmp_path_factory.mktemp("wake-cache"),
               "MARINESIM_CONFIG_DIR": tmp_path_factory.mktemp("config")}
    previous = {name: os.environ.get(name) for name in folders}
    os.environ.update({name: str(folder) for name, folder in folders.items()})
    yield folders["MARINESIM_CACHE_DIR"]
    for name, value in previous.items():
        if value is None:
            del os.environ[name]
        else:
            os.environ[name] = value


def outcome(read: Callable[[Path], object], valid: type, path: Path) -> None:
    """Read ``path``: a ``valid`` object or a one-line :class:`MarinesimError`; anything else fails."""
    try:
        result = read(path)
    except MarinesimError as error:
        assert "\n" not in str(error) and str(error), repr(str(error))
    else:
        assert isinstance(result, valid)


def ray_hits(tri: np.ndarray, origin, direction) -> tuple[np.ndarray, np.ndarray]:
    """Distances along the ray and the faces of the triangles ``tri`` (t, 3, 3) it crosses, nearest first
    (Moller-Trumbore)."""
    o, d = np.asarray(origin, float), np.asarray(direction, float) / np.linalg.norm(direction)
    e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
    p = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-12
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = o - tri[:, 0]
    u = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    v = (q @ d) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    found = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-6)
    order = np.argsort(t[found])
    return t[found][order], np.flatnonzero(found)[order]


def run_lengths(mask: np.ndarray) -> float:
    """Mean length (px) of the runs of True along the rows of ``mask``."""
    edges = np.diff(np.pad(mask.astype(int), ((0, 0), (1, 1))), axis=1)
    starts, ends = np.nonzero(edges == 1), np.nonzero(edges == -1)
    return float(np.mean(ends[1] - starts[1])) if len(starts[1]) else 0.0


# --- waiting on a process: for events, not for the clock -----------------------------------------------------------

HANG_S = 1800.0
"""How long a test waits for a command to end, or for an event in a command's life (a file appearing, a library
mapped), before it calls the wait a hang and fails: 30 minutes. The slowest wait, for a day's export to have
written 100 kB of its table, took 71 s on a 2-core machine running the campaign's three workers, and 284 s with two
CPU burners and other test sessions beside them (every other event awaited, under 30 s there). 30 minutes is six
times the worst seen: only a process that has stopped making progress gets there, and a hang still ends the test."""


def mapped(pid: int, library: str) -> bool:
    """Whether process ``pid`` has mapped a shared library whose path contains ``library`` (Linux's /proc): its
    import has begun."""
    try:
        return library in Path(f"/proc/{pid}/maps").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return False


def until(ready: Callable[[], bool], process: subprocess.Popen) -> str:
    """Wait, looking every 10 ms, until ``ready()`` holds while ``process`` runs: "" once it does, else why it never
    will (the process ended first, or :data:`HANG_S` passed: a hang). No limit but that: a slow machine only waits
    longer."""
    start = time.monotonic()
    while not ready():
        if process.poll() is not None:
            return f"the process ended first (exit {process.returncode})"
        if time.monotonic() - start > HANG_S:
            return f"not within {HANG_S:g} s (a hang)"
        time.sleep(0.01)
    return ""


def wait_for(ready: Callable[[], bool], process: subprocess.Popen, what: str) -> None:
    """:func:`until` ``ready()``; where it never holds, the process is killed and the test fails saying ``what`` (the
    event awaited) did not come, why, and the end of the process's stderr."""
    reason = until(ready, process)
    if reason:
        if process.poll() is None:
            process.kill()
        stderr = process.communicate()[1] or ""
        stderr = stderr.decode(errors="replace") if isinstance(stderr, bytes) else stderr
        pytest.fail(f"{what}: {reason}; stderr: {stderr[-600:]}")


class Hang(BaseException):
    """A block that did not end within :data:`HANG_S`. Not an Exception: the code under test's ``except Exception``
    cannot take it for an error of its own, and hypothesis reports it at once rather than run the hang again to
    shrink the example."""


@contextlib.contextmanager
def hang_guard(what: str) -> Iterator[None]:
    """Raise :class:`Hang` naming ``what`` in the block if it has not ended within :data:`HANG_S` (SIGALRM, so only
    in the main thread; elsewhere the block runs unguarded): a bound only a hang reaches, where a deadline of a few
    seconds would measure the machine's speed."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def hang(signum: int, frame: object) -> None:
        raise Hang(f"{what}: no end after {HANG_S:g} s (a hang)")

    previous = signal.signal(signal.SIGALRM, hang)
    signal.setitimer(signal.ITIMER_REAL, HANG_S)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
