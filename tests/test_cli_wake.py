"""`marinesim wake`: the Kelvin wake of a hull file written, plotted and reported; bad input refused in one line."""

import json
import math

import pytest

from conftest import ROOT
from marinesim.cli import main
from marinesim.wake.compute import Wake

G = 9.80665


def test_wake_command(tmp_path, capsys):
    out, plot = tmp_path / "wake.npz", tmp_path / "wake.png"
    code = main(["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "25", "--nx", "1024", "--ny", "512",
                 "--out", str(out), "--plot", str(plot), "--json", "--quiet"])
    assert code == 0
    report = json.loads(capsys.readouterr().out)
    for key in ("speed_m_s", "froude", "wave_resistance_N", "kelvin_half_angle_deg", "seconds"):
        assert key in report
    assert report["speed_m_s"] == pytest.approx(25 * 1852 / 3600)
    assert report["froude"] == pytest.approx(report["speed_m_s"] / math.sqrt(G * 100.0), rel=1e-3)
    assert Wake.load(out).elevation.shape == (512, 1024) and plot.stat().st_size > 10_000


@pytest.mark.parametrize("args, message", [
    (["--speed-kn", "0"], "speed"),
    (["--speed-kn", "nan"], "speed"),
    (["--speed-kn", "12", "--draft", "-1"], "draft"),
    (["--speed-kn", "12", "--units", "mm"], "units='m'"),
    (["--speed-kn", "12", "--scale", "0"], "scale must be > 0"),
    (["--speed-kn", "12", "--nx", "8"], "nx must be >= 16"),
    (["--speed-kn", "12", "--spacing", "30"], "cannot hold the transverse waves"),
    (["--speed-kn", "12,x"], "--speed-kn must be comma-separated knots"),
])
def test_wake_command_refuses_bad_input(args, message, capsys):
    code = main(["wake", str(ROOT / "hulls" / "wigley.stl"), *args, "--quiet"])
    err = capsys.readouterr().err
    assert code == 2 and message in err and "Traceback" not in err and len(err.strip().splitlines()) == 1
