"""`marinesim export` as a user runs it: rows and sidecar written, an interrupted export leaves no
partial file, bad arguments and files refused in one line before anything is written."""

import json
import signal
import subprocess
import sys

import pytest

from conftest import HANG_S, ROOT, VESSEL_SCENARIO as SCENARIO, cli, wait_for, write


@pytest.mark.slow
def test_interrupted_export_leaves_no_partial_file(tmp_path):
    """Ctrl-C while the export writes its table (its temporary ``.part`` file is there: a day at 10 Hz is far
    from done then, however fast the machine) discards the new table and leaves the earlier export as it was."""
    scenario = write(tmp_path, SCENARIO.replace("duration_s = 120.0", "duration_s = 86400.0"))
    old = b"time_s\n0.0\n"
    (tmp_path / "motions.csv").write_bytes(old)  # an earlier export must survive intact
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "motions.csv",
                                "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_for(lambda: any(tmp_path.glob(".motions.*.part.csv")), process, "the export never began its table")
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=HANG_S)
    assert process.returncode == 130 and "interrupted" in stderr and "Traceback" not in stderr
    assert (tmp_path / "motions.csv").read_bytes() == old
    assert not list(tmp_path.glob(".motions.*")) and not (tmp_path / "motions.csv.json").exists()


def test_export_writes_the_rows_and_sidecar_asked_for_and_refuses_a_bad_dt(tmp_path):
    """``export`` writes the rows of the asked duration and dt with the asked seed in its sidecar, and a zero
    dt is refused with one line naming run.dt_s and its range (else the export would never end)."""
    scenario = write(tmp_path, SCENARIO)
    result = cli("export", str(scenario), "--out", "m.csv", "--duration", "20", "--dt", "0.5", "--seed", "3",
                 "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "41 rows" in result.stdout
    assert json.loads((tmp_path / "m.csv.json").read_text())["seed"] == 3
    refused = cli("export", str(scenario), "--out", "x.csv", "--dt", "0", cwd=tmp_path)
    message = "run.dt_s: must be in 0.001..duration_s, got 0.0"
    assert refused.returncode == 2 and message in refused.stderr and "Traceback" not in refused.stderr
    assert len(refused.stderr.strip().splitlines()) == 1 and not (tmp_path / "x.csv").exists()


def test_malformed_rao_file_is_refused_naming_file_and_line(tmp_path):
    lines = (ROOT / "rao" / "tanker" / "tanker.4").read_text().splitlines()
    lines[41] = lines[41].replace("E", "X", 1)
    bad = tmp_path / "bad.4"
    bad.write_text("\n".join(lines) + "\n")
    path = write(tmp_path, SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), "bad.4"))
    result = cli("export", str(path), "--out", "m.csv", cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert f"vessel.rao: {bad}, line 42: expected PER" in result.stderr
    assert not (tmp_path / "m.csv").exists()


def test_export_needs_a_vessel(tmp_path):
    text = SCENARIO.split("[vessel]")[0] + "[run]\nseed = 1\n"
    result = cli("export", str(write(tmp_path, text)), "--out", "m.csv", cwd=tmp_path)
    assert result.returncode == 2 and "no [vessel] section" in result.stderr
