"""The hardening campaign re-run as a user meets it: ``python -m marinesim ...`` in processes of its own on
mutated RAO files and meshes, mutated scenarios, bad options, signals, two writers of one file, a damaged
wake cache and outputs that are not regular files. Six cases per category, seeded, so every run tries the
same ones.

Each case is classified: clean (exit 0 with valid outputs, or exit 2/130/143 with exactly one line on
stderr; a process killed by the signal before Python could handle it, with nothing on stderr, counts as
clean too), traceback (a traceback, or an exit that is neither of those: several lines, another status),
hang (no exit within :data:`HANG_S`), or data lost (an output that was there changed, a table whose sidecar
names other bytes, a leftover ``.part`` or ``.lock`` file, a wrong result). The table is printed (``pytest
-s``) and written as markdown to ``$MARINESIM_CAMPAIGN_REPORT`` when that is set.
"""

from __future__ import annotations

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

from conftest import ROOT

HANG_S = 60.0
PROGRESS = re.compile(r"\d+%\|")  # a progress bar's line (tqdm), not a message
VOLATILE = {"seconds", "seconds_computing", "cached"}  # what a wake's JSON may say differently from the cache
WORKERS = 3
PER_CATEGORY = 6
"""Cases run per category: a seeded choice among those built (the fuzz tests try many more in one process)."""
COLUMNS = ("clean", "traceback", "hang", "data lost")
HOSTILE = ["nan", "inf", "-inf", "1e308", "-1e308", "0", "-1", "x", "", "99999999999", "1e-300", "[", "\""]
ENV = dict(os.environ, PYTHONPATH=str(ROOT))


@dataclass(frozen=True)
class Case:
    """One thing a user does: ``run(folder)`` does it in an empty folder and returns (verdict, detail)."""

    category: str
    name: str
    run: Callable[[Path], tuple[str, str]]


def cli(args: list[str], cwd: Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess | None:
    """``python -m marinesim *args`` in ``cwd``; None if it did not end within :data:`HANG_S`."""
    try:
        return subprocess.run([sys.executable, "-m", "marinesim", *args], cwd=cwd, capture_output=True, text=True,
                              env=env or ENV, timeout=HANG_S, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
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
    """A small barge solved by Capytaine (tests/test_inputs_fuzz_more.py), written as NetCDF."""
    import capytaine

    from test_inputs_fuzz_more import small_capytaine_dataset

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
                result = cli(command(path), folder)
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
            result = cli(["export", str(path), "--out", "m.csv", "--duration", "2", "--quiet"], folder)
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
            result = cli([a.replace("{scenario}", str(scenario)) for a in args], folder)
            if result is not None and result.returncode == 0:
                return "traceback", "a bad option was accepted (exit 0)"
            return verdict(result, lambda: leftovers(folder))
        cases.append(Case("CLI options", " ".join(args[:1] + args[2:]), run))
    return cases


OLD_TABLE, OLD_SIDECAR = b"time_s\n0.0\n", b'{"seed": 0}\n'


def signal_cases() -> list[Case]:
    """SIGINT and SIGTERM to an export of a day at 10 Hz: while it loads, once its
    temporary table exists and once it has grown; the old pair must stay as it was. (Not earlier than 0.3 s:
    a Ctrl-C in the interpreter's own first tens of milliseconds, before any marinesim code runs, is Python's.)"""
    moments: list[tuple[str, Callable[[Path], bool]]] = [
        ("at 0.3 s", lambda folder: True),
        ("at 0.5 s", lambda folder: True),
        ("at 1.2 s", lambda folder: True),
        ("table begun", lambda folder: any(folder.glob(".m.*.part.csv"))),
        ("table > 100 kB", lambda folder: any(p.stat().st_size > 100_000 for p in folder.glob(".m.*.part.csv"))),
    ]
    cases = []
    for sig in (signal.SIGINT, signal.SIGTERM):
        for label, ready in moments:
            def run(folder: Path, sig: signal.Signals = sig, label: str = label,
                    ready: Callable[[Path], bool] = ready) -> tuple[str, str]:
                scenario = folder / "long.toml"
                scenario.write_text(LONG_SCENARIO)
                (folder / "m.csv").write_bytes(OLD_TABLE)
                (folder / "m.csv.json").write_bytes(OLD_SIDECAR)
                process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out",
                                            "m.csv", "--quiet"], cwd=folder, env=ENV, stdout=subprocess.PIPE,
                                           stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True)
                start = time.monotonic()
                delay = float(label.split()[1]) if label.startswith("at ") else 0.0
                while time.monotonic() - start < HANG_S and process.poll() is None:
                    if time.monotonic() - start >= delay and ready(folder):
                        break
                    time.sleep(0.01)
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
            cases.append(Case("signals", f"{sig.name} {label}", run))
    return cases


