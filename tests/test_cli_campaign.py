"""The hardening campaign re-run as a user meets it: ``marinesim ...`` on mutated RAO files and meshes, mutated
scenarios, bad options, signals, two writers of one file, a damaged wake cache and outputs that are not regular
files. Six cases per category, seeded, so every run tries the same ones. Signals and two writers need processes of
their own (``python -m marinesim``, run side by side); every other case calls the entry point in this process
(conftest's :func:`~conftest.cli`, one after another), under a hang guard.

Each case is classified: clean (exit 0 with valid outputs, or exit 2/130/143 with exactly one line on
stderr; a process killed by the signal before Python could handle it, with nothing on stderr, counts as
clean too), traceback (a traceback, or an exit that is neither of those: several lines, another status),
hang (no exit within :data:`~conftest.HANG_S`), silent (exit 0 where the input had to be refused or noted, or a wrong
number with no word), or data lost (an output that was there changed, a table whose sidecar names other
bytes, a leftover ``.part`` or ``.lock`` file, an input written over). The table is printed (``pytest
-s``) and written as markdown to ``$MARINESIM_CAMPAIGN_REPORT`` when that is set.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest
import trimesh

from conftest import HANG_S, ROOT, Hang, cli, hang_guard, mapped, until

PROGRESS = re.compile(r"\d+%\||: (\d+% \(\d+/\d+ \w+\)|done \(\d+ \w+, [\d.]+ s\)"
                      r"|stopped at \d+% \(\d+/\d+ \w+, [\d.]+ s\))$")
"""A progress line, not a message: a bar's (tqdm, on a terminal) or a plain one (stderr not a terminal)."""
VOLATILE = {"seconds", "seconds_computing", "cached"}  # what a wake's JSON may say differently from the cache
WORKERS = 3
"""How many cases with processes of their own run side by side."""
PER_CATEGORY = 6
"""Cases run per category: a seeded choice among those built (the fuzz tests try many more in one process)."""
COLUMNS = ("clean", "traceback", "hang", "silent", "data lost")
HOSTILE = ["nan", "inf", "-inf", "1e308", "-1e308", "0", "-1", "x", "", "99999999999", "1e-300", "[", "\""]


@functools.cache
def environment() -> dict[str, str]:
    """The processes' environment: this one's as the tests set it (their cache and configuration folders), taken
    once, before any case runs in this process (a case run here swaps ``os.environ`` while it runs)."""
    return dict(os.environ, PYTHONPATH=str(ROOT))


@dataclass(frozen=True)
class Case:
    """One thing a user does: ``run(folder)`` does it in an empty folder and returns (verdict, detail)."""

    category: str
    name: str
    run: Callable[[Path], tuple[str, str]]
    own_process: bool = False
    """Whether its commands run in processes of their own (signals, two writers): such cases run side by side."""


