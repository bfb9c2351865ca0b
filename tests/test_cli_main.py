"""The `marinesim` command's contract: --version and --help, and a bad value is one line on stderr
naming it, exit status 2, no traceback."""

import pytest

import marinesim
from conftest import cli


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