def writer_cases() -> list[Case]:
    """Two exports (seeds 1 and 2) to one file, the second started after a delay: one pair, whole."""
    cases = []
    for delay in (0.0, 0.0, 0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.5):
        def run(folder: Path, delay: float = delay) -> tuple[str, str]:
            scenario = folder / "s.toml"
            scenario.write_text(scenario_text())
            command = [sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "m.csv", "--quiet",
                       "--seed"]
            processes = []
            for seed in ("1", "2"):
                processes.append(subprocess.Popen([*command, seed], cwd=folder, env=ENV, stdout=subprocess.PIPE,
                                                  stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True))
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
        cases.append(Case("concurrent writers", f"second after {delay:g} s", run))
    return cases


WAKE = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "10", "--nx", "256", "--ny", "128", "--json"]


def cache_cases(folder: Path) -> list[Case]:
    """A wake computed once into a cache; each case damages a copy of the entry and asks again."""
    cache = folder / "cache"
    result = cli(WAKE, folder, dict(ENV, MARINESIM_CACHE_DIR=str(cache)))
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
            answer = cli(WAKE, case_folder, dict(ENV, MARINESIM_CACHE_DIR=str(own)))

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
            result = cli(args, folder)
            if result is not None and result.returncode == 0 and kind != "device":
                return "data lost", f"exit 0 writing to a {kind}"
            return verdict(result, lambda: ("" if state(folder) == before else f"{kind} changed") or leftovers(folder))
        cases.append(Case("non-regular outputs", f"{command} to a {kind}", run))
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
                   + writer_cases() + cache_cases(sources) + output_cases())

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
    with ThreadPoolExecutor(WORKERS) as pool:
        results = list(pool.map(attempt, enumerate(cases)))
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
    result = cli(["sea", "--spectrum", "storm"], ROOT)
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
    import {module}
except Stop:
    sys.exit(143)
print("the signal was swallowed")
"""


def test_a_signal_while_trimesh_imports_is_not_lost():
    """Regression (found by the campaign): a SIGTERM or Ctrl-C while trimesh loaded was swallowed by its
    ``except BaseException`` around optional imports, and the export ran on for minutes."""
    result = subprocess.run([sys.executable, "-c", SIGNAL_DURING_TRIMESH_IMPORT.format(module="marinesim.hull")],
                            capture_output=True, text=True, env=ENV, timeout=HANG_S)
    assert result.returncode == 143, result.stdout + result.stderr


def test_a_refused_sidecar_leaves_no_temporary_table(tmp_path):
    """Regression (found by the campaign): the table's temporary file was made before the sidecar's path was
    checked, and nothing removed it when that check (or a signal between the two) ended the export."""
    scenario = tmp_path / "s.toml"
    scenario.write_text(scenario_text())
    os.mkfifo(tmp_path / "m.csv.json")
    result = cli(["export", str(scenario), "--out", "m.csv", "--duration", "2", "--quiet"], tmp_path)
    assert result is not None and result.returncode == 2, result and result.stderr
    assert not leftovers(tmp_path) and not (tmp_path / "m.csv").exists()