def here(args: list[str], cwd: Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess | None:
    """``marinesim *args`` in ``cwd``, in this process (conftest's :func:`~conftest.cli`); None if it did not end
    within :data:`HANG_S`."""
    try:
        with hang_guard(f"marinesim {' '.join(args)}"):
            return cli(*args, cwd=cwd, env=env)
    except Hang:
        return None


def verdict(result: subprocess.CompletedProcess | None, outputs_ok: Callable[[], str] = lambda: "") -> tuple[str, str]:
    """Classify one process; ``outputs_ok`` returns what is wrong with the files it left ("" if nothing).
    Progress-bar lines on stderr are not counted as message lines."""
    if result is None:
        return "hang", f"no exit in {HANG_S:g} s"
    lines = [line for line in result.stderr.strip().splitlines() if line.strip() and not PROGRESS.search(line)]
    if "Traceback" in result.stderr:
        return "traceback", result.stderr[-400:]
    wrong = outputs_ok()
    if wrong:
        return "data lost", wrong
    if result.returncode == 0:
        return "clean", ""
    if result.returncode in (2, 130, 143) and len(lines) == 1:
        return "clean", lines[0]
    if result.returncode in (-signal.SIGINT, -signal.SIGTERM) and not lines:
        return "clean", "killed by the signal before Python handled it"
    return "traceback", f"exit {result.returncode}, {len(lines)} lines: {result.stderr[-400:]}"


def leftovers(folder: Path) -> str:
    """Temporary or lock files left in ``folder``, and tables whose sidecar names other bytes."""
    wrong = [p.name for p in folder.iterdir() if ".part" in p.name or p.name.endswith(".lock")]
    for sidecar in folder.glob("*.json"):
        if not sidecar.is_file():  # a FIFO staged by a case: opening it would block
            continue
        table = sidecar.with_suffix("")
        try:
            meta = json.loads(sidecar.read_text())
        except (ValueError, UnicodeDecodeError):
            wrong.append(f"{sidecar.name} is not JSON")
            continue
        if isinstance(meta, dict) and "data_sha256" in meta:
            if not table.is_file() or meta["data_sha256"] != hashlib.sha256(table.read_bytes()).hexdigest():
                wrong.append(f"{sidecar.name} does not name the bytes of {table.name}")
    return ", ".join(wrong)


# --- mutations ---------------------------------------------------------------------------------------------

def mutate_text(text: str, rng: random.Random) -> str:
    """One to three edits: a line deleted or duplicated, a token made hostile, the text cut."""
    lines = text.splitlines()
    for _ in range(rng.randint(1, 3)):
        if not lines:
            break
        at = rng.randrange(len(lines))
        what = rng.choice(["delete", "duplicate", "token", "token", "cut"])
        if what == "delete":
            del lines[at]
        elif what == "duplicate":
            lines.insert(at, lines[at])
        elif what == "token":
            parts = lines[at].split(" ")
            parts[rng.randrange(len(parts))] = rng.choice(HOSTILE)
            lines[at] = " ".join(parts)
        else:
            lines = lines[:at]
    return "\n".join(lines) + "\n"


def mutate_bytes(data: bytes, rng: random.Random) -> bytes:
    """The bytes cut at a random place, or a few of them overwritten."""
    data = bytearray(data)
    if rng.random() < 0.4:
        return bytes(data[: rng.randrange(len(data))])
    for _ in range(rng.randint(1, 6)):
        data[rng.randrange(len(data))] = rng.randrange(256)
    return bytes(data)


# --- sources -----------------------------------------------------------------------------------------------

def small_capytaine_file(folder: Path) -> Path:
    """A small barge solved by Capytaine (tests/test_formats_fuzz_more.py), written as NetCDF."""
    import capytaine

    from test_formats_fuzz_more import small_capytaine_dataset

    path = folder / "barge.nc"
    capytaine.export_dataset(path, small_capytaine_dataset())
    return path


def native_file(folder: Path) -> Path:
    from marinesim.vessel.native import write_native
    from marinesim.vessel.read import read_rao

    path = folder / "tanker.csv"
    write_native(read_rao(ROOT / "rao" / "tanker" / "tanker.4"), path)
    return path


def scenario_text() -> str:
    """configs/default.toml with absolute paths."""
    return (ROOT / "configs" / "default.toml").read_text().replace('"../', f'"{ROOT.as_posix()}/')


LONG_SCENARIO = scenario_text().replace("duration_s = 600.0", "duration_s = 86400.0")


# --- categories --------------------------------------------------------------------------------------------

def mutated_file_cases(category: str, sources: dict[str, Path], command: Callable[[Path], list[str]],
                       per_source: int) -> list[Case]:
    """``per_source`` seeded mutations of each source file, each given to ``command``."""
    cases = []
    for name, source in sources.items():
        binary = source.suffix in (".nc", ".glb", ".ply") or (source.suffix == ".stl" and "ascii" not in source.name)
        for seed in range(per_source):
            def run(folder: Path, source: Path = source, seed: int = seed, binary: bool = binary) -> tuple[str, str]:
                rng = random.Random(f"{source.name}-{seed}")
                path = folder / f"in{source.suffix}"
                data = source.read_bytes()
                if binary:
                    path.write_bytes(mutate_bytes(data, rng))
                else:
                    path.write_text(mutate_text(data.decode(), rng))
                result = here(command(path), folder)
                return verdict(result, lambda: leftovers(folder) or json_error(result))
            cases.append(Case(category, f"{name} #{seed}", run))
    return cases


def json_error(result: subprocess.CompletedProcess | None) -> str:
    """What is wrong with a successful ``--json`` answer (it must be one JSON document)."""
    if result is None or result.returncode != 0:
        return ""
    try:
        json.loads(result.stdout)
    except ValueError:
        return "exit 0 without a JSON answer"
    return ""


def rao_cases(folder: Path) -> list[Case]:
    sources = {"wamit": ROOT / "rao" / "tanker" / "tanker.4", "veres": ROOT / "rao" / "s175" / "input.re1",
               "native": native_file(folder), "capytaine": small_capytaine_file(folder)}
    return mutated_file_cases("RAO files", sources, lambda path: ["rao", str(path), "--json"], 3)


def mesh_cases(folder: Path) -> list[Case]:
    wigley = trimesh.load(ROOT / "hulls" / "wigley.stl", force="mesh")
    sources = {"gdf": ROOT / "hulls" / "tanker.gdf", "stl": ROOT / "hulls" / "wigley.stl"}
    for name, kind, extension in (("stl-ascii", "stl_ascii", "stl"), ("obj", "obj", "obj"), ("ply", "ply", "ply"),
                                  ("off", "off", "off"), ("glb", "glb", "glb")):
        path = folder / f"wigley-{name}.{extension}"
        data = wigley.export(file_type=kind)
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
        sources[name] = path
    return mutated_file_cases("meshes", sources, lambda path: ["hull", str(path), "--json"], 2)


def scenario_cases() -> list[Case]:
    cases = []
    for seed in range(10):
        def run(folder: Path, seed: int = seed) -> tuple[str, str]:
            path = folder / "s.toml"
            path.write_text(mutate_text(scenario_text(), random.Random(f"scenario-{seed}")))
            result = here(["export", str(path), "--out", "m.csv", "--duration", "2", "--quiet"], folder)
            return verdict(result, lambda: leftovers(folder) or exported(folder, result))
        cases.append(Case("scenarios", f"#{seed}", run))
    return cases


def exported(folder: Path, result: subprocess.CompletedProcess | None) -> str:
    """What is missing after an export that exited 0."""
    if result is None or result.returncode != 0:
        return ""
    return "" if (folder / "m.csv").is_file() and (folder / "m.csv.json").is_file() else "exit 0 without its pair"


BAD_OPTIONS = [
    ["run", "{scenario}", "--headless", "--duration", "-5"],
    ["render", "{scenario}", "--size", "13x7", "--out", "v.mp4"],
    ["render", "{scenario}", "--fps", "0", "--out", "v.mp4"],
    ["export", "{scenario}", "--out", "m.csv", "--dt", "-1"],
    ["export", "{scenario}", "--out", "m.csv", "--format", "xls"],
    ["export", "{scenario}", "--out", "m.csv", "--seed", "one"],
    ["rao", str(ROOT / "rao" / "tanker" / "tanker.4"), "--headings", "north"],
    ["rao", str(ROOT / "rao" / "tanker" / "tanker.4"), "--roll-damping-pct", "150"],
    ["hull", str(ROOT / "hulls" / "wigley.stl"), "--units", "furlong"],
    ["hull", str(ROOT / "hulls" / "wigley.stl"), "--axes", "x,x,z"],
    ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "-3"],
    ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "10", "--nx", "0"],
    ["sea", "--hs", "-1"],
    ["sea", "--spectrum", "storm"],
    ["sea", "--resolution", "7"],
    ["export", "{scenario}"],
]
"""Invocations a user gets wrong, over every command; each must be one line and exit 2."""


