"""The `marinesim` command's contract: --version and --help, and a bad value is one line on stderr
naming it, exit status 2, no traceback."""

import signal
import subprocess
import sys
import time

import pytest

import marinesim
from conftest import VESSEL_SCENARIO, cli, write


def test_version_and_help():
    assert cli("--version").stdout.strip() == f"marinesim {marinesim.__version__}"
    assert "sea" in cli("--help").stdout


@pytest.mark.parametrize("args, value", [
    (["--hs", "-1"], "-1"),
    (["--hs", "0"], "0"),
    (["--tp", "0"], "0"),
    (["--gamma", "0.5"], "0.5"),
    (["--depth", "-3"], "-3"),
    (["--depth", "0"], "0"),
    (["--resolution", "100"], "100"),
    (["--hs", "nan"], "nan"),
    (["--from-deg", "nan"], "nan"),
    (["--spectrum", "tma"], "depth"),
    (["--swell-hs", "-2"], "swell"),
    (["--spreading", "cos2s"], "spreading-s"),
    (["--plot", "/nonexistent/dir/x.png"], "/nonexistent/dir"),
    (["--tiles", "0"], "tiles"),
    (["--seed", "-1"], "seed"),
    (["--choppiness", "nan"], "choppiness"),
    (["--time", "inf"], "time"),
    (["--u10", "15", "--fetch-km", "-1"], "fetch_km"),
    (["--u10", "15", "--spectrum", "pm"], "u10"),
    (["--spreading-s", "-1"], "-1"),
    (["--spectrum", "regular", "--period", "0"], "period"),
])
def test_bad_values_give_one_line_and_exit_2(args, value):
    result = cli("sea", *args)
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and value in lines[0], result.stderr


def loading(pid: int, library: str) -> bool:
    """Whether process ``pid`` has mapped a shared library whose path contains ``library``."""
    try:
        return library in open(f"/proc/{pid}/maps").read()
    except FileNotFoundError:
        return False


def test_the_command_line_itself_imports_no_numerics():
    """``marinesim`` parses its arguments before it loads numpy, scipy or the physics, and loads them with
    Ctrl-C held (``cli._load``). A command module that imports numpy at its top puts numpy's import outside
    the hold: a Ctrl-C there ends in numpy's own ImportError traceback (seen: "PyCapsule_Import could not
    import module datetime"), and every ``--help`` pays for the import."""
    code = ("import sys, marinesim.cli; print(sorted({m.split('.')[0] for m in sys.modules} & "
            "{'numpy', 'scipy', 'pandas', 'trimesh', 'xarray', 'moderngl', 'pyglet'}))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[]"


@pytest.mark.parametrize("after_s", [0.0, 0.2, 0.5])
def test_ctrl_c_while_the_command_loads_gives_one_line(tmp_path, after_s):
    """Ctrl-C while a command imports what it needs (numpy, scipy, the ocean: the first second or so) used to
    print a KeyboardInterrupt traceback: it ends with one line and status 130. The signal is sent once numpy's
    library is mapped (the command's imports have begun), and 0.2 s and 0.5 s later."""
    scenario = write(tmp_path, VESSEL_SCENARIO)
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "m.csv",
                                "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while not loading(process.pid, "numpy") and process.poll() is None and time.time() < deadline:
        time.sleep(0.002)
    time.sleep(after_s)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=120)
    assert "Traceback" not in stderr
    assert process.returncode in (0, 130), stderr  # 0: the export was done before the signal came
    assert process.returncode == 0 or (len(stderr.strip().splitlines()) == 1 and "interrupted" in stderr)
    assert not list(tmp_path.glob(".m.*")) and not (tmp_path / "m.csv.lock").exists()
