"""The `marinesim` command's contract: --version and --help, and a bad value is one line on stderr
naming it, exit status 2, no traceback. The real command (a process of its own) answers --version, --help and
one bad value; the other bad values go to its entry point in this process (conftest's ``cli``)."""

import signal
import subprocess
import sys

import pytest

import marinesim
from conftest import HANG_S, ROOT, VESSEL_SCENARIO, cli, cli_process, wait_for, write


def test_version_and_help():
    assert cli_process("--version").stdout.strip() == f"marinesim {marinesim.__version__}"
    assert "sea" in cli_process("--help").stdout


def test_the_real_command_gives_a_bad_value_one_line_and_exit_2():
    """As a user's shell runs it (``python -m marinesim``): what ends the process after the entry point returns
    adds nothing to its one line."""
    result = cli_process("sea", "--hs", "-1")
    assert result.returncode == 2 and result.stderr.strip().splitlines() == [
        "marinesim sea: error: hs must be in 0..30 m, got -1.0"], result.stderr


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


def test_a_command_imports_the_mesh_and_fft_libraries_only_when_it_needs_them(tmp_path):
    """``export`` of a scenario refused for a bad value (what most user mistakes meet): the command's modules and
    the scenario's are loaded, but trimesh (with networkx) and pyfftw (which imports dask.array and xarray) are not,
    a second of the refusal's start. A valid scenario then reads its hull with trimesh and plans its ocean's FFTs with
    pyfftw. What would be wrong: a module's top importing them again, for a constant or a type."""
    bad = write(tmp_path, VESSEL_SCENARIO.replace("hs_m = 4.0", "hs_m = -4.0"), "bad.toml")
    good = write(tmp_path, VESSEL_SCENARIO, "good.toml")
    code = ("import sys\n"
            "from marinesim.cli import main\n"
            "heavy = {'trimesh', 'networkx', 'pyfftw', 'dask', 'xarray'}\n"
            f"print(main(['export', {str(bad)!r}, '--out', 'm.csv', '--quiet']))\n"
            "print(sorted({m.split('.')[0] for m in sys.modules} & heavy))\n"
            f"print(main(['export', {str(good)!r}, '--out', 'm.csv', '--quiet', '--duration', '1']))\n"
            "print(sorted({m.split('.')[0] for m in sys.modules} & heavy))\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path)
    lines = [line for line in result.stdout.splitlines() if not line.startswith("wrote ")]
    assert lines[:3] == ["2", "[]", "0"], result.stdout + result.stderr
    assert "'pyfftw'" in lines[3] and "'trimesh'" in lines[3], lines[3]


@pytest.mark.parametrize("library", ["numpy", "scipy", "numba"])
def test_ctrl_c_while_the_command_loads_gives_one_line(tmp_path, library):
    """Ctrl-C while a command imports what it needs (numpy, scipy, numba, the ocean) used to print a
    KeyboardInterrupt traceback: it ends with one line and status 130. The signal is sent once numpy's, scipy's or
    numba's library is mapped: early, midway and late in the command's imports, on a fast machine as on a slow one
    (a moment taken as a time after the start would fall elsewhere, or after the export's end)."""
    scenario = write(tmp_path, VESSEL_SCENARIO)
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "m.csv",
                                "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wait_for(lambda: loading(process.pid, library), process, f"the export never loaded {library}")
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=HANG_S)
    assert "Traceback" not in stderr
    assert process.returncode == 130, stderr
    assert len(stderr.strip().splitlines()) == 1 and "interrupted" in stderr, stderr
    assert not list(tmp_path.glob(".m.*")) and not (tmp_path / "m.csv.lock").exists()