def option_cases() -> list[Case]:
    cases = []
    for args in BAD_OPTIONS:
        def run(folder: Path, args: list[str] = args) -> tuple[str, str]:
            scenario = folder / "s.toml"
            scenario.write_text(scenario_text())
            result = here([a.replace("{scenario}", str(scenario)) for a in args], folder)
            if result is not None and result.returncode == 0:
                return "traceback", "a bad option was accepted (exit 0)"
            return verdict(result, lambda: leftovers(folder))
        cases.append(Case("CLI options", " ".join(args[:1] + args[2:]), run))
    return cases


OLD_TABLE, OLD_SIDECAR = b"time_s\n0.0\n", b'{"seed": 0}\n'


def part_sizes(folder: Path) -> list[int]:
    """The sizes of the export's temporary tables in ``folder`` (one, once it has begun)."""
    sizes = []
    for part in folder.glob(".m.*.part.csv"):
        try:
            sizes.append(part.stat().st_size)
        except FileNotFoundError:  # renamed or removed since it was listed
            pass
    return sizes


def signal_cases() -> list[Case]:
    """SIGINT and SIGTERM to an export of a day at 10 Hz: while it loads (once numpy's, scipy's and numba's libraries
    are mapped: the imports Ctrl-C is held through have begun), once its temporary table exists and once it has
    grown; the old pair must stay as it was. Each moment is awaited, not timed: a moment taken as a time after the
    start falls elsewhere on a slower machine (in the interpreter's own start-up, where a Ctrl-C is Python's)."""
    moments: list[tuple[str, Callable[[Path, int], bool]]] = [
        ("numpy loading", lambda folder, pid: mapped(pid, "numpy")),
        ("scipy loading", lambda folder, pid: mapped(pid, "scipy")),
        ("numba loading", lambda folder, pid: mapped(pid, "numba")),
        ("table begun", lambda folder, pid: bool(part_sizes(folder))),
        ("table > 100 kB", lambda folder, pid: any(size > 100_000 for size in part_sizes(folder))),
    ]
    cases = []
    for sig in (signal.SIGINT, signal.SIGTERM):
        for label, ready in moments:
            def run(folder: Path, sig: signal.Signals = sig, label: str = label,
                    ready: Callable[[Path, int], bool] = ready) -> tuple[str, str]:
                scenario = folder / "long.toml"
                scenario.write_text(LONG_SCENARIO)
                (folder / "m.csv").write_bytes(OLD_TABLE)
                (folder / "m.csv.json").write_bytes(OLD_SIDECAR)
                process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out",
                                            "m.csv", "--quiet"], cwd=folder, env=environment(), stdout=subprocess.PIPE,
                                           stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True)
                missed = until(lambda: ready(folder, process.pid), process)
                if missed:  # the moment never came: a hang, or an export of a day that ended by itself
                    hung = process.poll() is None
                    if hung:
                        process.kill()
                    stderr = process.communicate()[1]
                    return "hang" if hung else "traceback", f"{label} never came: {missed}: {stderr[-400:]}"
                process.send_signal(sig)
                try:
                    stdout, stderr = process.communicate(timeout=HANG_S)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.communicate()
                    return "hang", f"no exit {HANG_S:g} s after {sig.name}"
                result = subprocess.CompletedProcess(process.args, process.returncode, stdout, stderr)

                def untouched() -> str:
                    same = ((folder / "m.csv").read_bytes() == OLD_TABLE
                            and (folder / "m.csv.json").read_bytes() == OLD_SIDECAR)
                    return ("" if same else "the old pair changed") or leftovers(folder)
                return verdict(result, untouched)
            cases.append(Case("signals", f"{sig.name} {label}", run, own_process=True))
    return cases


def writer_cases() -> list[Case]:
    """Two exports (seeds 1 and 2) to one file, the second started after a delay: one pair, whole. The delay only
    varies where the first one is when the second starts; no outcome depends on what it had done by then."""
    cases = []
    for delay in (0.0, 0.0, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.5):
        def run(folder: Path, delay: float = delay) -> tuple[str, str]:
            scenario = folder / "s.toml"
            scenario.write_text(scenario_text())
            command = [sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "m.csv", "--quiet",
                       "--seed"]
            processes = []
            for seed in ("1", "2"):
                processes.append(subprocess.Popen([*command, seed], cwd=folder, env=environment(),
                                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                                  stdin=subprocess.DEVNULL, text=True))
                time.sleep(delay)
            results = []
            for process in processes:
                try:
                    stdout, stderr = process.communicate(timeout=HANG_S)
                except subprocess.TimeoutExpired:
                    for other in processes:
                        other.kill()
                    return "hang", "an export did not end"
                results.append(subprocess.CompletedProcess(process.args, process.returncode, stdout, stderr))
            if not any(r.returncode == 0 for r in results):
                return "data lost", "neither export wrote its pair: " + " | ".join(r.stderr for r in results)
            for result in results:
                outcome = verdict(result, lambda: leftovers(folder) or exported(folder, result))
                if outcome[0] != "clean":
                    return outcome
            return "clean", ""
        cases.append(Case("concurrent writers", f"second after {delay:g} s", run, own_process=True))
    return cases


WAKE = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "10", "--nx", "256", "--ny", "128", "--json"]


