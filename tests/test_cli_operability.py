"""``marinesim operability`` end to end, as a user runs it: a vessel that follows the sea over a hand-made
scatter gives the percentages summed by hand; the shipped crane lift over the shipped North Sea table
writes its files reproducibly; the time-domain check runs on a real LocalCluster and resumes; bad input is
one line and exit 2."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from conftest import ROOT, cli, write
from marinesim.cli import main
from test_criteria_spectral import constant_heave

HAND_SCATTER = "# by hand\nhs_m,tp_s,count\n1,6,10\n1,10,20\n2,6,30\n2,10,15\n3,10,25\n"
"""Cells: Hs 1 m (30 of 100), 2 m (45), 3 m (25)."""

FOLLOWER = """
[[sea]]
type = "jonswap"
hs_m = 2.0
tp_s = 8.0
gamma = 3.3
from_deg = 0.0
spreading_s = 8.0

[vessel]
rao = "heave.csv"
heading_deg = 0.0

[[criteria]]
name = "heave"
quantity = "heave_rms_m"
limit = {limit}
"""


@pytest.fixture
def follower(tmp_path):
    """A scenario whose vessel heaves exactly with the sea (heave RAO 1), its limit given."""
    constant_heave(tmp_path)  # writes tmp_path / "heave.csv"
    (tmp_path / "site.csv").write_text(HAND_SCATTER)
    return lambda limit: write(tmp_path, FOLLOWER.format(limit=limit))


@pytest.mark.parametrize("limit,expected", [(0.5, 75.0), (0.3, 30.0), (0.2, 0.0), (0.75, 100.0)])
def test_a_vessel_that_follows_the_sea_is_workable_below_four_times_its_heave_limit(follower, tmp_path, capsys,
                                                                                       limit, expected):
    """Limiting Hs = 4 x the heave RMS limit at every Tp and heading, so the operability is the probability of
    the cells with Hs <= 4 L: 0.5 m -> Hs 2 m -> 30 + 45 of 100; 0.3 -> 1.2 m -> 30; 0.2 -> 0.8 m -> none."""
    scenario = follower(limit)
    assert main(["operability", str(scenario), "--scatter", str(tmp_path / "site.csv"), "--out",
                 str(tmp_path / "out"), "--headings", "0,90,180", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["operability_pct"] == {"0": expected, "90": expected, "180": expected}
    assert result["overall_pct"] == expected
    with xr.open_dataset(tmp_path / "out" / "operability.nc", engine="scipy") as data:
        np.testing.assert_allclose(data["limiting_hs_m_all"], 4 * limit, rtol=2e-4)


def test_the_crane_lift_over_the_north_sea_writes_the_same_files_twice(tmp_path):
    args = ["operability", str(ROOT / "configs" / "training" / "crane_lift.toml"), "--scatter",
            str(ROOT / "configs" / "scatter" / "northern_north_sea.csv"), "--headings", "0:360:30"]
    first = cli(*args, "--out", str(tmp_path / "a"))
    assert first.returncode == 0, first.stderr
    assert "overall" in first.stdout and "governing" in first.stdout
    assert cli(*args, "--out", str(tmp_path / "b")).returncode == 0
    for name in ("operability.nc", "summary.csv", "operability_polar.png", "limiting_hs.png", "governing.png"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name
    table = pd.read_csv(tmp_path / "a" / "summary.csv")
    with xr.open_dataset(tmp_path / "a" / "operability.nc", engine="scipy") as data:
        by_heading = table.groupby("heading_deg")["operability_pct"].first()
        np.testing.assert_allclose(by_heading.values, data["operability_pct"].values, atol=5e-4)
        head, beam = data["operability_pct"].sel(heading_deg=180.0), data["operability_pct"].sel(heading_deg=90.0)
        assert head > beam + 10, "the supply vessel rolls in beam seas: lifting is easier head to sea"
        assert data.attrs["scatter_sha256"] and data.attrs["scenario_sha256"]


def test_the_time_domain_check_runs_on_a_cluster_and_resumes(follower, tmp_path, capsys):
    """Two seeds of two cells at two headings on a LocalCluster of two processes; the follower's heave RMS
    over each 3 h record must be Hs/4 within the records' scatter, and a second run reopens the same store."""
    scenario = follower(0.5)
    args = ["operability", str(scenario), "--scatter", str(tmp_path / "site.csv"), "--out", str(tmp_path / "out"),
            "--headings", "90,180", "--time-domain", "2", "--cells", "0,4", "--workers", "2", "--quiet"]
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "time-domain check" in text
    with xr.open_dataset(tmp_path / "out" / "operability.nc", engine="scipy") as data:
        mean, spectral = data["time_domain_mean"].values, data["spectral_value"].values
        np.testing.assert_allclose(spectral[..., 0], [[0.25, 0.25], [0.75, 0.75]], rtol=2e-4)
        np.testing.assert_allclose(mean[..., 0], spectral[..., 0], rtol=0.1)
    store = tmp_path / "out" / "time_domain.zarr"
    assert store.is_dir()
    again = cli(*args[:-1], cwd=tmp_path)
    assert again.returncode == 0, again.stderr


