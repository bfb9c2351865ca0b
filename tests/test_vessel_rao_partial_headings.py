"""Partial RAO tables: a single heading, or headings with a gap wider than interpolation may bridge. The table
says which headings it covers; waves inside them are answered from its own headings (never interpolated across
the gap); a sea whose variance meets the vessel elsewhere is refused, naming what the table covers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO, cli, write
from marinesim.errors import ParameterError
from marinesim.sea.ocean import Components
from marinesim.vessel.rao import HEADING_MARGIN, make_table
from marinesim.vessel.response import Response, Track
from marinesim.vessel.summary import format_rao_summary, rao_summary

OMEGA = np.array([0.3, 0.6, 0.9])


def table_at(headings_deg: list[float]):
    """A table whose heave at heading b is b / 100 (so the heading each answer came from can be read off)."""
    beta = np.radians(headings_deg)
    values = np.zeros((1, beta.size, OMEGA.size, 6), complex)
    values[0, :, :, 2] = np.array(headings_deg)[:, None] / 100.0
    return make_table(OMEGA, beta, [0.0], values)


def heave_at(table, heading_deg: float) -> float:
    return float(table(OMEGA[:1], np.radians([heading_deg]))[0, 2].real)


def test_the_arcs_a_partial_table_covers():
    """One heading covers itself +- the margin; headings 90..180 in 30 deg steps are one arc; a gap of 180 deg
    leaves two arcs; 0/90/180/270 is the whole circle (no gap over 90 deg)."""
    margin = math.degrees(HEADING_MARGIN)
    assert table_at([180.0]).covered_text() == f"{180 - margin:g}..{180 + margin:g} deg (tabulated 180)"
    assert table_at([90.0, 120.0, 150.0, 180.0]).covered_text() == "75..195 deg (tabulated 90..180)"
    assert len(table_at([0.0, 180.0]).covered) == 2
    assert table_at([0.0, 90.0, 180.0, 270.0]).covered is None
    covers = table_at([90.0, 120.0, 150.0, 180.0]).covers(np.radians([60.0, 80.0, 135.0, 194.0, 200.0, 300.0]))
    assert covers.tolist() == [False, True, True, True, False, False]


def test_answers_come_from_the_covered_headings_never_across_a_gap():
    """If this fails, a partial table is interpolated across its gap (a beam sea from a 0/180 table would be
    the mean of following and head seas) or extrapolated past its ends."""
    table = table_at([0.0, 180.0])
    assert heave_at(table, 180.0) == pytest.approx(1.8)
    assert heave_at(table, 190.0) == pytest.approx(1.8)   # beyond the tabulated end: its value held
    assert heave_at(table, 350.0) == pytest.approx(0.0)
    assert heave_at(table, 100.0) == pytest.approx(1.8)   # outside every arc: the nearest end, not 0.9
    arc = table_at([90.0, 120.0, 150.0, 180.0])
    assert heave_at(arc, 135.0) == pytest.approx(1.35)    # inside an arc: interpolated as before


def test_a_whole_circle_from_15_deg_wraps_between_its_last_and_first_headings():
    """Headings 15..345 deg every 30 deg cover the circle: a wave at 0, 5 or 14 deg lies between 345 and 15 deg
    and is interpolated between them (as at 350 deg), not extrapolated from the 15..45 deg cell (which gave 0.0,
    0.05 and 0.14 instead of 1.8, 1.25 and 0.26)."""
    table = table_at([15.0 + 30.0 * i for i in range(12)])
    assert table.covered is None
    for heading in (0.0, 5.0, 14.0, 350.0, 359.0, 360.0, -10.0):
        expected = 3.45 + (0.15 - 3.45) * ((heading - 345.0) % 360.0) / 30.0
        assert heave_at(table, heading) == pytest.approx(expected, abs=1e-12), heading
    assert heave_at(table, 15.0) == pytest.approx(0.15) and heave_at(table, 30.0) == pytest.approx(0.3)


def waves(beta_rel_deg: np.ndarray, variance: np.ndarray) -> Components:
    """One frequency (0.6 rad/s, deep water) from the given relative headings (vessel heading 0)."""
    k = 0.6**2 / 9.80665
    b = np.radians(beta_rel_deg)
    return Components(np.full(b.size, 0.6), k * np.cos(b), k * np.sin(b), np.sqrt(2.0 * variance) + 0j,
                      np.zeros(b.size, int))


def test_a_sea_outside_the_table_is_refused_naming_what_it_covers():
    """A head-seas-only table answers a long-crested head sea, and refuses beam seas and a short-crested sea
    whose spreading puts more than 1 % of the variance outside 165..195 deg: the message names the covered
    headings and where the waves come from."""
    table = table_at([180.0])
    Response(table, waves(np.array([180.0]), np.array([1.0])), Track(heading=0.0))
    Response(table, waves(np.array([180.0, 100.0]), np.array([1.0, 0.005])), Track(heading=0.0))  # 0.5 % outside
    with pytest.raises(ParameterError, match=r"covers relative wave headings 165\.\.195 deg \(tabulated 180\) "
                                             r"only: 100 % .*around 90 deg"):
        Response(table, waves(np.array([90.0]), np.array([1.0])), Track(heading=0.0))
    spread = np.arange(90.0, 271.0, 5.0)
    weights = np.cos(np.radians(spread - 180.0) / 2.0) ** 30  # cos-2s, s = 15, about head seas
    with pytest.raises(ParameterError, match="% of this sea's variance meets the vessel at other headings"):
        Response(table, waves(spread, weights / weights.sum()), Track(heading=0.0))


def test_the_summary_says_the_table_is_partial_and_checks_only_what_it_covers():
    summary = rao_summary(table_at([150.0, 180.0]))
    assert summary["headings_covered"] == "135..195 deg (tabulated 150..180)"
    assert summary["long_wave_limits"]["sway"]["status"] == "not tabulated at 90 deg"
    assert "a partial table: it covers 135..195 deg" in format_rao_summary(summary)


def test_an_export_in_a_sea_the_table_does_not_cover_is_one_line(tmp_path):
    """The AQWA cylinder's listing has 0 and 180 deg only: an export in a beam sea ends with one line naming the
    covered headings (exit 2); the same export in a long-crested head sea runs."""
    cylinder = ROOT / "tests" / "data" / "aqwa" / "cylinder_excerpt.LIS"
    text = (VESSEL_SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), str(cylinder))
            .replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "").replace("speed_kn = 6.0", "speed_kn = 0.0")
            .replace("spreading_s = 10.0", 'spreading = "long-crested"')
            .replace("duration_s = 120.0", "duration_s = 20.0"))
    beam = write(tmp_path, text.replace("heading_deg = 30.0", "heading_deg = 110.0"), "beam.toml")
    result = cli("export", str(beam), "--out", "beam.csv", "--quiet", cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr, result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and "covers relative wave headings" in result.stderr
    head = write(tmp_path, text.replace("heading_deg = 30.0", "heading_deg = 200.0"), "head.toml")  # into the waves
    result = cli("export", str(head), "--out", "head.csv", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr


def test_an_operability_study_refuses_headings_the_table_does_not_cover(tmp_path):
    """A study of the head-seas-only AQWA listing is answered at 180 deg in a long-crested sea, and refuses
    --headings at 90 deg naming what the table covers, before any work."""
    cylinder = ROOT / "tests" / "data" / "aqwa" / "cylinder_excerpt.LIS"
    text = (VESSEL_SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), str(cylinder))
            .replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "").replace("speed_kn = 6.0", "speed_kn = 0.0")
            .replace("spreading_s = 10.0", 'spreading = "long-crested"')
            + '\n[[criteria]]\nname = "heave"\nquantity = "heave_rms_m"\nlimit = 1.0\n')
    scenario = write(tmp_path, text)
    scatter = ROOT / "configs" / "scatter" / "northern_north_sea.csv"
    result = cli("operability", str(scenario), "--scatter", str(scatter), "--out", "study", "--headings", "90,180",
                 cwd=tmp_path)
    assert result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert "--headings 90 deg" in result.stderr and "165..195 deg (tabulated 180)" in result.stderr
    result = cli("operability", str(scenario), "--scatter", str(scatter), "--out", "study", "--headings", "180",
                 "--json", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