def cache_cases(folder: Path) -> list[Case]:
    """A wake computed once into a cache; each case damages a copy of the entry and asks again."""
    cache = folder / "cache"
    result = here(WAKE, folder, dict(environment(), MARINESIM_CACHE_DIR=str(cache)))
    assert result is not None and result.returncode == 0, result and result.stderr
    reference = json.loads(result.stdout)
    entry = next(cache.rglob("*.npz"))
    data = entry.read_bytes()

    def damage(how: str, target: Path, rng: random.Random) -> None:
        target.unlink()
        if how == "cut":
            target.write_bytes(data[: rng.randrange(len(data))])
        elif how == "flipped bytes":
            target.write_bytes(mutate_bytes(data, random.Random(rng.random() + 1)))  # never a cut
        elif how == "empty":
            target.write_bytes(b"")
        elif how == "text":
            target.write_text("not a wake\n")
        elif how == "zeros":
            target.write_bytes(bytes(len(data)))
        elif how == "a folder":
            target.mkdir()
        elif how == "a FIFO":
            os.mkfifo(target)
        elif how == "a link to itself":
            target.symlink_to(target.name)
        elif how == "other arrays":
            import numpy as np

            with target.open("wb") as handle:
                np.savez(handle, elevation=np.zeros(3), info=np.array("{}"))

    cases = []
    for how in ("cut", "cut", "flipped bytes", "flipped bytes", "empty", "text", "zeros", "a folder", "a FIFO",
                "a link to itself", "other arrays"):
        def run(case_folder: Path, how: str = how) -> tuple[str, str]:
            own = case_folder / "cache"
            shutil.copytree(cache, own)
            damage(how, own / entry.relative_to(cache), random.Random(f"cache-{how}-{case_folder.name}"))
            answer = here(WAKE, case_folder, dict(environment(), MARINESIM_CACHE_DIR=str(own)))

            def same_wake() -> str:
                if answer is None or answer.returncode != 0:
                    return ""
                try:
                    value = json.loads(answer.stdout)
                except ValueError:
                    return "exit 0 without a JSON answer"
                same = {k: v for k, v in value.items() if k not in VOLATILE} == {
                    k: v for k, v in reference.items() if k not in VOLATILE}
                return "" if same else "another wake than the one computed afresh"
            return verdict(answer, same_wake)
        cases.append(Case("damaged caches", how, run))
    return cases


def output_cases() -> list[Case]:
    """Outputs that are not regular files (a folder, a FIFO, a device, links to them, a file as a folder):
    each refused in one line, and what was there left as it was."""
    def make(folder: Path, kind: str, extension: str) -> Path:
        target = folder / f"out{extension}"
        if kind == "folder":
            target.mkdir()
        elif kind == "FIFO":
            os.mkfifo(target)
        elif kind == "link to a FIFO":
            os.mkfifo(folder / "pipe")
            target.symlink_to("pipe")
        elif kind == "link to a folder":
            (folder / "dir").mkdir()
            target.symlink_to("dir")
        elif kind == "under a file":
            (folder / "file").write_text("keep\n")
            return folder / "file" / target.name
        elif kind == "device":
            return Path("/dev/null")
        return target

    def state(folder: Path) -> list[tuple[str, int]]:
        return sorted((p.name, p.lstat().st_mode) for p in folder.iterdir() if p.name != "s.toml")

    specs = [("export", "folder", ".csv"), ("export", "FIFO", ".csv"), ("export", "link to a FIFO", ".csv"),
             ("export", "link to a folder", ".csv"), ("export", "under a file", ".csv"), ("export", "device", ""),
             ("wake", "FIFO", ".npz"), ("rao", "FIFO", ".png"), ("sea", "FIFO", ".csv"), ("sea", "folder", ".csv"),
             ("hull", "FIFO", "")]
    cases = []
    for command, kind, extension in specs:
        def run(folder: Path, command: str = command, kind: str = kind, extension: str = extension) -> tuple[str, str]:
            scenario = folder / "s.toml"
            scenario.write_text(scenario_text())
            out = str(make(folder, kind, extension))
            args = {"export": ["export", str(scenario), "--out", out, "--duration", "2", "--quiet"],
                    "wake": WAKE[:-1] + ["--out", out],
                    "rao": ["rao", str(ROOT / "rao" / "tanker" / "tanker.4"), "--plot", out],
                    "sea": ["sea", "--resolution", "32", "--spectrum-csv", out],
                    "hull": ["hull", out]}[command]
            before = state(folder)
            result = here(args, folder)
            if result is not None and result.returncode == 0 and kind != "device":
                return "data lost", f"exit 0 writing to a {kind}"
            return verdict(result, lambda: ("" if state(folder) == before else f"{kind} changed") or leftovers(folder))
        cases.append(Case("non-regular outputs", f"{command} to a {kind}", run))
    return cases


def refusal(result: subprocess.CompletedProcess | None, folder: Path, before: dict[str, bytes]) -> tuple[str, str]:
    """Classify a case that must be refused: exit 0 is silent; a file of ``before`` changed, or one more file in
    ``folder`` (a temporary one, an output) is data lost."""
    def changed() -> str:
        after = snapshot(folder)
        lost = sorted(name for name, data in before.items() if after.get(name) != data)
        new = sorted(set(after) - set(before))
        return "; ".join(f"{what}: {', '.join(names)}" for what, names in (("changed", lost), ("left", new)) if names)
    outcome, detail = verdict(result, changed)
    if outcome == "clean" and result.returncode == 0:
        return "silent", "exit 0: accepted without a word"
    return outcome, detail