@pytest.mark.parametrize("limit,period_h,alpha,expected", [(0.5, 24.0, 0.73, 30.0), (0.5, 20.0, 0.73, 30.0),
                                                           (0.75, 24.0, 0.745, 75.0), (0.75, 12.5, 0.745, 75.0),
                                                           (0.75, 6.0, 0.775, 75.0), (1.5, 72.0, 0.72, 100.0),
                                                           (2.0, 72.0, 0.72, 100.0), (2.0, 24.0, 0.78, 100.0)])
def test_the_forecast_limit_is_the_alpha_of_the_planned_period_at_the_design_hs(follower, tmp_path, capsys,
                                                                                  limit, period_h, alpha, expected):
    """DNV-OS-H101 Table 4-1 base case by hand: the design Hs is 4 x the heave limit; alpha is the table's row
    for T_POP (a row holds up to its hours: 20 h and 12.5 h take the 24 h row, 6 h the 12 h row), linear between
    its Hs columns (3 m: halfway between 2 and 4 m; 6 m: the 6 m column; 8 m: still the 6 m column, which the
    standard holds for Hs >= 6 m). Operability counts the cells below alpha x 4 L: 2 m x 0.73 = 1.46 m keeps
    only Hs 1 (30 of 100); 3 m x 0.745 = 2.2 m keeps Hs 1 and 2. A wrong row or an extrapolated column would
    change the limiting Hs written to the file."""
    scenario = follower(limit)
    assert main(["operability", str(scenario), "--scatter", str(tmp_path / "site.csv"), "--out",
                 str(tmp_path / "out"), "--headings", "0,180", "--planned-period-h", str(period_h), "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["operability_pct"] == {"0": expected, "180": expected}
    with xr.open_dataset(tmp_path / "out" / "operability.nc", engine="scipy") as data:
        np.testing.assert_allclose(data["limiting_hs_m_all"], alpha * 4 * limit, rtol=2e-4)
        assert data.attrs["planned_period_h"] == period_h
        assert data.attrs["alpha_table"].endswith("dnv_base_case.csv")


@pytest.mark.parametrize("args,words", [
    (["--scatter", "site.csv", "--planned-period-h", "72.5"], "--planned-period-h (T_POP) must be in (0, 72] h"),
    (["--scatter", "site.csv", "--planned-period-h", "96"], "not weather-restricted"),
    (["--scatter", "site.csv", "--alpha-table", "site.csv"], "--alpha-table needs --planned-period-h"),
    (["--scatter", "site.csv", "--planned-period-h", "24", "--alpha-table", "site.csv"], "planned_period_h"),
    (["--scatter", "missing.csv"], "missing.csv"),
    (["--scatter", "site.csv", "--headings", "0:360:0"], "--headings"),
    (["--scatter", "site.csv", "--alpha", "1.5"], "--alpha"),
    (["--scatter", "site.csv", "--duration-h", "0"], "--duration-h"),
])
def test_bad_input_is_one_line_and_exit_2(follower, tmp_path, args, words, capsys, monkeypatch):
    """Each mistake (T_POP past the table, --alpha-table without a T_POP, a file that is no alpha table, a missing
    file, bad headings, alpha or duration) must be one line naming what to fix, exit 2, not a traceback."""
    scenario = follower(0.5)
    monkeypatch.chdir(tmp_path)
    assert main(["operability", str(scenario), "--out", str(tmp_path / "out"), *args]) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1, err


def test_a_scenario_without_criteria_is_refused(tmp_path):
    (tmp_path / "site.csv").write_text(HAND_SCATTER)
    run = cli("operability", str(ROOT / "configs" / "default.toml"), "--scatter", str(tmp_path / "site.csv"),
              "--out", str(tmp_path / "out"))
    assert run.returncode == 2 and "no [[criteria]]" in run.stderr, run.stderr
