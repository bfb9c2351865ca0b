"""An exported table and its sidecar are one unit: nothing lost, nothing mixed, nothing clobbered.

Each fault is staged for real: a SIGTERM to a running export, a second export to the same file, a
rename that fails half way, a FIFO, a device and a symbolic link where the output should go.
"""

from __future__ import annotations

import hashlib
import json
import os
import signal
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pandas as pd
import pytest

from marinesim.atomic import AtomicFile, commit_together, signals_held
from marinesim.errors import MarinesimError, ParameterError
from marinesim.scenario import load_scenario, with_run
from marinesim.session.assembly import Assembly
from marinesim.session.export import export_motions

from conftest import HANG_S, ROOT, cli, wait_for

SCENARIO = f"""
[ocean]
resolution = 64
tiles = 3

[[sea]]
type = "jonswap"
hs_m = 3.0
tp_s = 9.0
from_deg = 200.0

[vessel]
rao = "{ROOT / 'rao' / 'tanker' / 'tanker.4'}"
speed_kn = 4.0

[run]
duration_s = 86400.0
dt_s = 0.1
seed = 1
"""


@pytest.fixture
def scenario(tmp_path) -> Path:
    path = tmp_path / "long.toml"
    path.write_text(SCENARIO)
    return path


def start_export(scenario: Path, cwd: Path, *args: str) -> subprocess.Popen:
    """``marinesim export`` of a day at 10 Hz (``args`` may shorten it) in the background, once it has begun its
    temporary table: it holds its lock then, and has its whole record still to compute and write."""
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "m.csv",
                                "--quiet", *args], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_for(lambda: any(cwd.glob(".m.*.part.csv")), process, "the export never began its table")
    return process


def export(scenario: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    """``marinesim export`` through the entry point in this process, in the folder ``cwd``: a refusal or a short
    export needs no process of its own (the signals and the second writer above do)."""
    return cli("export", str(scenario), "--quiet", *args, cwd=cwd)


def test_the_sidecar_names_the_bytes_of_its_table_and_each_table_has_its_own(tmp_path, scenario):
    """``m.csv`` gets ``m.csv.json`` and ``m.parquet`` gets ``m.parquet.json`` (one shared ``m.json`` let the
    second export overwrite the first's metadata); each sidecar's data_sha256 is its table's sha256."""
    pytest.importorskip("pyarrow")
    assembly = Assembly(with_run(load_scenario(scenario), duration=20.0))
    csv = export_motions(assembly, tmp_path / "m.csv")
    parquet = export_motions(assembly, tmp_path / "m.parquet")
    assert (csv.sidecar.name, parquet.sidecar.name) == ("m.csv.json", "m.parquet.json")
    for result, file_format in ((csv, "csv"), (parquet, "parquet")):
        meta = json.loads(result.sidecar.read_text())
        assert meta["data_sha256"] == hashlib.sha256(result.table.read_bytes()).hexdigest()
        assert meta["format"] == file_format and meta["file"] == result.table.name
    assert len(pd.read_parquet(parquet.table)) == len(pd.read_csv(csv.table)) == 201


def test_a_format_that_contradicts_the_extension_is_refused(tmp_path, scenario):
    """``--format parquet --out x.csv`` would write Parquet bytes into a file every tool reads as CSV."""
    refused = export(scenario, tmp_path, "--out", "x.csv", "--format", "parquet", "--duration", "5")
    assert refused.returncode == 2 and "--format parquet does not fit x.csv" in refused.stderr
    assert len(refused.stderr.strip().splitlines()) == 1 and not list(tmp_path.glob("x.csv*"))


def test_sigterm_discards_the_new_pair_and_keeps_the_old_one(tmp_path, scenario):
    """SIGTERM (timeout, docker stop, a cancelled job) ends the export like Ctrl-C: one line, exit 143, the
    previous pair untouched, no temporary file and no lock left behind."""
    old_table, old_sidecar = b"time_s\n0.0\n", b'{"seed": 0}\n'
    (tmp_path / "m.csv").write_bytes(old_table)
    (tmp_path / "m.csv.json").write_bytes(old_sidecar)
    process = start_export(scenario, tmp_path)
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate(timeout=HANG_S)
    assert process.returncode == 143 and "terminated" in stderr and "Traceback" not in stderr
    assert len(stderr.strip().splitlines()) == 1
    assert (tmp_path / "m.csv").read_bytes() == old_table and (tmp_path / "m.csv.json").read_bytes() == old_sidecar
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long.toml", "m.csv", "m.csv.json"]


@pytest.mark.slow
def test_a_second_writer_is_refused_while_the_first_runs(tmp_path, scenario):
    """Two exports to one file used to leave one's table beside the other's sidecar; now the second is refused
    with the first's process named, and the first's pair is whole. The first is stopped (SIGSTOP, its lock still
    held) while the second tries, so that on no machine can it end before the second has started."""
    first = start_export(scenario, tmp_path, "--duration", "20000")
    first.send_signal(signal.SIGSTOP)
    try:
        second = export(scenario, tmp_path, "--out", "m.csv", "--seed", "2", "--duration", "10")
    finally:
        first.send_signal(signal.SIGCONT)
    assert second.returncode == 2 and f"another marinesim (process {first.pid}) is writing it" in second.stderr
    assert first.wait(timeout=HANG_S) == 0
    meta = json.loads((tmp_path / "m.csv.json").read_text())
    assert meta["seed"] == 1 and meta["data_sha256"] == hashlib.sha256((tmp_path / "m.csv").read_bytes()).hexdigest()
    assert not (tmp_path / "m.csv.lock").exists()


def test_a_lock_left_by_a_process_that_no_longer_runs_is_taken_over(tmp_path, scenario):
    """A killed export leaves its lock; the next export sees that its process is gone and goes ahead."""
    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    (tmp_path / "m.csv.lock").write_text(gone.stdout)
    done = export(scenario, tmp_path, "--out", "m.csv", "--duration", "5")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "m.csv").exists() and not (tmp_path / "m.csv.lock").exists()