def snapshot(folder: Path) -> dict[str, bytes]:
    """Every regular file under ``folder`` (not through links) and its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and not p.is_symlink()}


def tanker_scenario(folder: Path) -> Path:
    """The WAMIT tanker set copied into ``folder``/tanker and a short scenario ``s.toml`` naming it."""
    from test_atomic_overwrite import SCENARIO

    shutil.copytree(ROOT / "rao" / "tanker", folder / "tanker")
    path = folder / "s.toml"
    path.write_text(SCENARIO.format(duration=4.0))
    return path


def session_log(folder: Path) -> Path:
    """A real session log of :func:`tanker_scenario`: 20 s, the instructor's message at 10 s, the end; signed with
    the tests' key, with its sidecar."""
    from marinesim.scenario import load_scenario
    from marinesim.session.exercise import Exercise
    from marinesim.session.log import write_log
    from marinesim.session.timeline import Simulation

    folder.mkdir()
    simulation = Simulation(load_scenario(tanker_scenario(folder)), wake=False)
    try:
        exercise = Exercise(simulation)
        exercise.advance(10.0)
        exercise.act("message", text="stand by the crane")
        exercise.advance(10.0)
        exercise.note("end")
    finally:
        simulation.close()
    return write_log(folder / "l.jsonl", exercise)


SELF_OVERWRITES = [
    ["export", "s.toml", "--out", "s.toml", "--quiet"],
    ["export", "s.toml", "--out", "tanker/tanker.1", "--quiet"],
    ["export", "s.toml", "--out", "tanker/tanker.frc", "--quiet"],
    ["export", "s.toml", "--out", "hard.toml", "--quiet"],
    ["rao", "tanker/tanker.1", "--write", "tanker/tanker.3"],
    ["rao", "tanker/tanker.1", "--plot", "tanker/tanker.hst"],
    ["rao", "s175.re1", "--plot", "s175.re1"],
    ["wake", "box.stl", "--speed-kn", "8", "--out", "box.stl", "--quiet"],
    ["wake", "box.stl", "--speed-kn", "8", "--plot", "box.stl", "--quiet"],
    ["report", "s.toml", "--out", "s.toml", "--quiet"],
    ["report", "l.jsonl", "--out", "l.jsonl", "--quiet"],
    ["replay", "l.jsonl", "--export", "l.jsonl", "--quiet"],
    ["replay", "l.jsonl", "--export", "l.jsonl.json", "--quiet"],
]
"""Outputs given onto the command's own inputs (``hard.toml`` is a hard link to the scenario): each once
written over its input with exit 0."""


def self_overwrite_cases(sources: Path) -> list[Case]:
    log = session_log(sources / "log")
    cases = []
    for args in SELF_OVERWRITES:
        def run(folder: Path, args: list[str] = args) -> tuple[str, str]:
            shutil.copytree(log.parent, folder, dirs_exist_ok=True)
            os.link(folder / "s.toml", folder / "hard.toml")
            shutil.copy(ROOT / "rao" / "s175" / "input.re1", folder / "s175.re1")
            shutil.copy(ROOT / "hulls" / "box_barge.stl", folder / "box.stl")
            before = snapshot(folder)
            return refusal(here(args, folder), folder, before)
        cases.append(Case("self-overwrite", " ".join(args), run))
    return cases


def forge(log: Path, how: str) -> None:
    """Edit the session log ``log`` (and its sidecar) as someone covering a trainee's record would."""
    sidecar = log.with_name(log.name + ".json")
    lines = log.read_text().splitlines()
    head, entries = json.loads(lines[0]), [json.loads(line) for line in lines[1:]]
    if how == "an entry's time moved":
        entries[0]["t"] = round(entries[0]["t"] + 0.5, 3)
    elif how == "the seed changed":
        head["seed"] += 1
    elif how == "its end cut off":
        entries = entries[:-1]
    elif how == "an entry at t = 1e308":
        entries[0]["t"] = 1e308
    elif how == "its sidecar deleted":
        sidecar.unlink()
        return
    elif how == "moved and re-hashed":
        entries[0]["t"] = round(entries[0]["t"] + 0.5, 3)
    log.write_text("".join(json.dumps(e) + "\n" for e in [head, *entries]))
    if how == "moved and re-hashed":
        meta = json.loads(sidecar.read_text())
        meta["data_sha256"] = hashlib.sha256(log.read_bytes()).hexdigest()
        sidecar.write_text(json.dumps(meta, indent=2) + "\n")


FORGERIES = ("an entry's time moved", "the seed changed", "its end cut off", "an entry at t = 1e308",
             "its sidecar deleted", "moved and re-hashed")


def forged_log_cases(sources: Path) -> list[Case]:
    """A real session log edited; ``replay --export`` must refuse it, ``report`` must refuse it or write the
    debrief marked UNVERIFIED LOG (a debrief of it that looks like any other is silent)."""
    log = session_log(sources / "forged")
    cases = []
    for how in FORGERIES:
        for command in ("replay", "report"):
            def run(folder: Path, how: str = how, command: str = command) -> tuple[str, str]:
                shutil.copytree(log.parent, folder, dirs_exist_ok=True)
                forge(folder / "l.jsonl", how)
                before = snapshot(folder)
                if command == "replay":
                    result = here(["replay", "l.jsonl", "--export", "m.csv", "--quiet"], folder)
                    return refusal(result, folder, before)
                result = here(["report", "l.jsonl", "--out", "r.html", "--quiet"], folder)
                if result is not None and result.returncode == 0:
                    marked = "UNVERIFIED LOG" in (folder / "r.html").read_text(encoding="utf-8")
                    return ("clean", "marked UNVERIFIED LOG") if marked else ("silent", "a debrief with no mark")
                return refusal(result, folder, before)
            cases.append(Case("forged and truncated logs", f"{command}: {how}", run))
    return cases


