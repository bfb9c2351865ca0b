"""No command writes over a file it reads, and no killed writer leaves its temporary files behind.

Each output is staged onto one of the command's own inputs, as a user mistyping a path would: the
scenario, the RAO file a scenario names, an RAO or hull given on the command line, a session log and
its sidecar; by the same name, through a hard link and through a symbolic link to the folder. Every
refusal must be one line with exit status 2, and every input must keep its bytes.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import ROOT, cli, write
from marinesim.scenario import load_scenario
from marinesim.session.exercise import Exercise
from marinesim.session.log import write_log
from marinesim.session.timeline import Simulation

SCENARIO = """
[ocean]
resolution = 32
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 2.0
tp_s = 8.0
from_deg = 200.0

[vessel]
rao = "tanker/tanker.1"
speed_kn = 0.0
heading_deg = 0.0

[vessel.points]
bridge = [-100.0, 0.0, 30.0]

[run]
duration_s = {duration}
dt_s = 0.5
seed = 3
"""
"""The WAMIT tanker at rest (its RAO set copied beside the scenario), a small ocean."""


def run(*argv: str) -> tuple[int, str, str]:
    """``marinesim *argv`` in this process (conftest's ``cli``): (exit status, stdout, stderr)."""
    result = cli(*argv)
    return result.returncode, result.stdout, result.stderr


def snapshot(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` and its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def refused(argv: list[str], folder: Path, option: str) -> str:
    """Run ``argv`` and check it was refused as a user mistake naming ``option``, with ``folder`` untouched."""
    before = snapshot(folder)
    code, out, err = run(*argv)
    assert code == 2, (out, err)
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert option in err and "inputs" in err, err
    assert snapshot(folder) == before, "an input or an old output changed"
    return err


@pytest.fixture
def case(tmp_path) -> Path:
    shutil.copytree(ROOT / "rao" / "tanker", tmp_path / "tanker")
    write(tmp_path, SCENARIO.format(duration=20.0), "s.toml")
    return tmp_path


def test_export_refuses_the_scenario_and_the_files_it_names(case):
    """``export s.toml --out s.toml`` once replaced the scenario with CSV (exit 0); so did an ``--out`` onto
    the RAO file the scenario names, or onto the sidecar name of one (``tanker.1.json`` would be ``--out
    tanker.1``'s sidecar: the table's name decides)."""
    scenario = case / "s.toml"
    refused(["export", str(scenario), "--out", str(scenario), "--quiet"], case, "--out")
    refused(["export", str(scenario), "--out", str(case / "tanker" / "tanker.1"), "--quiet"], case, "--out")
    refused(["export", str(scenario), "--out", str(case / "tanker" / "tanker.hst"), "--quiet"], case, "--out")


def test_a_hard_link_or_a_linked_folder_is_the_same_input(case):
    """The same file by another name is the same input: a hard link to the scenario, and the scenario
    reached through a symbolic link to its folder."""
    os.link(case / "s.toml", case / "other.toml")
    refused(["export", str(case / "s.toml"), "--out", str(case / "other.toml"), "--quiet"], case, "--out")
    (case / "linked").symlink_to(case, target_is_directory=True)
    refused(["export", str(case / "s.toml"), "--out", str(case / "linked" / "s.toml"), "--quiet"], case, "--out")


def test_an_export_beside_its_inputs_is_written(case):
    """The guard refuses only inputs: an output beside them is written, with its sidecar."""
    code, _, err = run("export", str(case / "s.toml"), "--out", str(case / "m.csv"), "--quiet")
    assert code == 0, err
    assert (case / "m.csv").stat().st_size > 0 and (case / "m.csv.json").exists()


def test_rao_refuses_to_plot_or_write_over_what_it_reads(case):
    """``rao p.re1 --plot p.re1`` and ``rao x.4 --write x.4`` once overwrote the RAO file; the plot onto a
    file of the WAMIT set it read (``.hst``) is refused too."""
    veres = case / "input.re1"
    shutil.copy(ROOT / "rao" / "s175" / "input.re1", veres)
    refused(["rao", str(veres), "--plot", str(veres)], case, "--plot")
    semisub = case / "semisub"
    shutil.copytree(ROOT / "rao" / "semisub", semisub)
    refused(["rao", str(semisub / "semisub.4"), "--write", str(semisub / "semisub.4")], case, "--write")
    refused(["rao", str(case / "tanker" / "tanker.1"), "--plot", str(case / "tanker" / "tanker.hst")], case, "--plot")


def test_wake_refuses_its_hull(case):
    """``wake box.stl --out box.stl`` (and ``--plot``) once replaced the hull."""
    hull = case / "box.stl"
    shutil.copy(ROOT / "hulls" / "box_barge.stl", hull)
    refused(["wake", str(hull), "--speed-kn", "8", "--out", str(hull), "--quiet"], case, "--out")
    refused(["wake", str(hull), "--speed-kn", "8", "--plot", str(hull), "--quiet"], case, "--plot")


@pytest.fixture
def session_log(case) -> Path:
    """A real session log of the scenario (20 s), with its sidecar."""
    simulation = Simulation(load_scenario(case / "s.toml"), wake=False)
    try:
        exercise = Exercise(simulation)
        exercise.advance(20.0)
    finally:
        simulation.close()
    return write_log(case / "l.jsonl", exercise)


def test_report_and_replay_refuse_the_log_and_its_sidecar(case, session_log):
    """``report r.toml --out r.toml``, ``report l.jsonl --out l.jsonl`` and ``replay l.jsonl --export
    l.jsonl`` once replaced a training session's evidence; the log's sidecar is one of its inputs too."""
    refused(["report", str(case / "s.toml"), "--out", str(case / "s.toml"), "--quiet"], case, "--out")
    refused(["report", str(session_log), "--out", str(session_log), "--quiet"], case, "--out")
    refused(["report", str(session_log), "--out", str(case / "l.jsonl.json"), "--quiet"], case, "--out")
    refused(["replay", str(session_log), "--export", str(session_log), "--quiet"], case, "--export")
    sidecar_name = case / "l.jsonl.json"
    refused(["replay", str(session_log), "--export", str(sidecar_name), "--quiet"], case, "--export")


def test_an_export_killed_with_sigkill_leaves_nothing_the_next_one_keeps(case):
    """SIGKILL cannot be caught: the killed export leaves its lock and its temporary table behind. The next
    export to the same file takes the lock (the OS gave it up with the process), removes the dead writer's
    temporary files and writes a whole pair; nothing else is left in the folder."""
    write(case, SCENARIO.format(duration=100000.0), "long.toml")
    before = set(os.listdir(case))
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(case / "long.toml"), "--out",
                                "m.csv", "--quiet"], cwd=case, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        while not list(case.glob(".m.*.part.csv")):  # waits on the temporary table, however slow the machine
            assert process.poll() is None, "the export ended before it began writing"
            time.sleep(0.01)
    finally:
        process.send_signal(signal.SIGKILL)
        process.wait()
    assert list(case.glob(".m.*.part.csv")), "the killed export must have left its temporary table"
    code, _, err = run("export", str(case / "s.toml"), "--out", str(case / "m.csv"), "--quiet")
    assert code == 0, err
    assert set(os.listdir(case)) - before == {"m.csv", "m.csv.json"}