def test_every_output_gets_the_permissions_open_would_give(tmp_path, scenario):
    """0666 less the umask, the table and its sidecar alike, from an export and from the live recorder (whose
    rows once went in under a private temporary file's 0600: a table others could not read beside its sidecar).
    The umask is set here, and the temporary files are made with it: no process-wide toggling while threads run."""
    from marinesim.session.exercise import Exercise
    from marinesim.session.recorder import Recorder
    from marinesim.session.timeline import Simulation

    previous = os.umask(0o027)
    try:
        short = with_run(load_scenario(scenario), 5.0)
        export_motions(Assembly(short), tmp_path / "m.csv")
        simulation = Simulation(short, wake=False)
        recorder = Recorder(Exercise(simulation), tmp_path / "r.csv")
        simulation.advance(2.0)
        recorder.stop()
        simulation.close()
    finally:
        os.umask(previous)
    modes = {name: stat.S_IMODE((tmp_path / name).stat().st_mode) for name in ("m.csv", "m.csv.json", "r.csv",
                                                                                "r.csv.json")}
    assert modes == dict.fromkeys(modes, 0o640), modes


def test_a_failed_rename_puts_back_what_was_there(tmp_path):
    """If the second rename of a pair fails (here: its temporary file vanished), the first file gets its
    previous contents back: the pair on disk is the old one, not a mix."""
    a, b = tmp_path / "a.csv", tmp_path / "a.csv.json"
    a.write_text("old table")
    b.write_text("old sidecar")
    new_b, new_a = AtomicFile(b), AtomicFile(a)
    new_b.temp.write_text("new sidecar")
    new_a.temp.write_text("new table")
    os.unlink(new_a.temp)
    with pytest.raises(FileNotFoundError):
        commit_together([new_b, new_a])
    assert (a.read_text(), b.read_text()) == ("old table", "old sidecar")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv", "a.csv.json"]


def test_a_held_signal_waits_for_the_block_even_with_other_threads_running():
    """A SIGINT sent to the process while a temporary file is being registered must wait for the block to
    end, though another thread (an FFT worker, a thread pool) is there to take it: were it acted on inside,
    the temporary file would be left behind (the campaign saw one after a Ctrl-C)."""
    stop = threading.Event()
    worker = threading.Thread(target=stop.wait)
    worker.start()
    arrived, wakeup = os.pipe()  # the C-level handler writes the signal's number here, whichever thread takes it
    os.set_blocking(wakeup, False)
    previous = signal.set_wakeup_fd(wakeup)
    reached_end = False
    try:
        with pytest.raises(KeyboardInterrupt):
            with signals_held():
                os.kill(os.getpid(), signal.SIGINT)
                assert os.read(arrived, 1) == bytes([signal.SIGINT])
                for _ in range(1000):  # bytecodes enough for a pending handler to run
                    pass
                reached_end = True
    finally:
        signal.set_wakeup_fd(previous)
        os.close(arrived)
        os.close(wakeup)
        stop.set()
        worker.join()
    assert reached_end


@pytest.mark.parametrize("kind", ["fifo", "symlink", "device", "folder"])
def test_an_output_that_is_not_a_regular_file_is_refused_and_left_alone(tmp_path, scenario, kind):
    """Writing over a FIFO, a symbolic link, a device (the null device, as root, was once replaced by a
    regular file) or a folder is refused with one line before the export starts."""
    target = tmp_path / "out.csv"
    if kind == "fifo":
        os.mkfifo(target)
    elif kind == "symlink":
        (tmp_path / "elsewhere.csv").write_text("keep me")
        target.symlink_to(tmp_path / "elsewhere.csv")
    elif kind == "device":
        try:
            os.mknod(target, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        except PermissionError:
            pytest.skip("making a device node needs root")
    else:
        target.mkdir()
    before = os.lstat(target)
    refused = export(scenario, tmp_path, "--out", "out.csv", "--duration", "5")
    assert refused.returncode == 2 and "give the path of a regular file" in refused.stderr, refused.stderr
    assert len(refused.stderr.strip().splitlines()) == 1
    after = os.lstat(target)
    assert (after.st_mode, after.st_ino, after.st_rdev) == (before.st_mode, before.st_ino, before.st_rdev)
    assert not list(tmp_path.glob(".out.*")) and not (tmp_path / "out.csv.json").exists()
    if kind == "symlink":
        assert (tmp_path / "elsewhere.csv").read_text() == "keep me"


def test_refusals_name_the_file(tmp_path):
    """The API refuses the same way (MarinesimError naming the path), and an unknown format is a ParameterError."""
    os.mkfifo(tmp_path / "pipe.csv")
    with pytest.raises(MarinesimError, match="pipe.csv: it is a FIFO"):
        AtomicFile(tmp_path / "pipe.csv")
    from marinesim.session.export import table_format

    with pytest.raises(ParameterError, match="unknown export format"):
        table_format(tmp_path / "x.csv", "xlsx")
    assert table_format(tmp_path / "x.parquet", None) == "parquet" and table_format(tmp_path / "x.out", None) == "csv"