def cut_wamit_cases() -> list[Case]:
    """The tanker's WAMIT set with one file cut as a failed copy or a full disk leaves it: once read as zeros or as
    fewer periods with no word, each must now be refused naming the file."""
    def lines(path: Path) -> list[str]:
        return path.read_text().splitlines()

    def periods(path: Path) -> list[str]:
        return list(dict.fromkeys(line.split()[0] for line in lines(path) if line.split()))

    def cut(folder: Path, how: str) -> None:
        hst, one, three = (folder / f"tanker.{s}" for s in ("hst", "1", "3"))
        if how == ".hst after the heave rows":
            hst.write_text("\n".join(lines(hst)[:18]) + "\n")
        elif how == ".3 to half its periods":
            kept = set(periods(three)[: len(periods(three)) // 2])
            three.write_text("".join(line + "\n" for line in lines(three) if line.split()[0] in kept))
        elif how == ".1 inside its last period":
            text = lines(one)
            last = text[-1].split()[0]
            one.write_text("\n".join(text[: next(n for n, t in enumerate(text) if t.split()[0] == last) + 1]) + "\n")
        elif how == ".3 to 0..90 deg of the .pot's 0..180":
            listed = " ".join(p for p in periods(one) if float(p) > 0)
            (folder / "tanker.cfg").write_text("IALTFRC=2\nIPERIO=1\n")
            (folder / "tanker.pot").write_text(f"tanker\n-1\n1 1\n58\n{listed}\n-19\n0 10\n1\ntanker.gdf\n0 0 0 0\n"
                                               "1 1 1 1 1 1\n")
            three.write_text("".join(line + "\n" for line in lines(three) if float(line.split()[1]) <= 90.0))
        elif how == ".1 to its first ten periods":
            kept = set(periods(one)[:10])
            one.write_text("".join(line + "\n" for line in lines(one) if line.split()[0] in kept))
        elif how == ".hst emptied":
            hst.write_text("")

    cases = []
    for how in (".hst after the heave rows", ".3 to half its periods", ".1 inside its last period",
                ".3 to 0..90 deg of the .pot's 0..180", ".1 to its first ten periods", ".hst emptied"):
        def run(folder: Path, how: str = how) -> tuple[str, str]:
            for name in ("tanker.1", "tanker.3", "tanker.hst", "tanker.frc", "tanker.cfg", "tanker.gdf"):
                shutil.copy(ROOT / "rao" / "tanker" / name, folder / name)
            cut(folder, how)
            before = snapshot(folder)
            return refusal(here(["rao", "tanker.3", "--json"], folder), folder, before)
        cases.append(Case("cut WAMIT sets", how, run))
    return cases


def multi_body_cases() -> list[Case]:
    """Two-body WAMIT runs: a body's .gdf placed by the run's .pot (read at its body-frame draft, its volume was
    wrong with no note), two .pot placing it apart, and a .4 or .1/.3 set of two bodies read with no --body."""
    from test_vessel_wamit_sets import two_body_pot

    tanker = ROOT / "rao" / "tanker"
    volume = None

    def raised(folder: Path) -> None:
        gdf = (tanker / "tanker.gdf").read_text().splitlines()
        moved = [" ".join([*line.split()[:2], f"{float(line.split()[2]) + 2.0:.5f}"]) for line in gdf[4:]]
        (folder / "barge.gdf").write_text("\n".join(gdf[:4] + moved) + "\n")

    def placed(folder: Path) -> tuple[str, str]:
        nonlocal volume
        if volume is None:
            from marinesim.hull import hydrostatics, load_hull
            volume = hydrostatics(load_hull(tanker / "tanker.gdf")).volume_m3
        raised(folder)
        two_body_pot(folder, "run.pot", "barge.gdf", (50.0, 60.0, -2.0, 0.0))
        result = here(["hull", "barge.gdf", "--json"], folder)
        if result is None or result.returncode != 0:
            return verdict(result)
        found = json.loads(result.stdout)["volume_m3"]
        return ("clean", "") if abs(found / volume - 1.0) < 1e-4 else ("silent", f"volume {found:.0f} m^3")

    def two_places(folder: Path) -> tuple[str, str]:
        raised(folder)
        two_body_pot(folder, "run.pot", "barge.gdf", (50.0, 60.0, -2.0, 0.0))
        two_body_pot(folder, "old.pot", "barge.gdf", (50.0, 60.0, -3.0, 0.0))
        return refusal(here(["hull", "barge.gdf", "--json"], folder), folder, snapshot(folder))

    def two_body_4(folder: Path, body: str | None) -> tuple[str, str]:
        rows = [line.split() for line in (tanker / "tanker.4").read_text().splitlines() if line.split()]
        merged = []
        for start in range(0, len(rows), 6):
            merged += [" ".join(r) for r in rows[start:start + 6]]
            merged += [" ".join([r[0], r[1], str(int(r[2]) + 6), *r[3:]]) for r in rows[start:start + 6]]
        (folder / "run.4").write_text("\n".join(merged) + "\n")
        two_body_pot(folder, "run.pot", "barge.gdf", (0.0, 0.0, 0.0, 0.0))
        if body is None:
            return refusal(here(["rao", "run.4", "--json"], folder), folder, snapshot(folder))
        return verdict(here(["rao", "run.4", "--body", body, "--json"], folder))

    def two_body_set(folder: Path) -> tuple[str, str]:
        for suffix, columns in ((".1", (1, 2)), (".3", (2,)), (".hst", (0, 1))):
            rows = [line.split() for line in (tanker / f"tanker{suffix}").read_text().splitlines() if line.split()]
            for row in rows:
                for c in columns:
                    row[c] = str(int(row[c]) + 6)
            (folder / f"tanker{suffix}").write_text("\n".join(" ".join(row) for row in rows) + "\n")
        shutil.copy(tanker / "tanker.frc", folder / "tanker.frc")
        two_body_pot(folder, "tanker.pot", "tanker2.gdf", (0.0, 0.0, 0.0, 0.0))
        return refusal(here(["rao", "tanker.3", "--body", "2", "--json"], folder), folder, snapshot(folder))

    return [Case("multi-body .pot", "a body placed by the run's .pot", placed),
            Case("multi-body .pot", "two .pot placing one body apart", two_places),
            Case("multi-body .pot", ".4 of two bodies, no --body", lambda folder: two_body_4(folder, None)),
            Case("multi-body .pot", ".4 of two bodies, --body 2", lambda folder: two_body_4(folder, "2")),
            Case("multi-body .pot", ".4 of two bodies, --body barge.gdf",
                 lambda folder: two_body_4(folder, "barge.gdf")),
            Case("multi-body .pot", ".1/.3 of body 2 without its mass", two_body_set)]


def scenario_with(edit: Callable[[str], str]) -> Callable[[Path], list[str]]:
    """A case's command: ``export`` of :func:`scenario_text` after ``edit``, written into the case's folder."""
    def command(folder: Path) -> list[str]:
        (folder / "s.toml").write_text(edit(scenario_text()))
        return ["export", "s.toml", "--out", "m.csv", "--duration", "2", "--quiet"]
    return command


def scatter(rows: str) -> Callable[[Path], list[str]]:
    """A case's command: an operability study of the crane lift over the scatter table ``rows`` (Hs, Tp, count)."""
    def command(folder: Path) -> list[str]:
        (folder / "site.csv").write_text("hs_m,tp_s,count\n" + rows)
        return ["operability", str(ROOT / "configs" / "training" / "crane_lift.toml"), "--scatter", "site.csv",
                "--out", "study", "--headings", "0,180"]
    return command


def points(n: int) -> str:
    return "\n".join(f"p{i} = [{i % 100}.0, 0.0, 10.0]" for i in range(n))


IMPOSSIBLE = {
    "depth 1e-9 m": scenario_with(lambda t: t.replace("[ocean]", "[ocean]\ndepth_m = 1e-9").replace(
        'hull = "', '# hull = "')),
    "a point at 1e308 m": scenario_with(lambda t: t.replace("bow = [120.0, 0.0, 12.0]", "bow = [1e308, 0.0, 12.0]")),
    "hull draft 1e308 m": scenario_with(lambda t: t.replace("speed_kn = 4.0", "hull_draft_m = 1e308\nspeed_kn = 4.0")),
    "visual mesh offset 1e308 m": scenario_with(lambda t: t.replace(
        "speed_kn = 4.0", "visual_mesh_offset_m = [1e308, 0.0, 0.0]\nspeed_kn = 4.0")),
    "u10 1e-300 m/s": lambda folder: ["sea", "--u10", "1e-300", "--resolution", "32"],
    "fetch 1e-300 km": lambda folder: ["sea", "--u10", "15", "--fetch-km", "1e-300", "--resolution", "32"],
    "wake draft 1e308 m": lambda folder: ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "10", "--draft",
                                         "1e308", "--quiet"],
    "trim 29.9 deg at draft 0.1 m": lambda folder: ["hull", str(ROOT / "hulls" / "supply_hull.stl"), "--trim-deg",
                                                    "29.9", "--draft", "0.1"],
    "rao speed 1e308 kn": lambda folder: ["rao", str(ROOT / "rao" / "s175" / "input.re1"), "--speed-kn", "1e308",
                                          "--plot", "p.png"],
    "rao headings 1e308 deg": lambda folder: ["rao", str(ROOT / "rao" / "tanker" / "tanker.4"), "--headings",
                                              "1e308", "--plot", "p.png"],
    "scatter in centimetres": scatter("150,8,10\n250,9,20\n"),
    "scatter steeper than breaking": scatter("1,6,10\n20,3,20\n"),
    "scatter Hs 1e308 m": scatter("1,6,10\n1e308,9,20\n"),
}
"""Inputs no sea or ship can have, each once accepted with exit 0 (NaN in the CSV, a 25 m draft, 0 % or 100 %
operability) or ended in a traceback."""

CAPS = {
    "1,000 wave systems": scenario_with(lambda t: t + "".join(
        f'\n[[sea]]\ntype = "jonswap"\nhs_m = 0.1\ntp_s = 8.0\nfrom_deg = {i % 360}.0\n' for i in range(1000))),
    "12 wave systems in an event": scenario_with(lambda t: t + "\n[[events]]\nat_s = 1.0\n" + "".join(
        '\n[[events.sea]]\ntype = "jonswap"\nhs_m = 0.1\ntp_s = 8.0\nfrom_deg = 0.0\n' for _ in range(12))),
    "10,000 points": scenario_with(lambda t: t.replace("manifold = [0.0, -20.0, 14.0]", points(10000))),
    "65 points": scenario_with(lambda t: t.replace("manifold = [0.0, -20.0, 14.0]", points(65))),
    "41 wake speeds": lambda folder: ["wake", str(ROOT / "hulls" / "wigley.stl"), "--nx", "64", "--ny", "32",
                                      "--speed-kn", ",".join(str(v) for v in range(1, 42)), "--quiet"],
}
"""Sizes that ran for minutes: each must be refused at once, naming its key or option."""


def physics_cases() -> list[Case]:
    cases = []
    for category, table in (("impossible physics", IMPOSSIBLE), ("size caps", CAPS)):
        for name, command in table.items():
            def run(folder: Path, command: Callable[[Path], list[str]] = command) -> tuple[str, str]:
                args = command(folder)
                return refusal(here(args, folder), folder, snapshot(folder))
            cases.append(Case(category, name, run))

    def repeated_speed(folder: Path) -> tuple[str, str]:
        """1,000 copies of one speed in ``wake --speed-kn``: each was computed again, for minutes; now once."""
        result = here(["wake", str(ROOT / "hulls" / "wigley.stl"), "--nx", "64", "--ny", "32", "--speed-kn",
                      ",".join(["12"] * 1000), "--json"], folder)
        if result is None or result.returncode != 0:
            return verdict(result)
        answer = json.loads(result.stdout)
        return ("clean", "") if isinstance(answer, dict) else ("silent", f"{len(answer)} wakes for one speed")
    cases.append(Case("size caps", "1,000 copies of one wake speed", repeated_speed))
    return cases


# --- the campaign ------------------------------------------------------------------------------------------

def table(results: list[tuple[Case, str, str]]) -> str:
    """The markdown table: one row per category, its cases counted by verdict."""
    rows = ["| category | tried | " + " | ".join(COLUMNS) + " |", "|---" * (len(COLUMNS) + 2) + "|"]
    for category in dict.fromkeys(case.category for case, _, _ in results):
        verdicts = [v for case, v, _ in results if case.category == category]
        rows.append(f"| {category} | {len(verdicts)} | " + " | ".join(str(verdicts.count(c)) for c in COLUMNS) + " |")
    return "\n".join(rows) + "\n"


def sample(cases: list[Case]) -> list[Case]:
    """:data:`PER_CATEGORY` cases of each category, the same ones every run (a seeded choice, in file order)."""
    chosen = []
    for category in dict.fromkeys(case.category for case in cases):
        mine = [case for case in cases if case.category == category]
        keep = sorted(random.Random(category).sample(range(len(mine)), min(PER_CATEGORY, len(mine))))
        chosen += [mine[i] for i in keep]
    return chosen


@pytest.mark.slow
def test_the_campaign_finds_no_traceback_hang_or_lost_data(tmp_path):
    """A non-zero count in the last three columns is a user seeing a traceback, waiting for ever, or losing or
    mixing an output; the failing cases are listed with what was seen."""
    sources = tmp_path / "sources"
    sources.mkdir()
    cases = sample(rao_cases(sources) + mesh_cases(sources) + scenario_cases() + option_cases() + signal_cases()
                   + writer_cases() + cache_cases(sources) + output_cases() + self_overwrite_cases(sources)
                   + forged_log_cases(sources) + cut_wamit_cases() + multi_body_cases() + physics_cases())

    def attempt(numbered: tuple[int, Case]) -> tuple[Case, str, str]:
        number, case = numbered
        folder = tmp_path / f"case{number:03d}"
        folder.mkdir()
        try:
            outcome, detail = case.run(folder)
        except Exception as error:  # the harness's own failure is the case's failure, not a silent pass
            outcome, detail = "traceback", f"harness: {type(error).__name__}: {error}"
        return case, outcome, detail

    started = time.monotonic()
    environment()  # the processes' environment, taken before a case here swaps this one's
    numbered = list(enumerate(cases))
    with ThreadPoolExecutor(WORKERS) as pool:  # the processes side by side, while the other cases run here
        apart = {n: pool.submit(attempt, (n, case)) for n, case in numbered if case.own_process}
        in_this_process = {n: attempt((n, case)) for n, case in numbered if not case.own_process}
    results = [apart[n].result() if n in apart else in_this_process[n] for n, _ in numbered]
    report = table(results)
    print(f"\n{report}\n{len(cases)} cases in {time.monotonic() - started:.0f} s")
    if os.environ.get("MARINESIM_CAMPAIGN_REPORT"):
        Path(os.environ["MARINESIM_CAMPAIGN_REPORT"]).write_text(report)
    failures = [f"{case.category} / {case.name}: {outcome}: {detail}" for case, outcome, detail in results
                if outcome != "clean"]
    assert not failures, "\n".join(failures)


def test_a_usage_mistake_is_one_line():
    """Regression (found by the campaign): argparse printed its whole usage block above the error, so a
    mistyped option gave many lines on stderr instead of one."""
    result = here(["sea", "--spectrum", "storm"], ROOT)
    assert result is not None and result.returncode == 2
    assert len(result.stderr.strip().splitlines()) == 1 and "--spectrum" in result.stderr, result.stderr


SIGNAL_DURING_TRIMESH_IMPORT = """
import os, signal, sys
class Stop(BaseException): pass
def stop(signum, frame): raise Stop
signal.signal(signal.SIGTERM, stop)
class Trigger:  # SIGTERM to this process when trimesh imports scipy, inside its try/except BaseException
    def find_spec(self, name, path=None, target=None):
        if name == "scipy":
            sys.meta_path.remove(self)
            os.kill(os.getpid(), signal.SIGTERM)
sys.meta_path.insert(0, Trigger())
try:
    {statement}
except Stop:
    sys.exit(143)
print("the signal was swallowed")
"""


def test_a_signal_while_trimesh_imports_is_not_lost():
    """Regression (found by the campaign): a SIGTERM or Ctrl-C while trimesh loaded was swallowed by its
    ``except BaseException`` around optional imports, and the export ran on for minutes. marinesim imports trimesh
    in one place, ``marinesim.hull.trimesh_held``, when a mesh is first read or built."""
    statement = "from marinesim.hull.trimesh_held import trimesh; trimesh.Trimesh"
    result = subprocess.run([sys.executable, "-c", SIGNAL_DURING_TRIMESH_IMPORT.format(statement=statement)],
                            capture_output=True, text=True, env=environment(), timeout=HANG_S)
    assert result.returncode == 143, result.stdout + result.stderr


def test_a_refused_sidecar_leaves_no_temporary_table(tmp_path):
    """Regression (found by the campaign): the table's temporary file was made before the sidecar's path was
    checked, and nothing removed it when that check (or a signal between the two) ended the export."""
    scenario = tmp_path / "s.toml"
    scenario.write_text(scenario_text())
    os.mkfifo(tmp_path / "m.csv.json")
    result = here(["export", str(scenario), "--out", "m.csv", "--duration", "2", "--quiet"], tmp_path)
    assert result is not None and result.returncode == 2, result and result.stderr
    assert not leftovers(tmp_path) and not (tmp_path / "m.csv").exists()
