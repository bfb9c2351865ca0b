"""`marinesim rao` as a user runs it: the JSON summary and plot of a VERES table, the text summary of a
WAMIT one, and bad input refused in one line."""

import json
import math
import re

import pytest

from conftest import ROOT, VESSEL_SCENARIO as SCENARIO, cli, write


def test_rao_reports_limits_and_resonances_plots_and_refuses_bad_input(tmp_path):
    """``rao`` reports the S175's speeds, the long-wave limits (heave and pitch 1) and its slow roll resonance,
    plots it, and refuses a scenario given as an RAO file and unreadable headings with one line each."""
    scenario = write(tmp_path, SCENARIO)
    report = cli("rao", str(ROOT / "rao" / "s175" / "input.re1"), "--json", "--plot", str(tmp_path / "rao.png"))
    assert report.returncode == 0, report.stderr
    summary = json.loads(report.stdout)
    assert summary["speeds_kn"] == pytest.approx([0, 5, 10, 15, 20], abs=0.01)
    assert summary["long_wave_limits"]["heave"]["status"] == "ok"
    assert summary["long_wave_limits"]["pitch"]["ratio"] == pytest.approx(1.0, abs=0.05)
    assert 15.0 < summary["resonance_period_s"]["roll"] < 30.0  # S175: slow roll, T ~ 21 s
    assert (tmp_path / "rao.png").stat().st_size > 30_000
    text = cli("rao", str(ROOT / "rao" / "tanker" / "tanker.4")).stdout
    assert "long-wave limits" in text and re.search(r"pitch\s+1\.000\s+ok", text)
    for args, message in ((("rao", str(scenario)), "unknown RAO format '.toml' (nor does its content match one)"),
                          (("rao", str(ROOT / "rao" / "s175" / "input.re1"), "--plot", "x.png", "--headings", "head"),
                           "--headings must be comma-separated degrees")):
        refused = cli(*args, cwd=tmp_path)
        assert refused.returncode == 2 and message in refused.stderr and "Traceback" not in refused.stderr
        assert len(refused.stderr.strip().splitlines()) == 1 and not (tmp_path / "x.csv").exists()


def test_the_rao_plot_shows_the_periods_where_the_waves_and_the_resonances_are():
    """The tanker's table runs to 160 s: its plot ends at 30 s, where the 5-25 s of ocean waves fill the axis
    (not squeezed into the left edge); the semisubmersible's pitch resonance near 37 s
    keeps its plot running past it (1.5 times the period)."""
    from marinesim.vessel import read_rao
    from marinesim.vessel.plot import period_axis_end
    from marinesim.vessel.summary import resonance_periods

    tanker = read_rao(ROOT / "rao" / "tanker" / "tanker.4")
    assert 2 * math.pi / tanker.omega[0] > 150.0 and period_axis_end(tanker) == 30.0
    semisub = read_rao(ROOT / "rao" / "semisub" / "semisub.4")
    pitch = resonance_periods(semisub)["pitch"]
    assert pitch > 30.0 and period_axis_end(semisub) == pytest.approx(1.5 * pitch)
