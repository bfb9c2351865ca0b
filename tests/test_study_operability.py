"""Operability arithmetic (marinesim/study/operability.py) and the study's files (marinesim/study/results.py):
a hand-built 3 x 3 scatter gives the percentages summed by hand, and the files read back as written."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from PIL import Image

from marinesim.errors import MarinesimError, ParameterError
from marinesim.study.operability import operability
from marinesim.study.results import FILES, dataset, pictures, summary_csv, write_study
from marinesim.study.scatter import Scatter

TP = np.array([6.0, 9.0, 12.0])
HEADINGS = np.array([90.0, 180.0])
NAMES = ["heave rms", "roll max"]
LIMITS = np.array([0.5, 4.0])


def hand_scatter() -> Scatter:
    """Hs 1, 2, 3 m x Tp 6, 9, 12 s with probabilities 1..9 / 45."""
    hs, tp = np.meshgrid([1.0, 2.0, 3.0], TP, indexing="ij")
    return Scatter(hs.ravel(), tp.ravel(), np.arange(1.0, 10.0) / 45.0, "tp")


def value1() -> np.ndarray:
    """(Tp, heading, criterion) at Hs = 1 m: beam seas roll hard at 9 s, head seas heave at 12 s."""
    v = np.empty((3, 2, 2))
    v[:, 0, 0] = [0.10, 0.15, 0.20]   # heave rms per m of Hs, beam
    v[:, 1, 0] = [0.05, 0.12, 0.24]   # head
    v[:, 0, 1] = [1.0, 3.0, 1.5]      # roll max, deg per m of Hs, beam
    v[:, 1, 1] = [0.1, 0.2, 0.3]      # head
    return v


def limiting() -> np.ndarray:
    """Limiting Hs (Tp, heading, criterion) of criteria linear in Hs: limit / value at Hs 1 m."""
    return LIMITS / value1()


def test_a_hand_built_scatter_gives_the_percentages_summed_by_hand():
    scatter = hand_scatter()
    result = operability(limiting(), TP, HEADINGS, scatter, scatter.period)
    # limiting Hs = limit / value1. Beam: heave 5, 3.33, 2.5; roll 4, 1.33, 2.67 -> 4, 1.33, 2.5 m
    np.testing.assert_allclose(result.limiting_hs_all[0], [4.0, 4.0 / 3.0, 2.5])
    assert result.governing[0].tolist() == [1, 1, 0]
    # head: heave 10, 4.17, 2.08; roll 40, 20, 13.3 -> 10, 4.17, 2.08, heave governs everywhere
    np.testing.assert_allclose(result.limiting_hs_all[1], [10.0, 0.5 / 0.12, 0.5 / 0.24])
    assert result.governing[1].tolist() == [0, 0, 0]
    # cells (Hs, Tp) with weights: Hs 1: 1, 2, 3 (Tp 6, 9, 12); Hs 2: 4, 5, 6; Hs 3: 7, 8, 9
    # beam workable: Hs1 Tp6, Tp9, Tp12; Hs2 Tp6, Tp12; Hs3 Tp6 -> 1+2+3+4+6+7 = 23
    # head workable: all at Tp 6 and 9 (1+2+4+5+7+8), Tp 12 only Hs 1 and 2 (3+6) -> 36
    np.testing.assert_allclose(result.operability_pct, [100 * 23 / 45, 100 * 36 / 45])
    # best heading per sea state: head works wherever beam does, and more -> 36 / 45 as well
    assert result.overall_pct == pytest.approx(100 * 36 / 45)
    assert result.best_heading_deg == 180.0


def test_a_cell_period_outside_the_study_is_refused():
    scatter = hand_scatter()
    with pytest.raises(ParameterError, match="peak period"):
        operability(limiting(), TP, HEADINGS, scatter, scatter.period + 0.5)


def test_the_study_files_read_back_as_written_and_are_reproducible(tmp_path):
    scatter = hand_scatter()
    result = operability(limiting(), TP, HEADINGS, scatter, scatter.period)
    data = dataset(result, value1(), NAMES, ["m", "deg"], LIMITS, scatter, scatter.period,
                   {"scenario": "hand.toml", "scenario_sha256": "ab" * 32})
    pngs = pictures(result, scatter, scatter.period, NAMES, "hand study")
    written = write_study(tmp_path / "study", data, summary_csv(result, NAMES), pngs)
    assert sorted(p.name for p in written) == sorted(FILES)
    back = xr.open_dataset(tmp_path / "study" / "operability.nc", engine="scipy")
    np.testing.assert_array_equal(back["limiting_hs_m_all"].values, result.limiting_hs_all)
    assert back["limiting_hs_m"].attrs["units"] == "m" and back.attrs["scenario_sha256"] == "ab" * 32
    assert list(back["criterion"].values) == NAMES
    np.testing.assert_allclose(back["operability_pct"].sel(heading_deg=180.0), 80.0)
    back.close()
    table = pd.read_csv(tmp_path / "study" / "summary.csv")
    assert len(table) == 6 and table.loc[0, "governing"] == "roll max"
    assert table["limiting_hs_m"].iloc[1] == pytest.approx(4.0 / 3.0, rel=1e-3)
    for name in ("operability_polar.png", "limiting_hs.png", "governing.png"):
        image = np.asarray(Image.open(tmp_path / "study" / name).convert("L"))
        assert image.std() > 10, f"{name} looks blank"
    again = write_study(tmp_path / "again", data, summary_csv(result, NAMES),
                        pictures(result, scatter, scatter.period, NAMES, "hand study"))
    for first, second in zip(written, again):
        assert first.read_bytes() == second.read_bytes(), first.name


def test_a_file_in_place_of_the_folder_is_refused(tmp_path):
    (tmp_path / "study").write_text("x")
    scatter = hand_scatter()
    result = operability(limiting(), TP, HEADINGS, scatter, scatter.period)
    data = dataset(result, value1(), NAMES, ["m", "deg"], LIMITS, scatter, scatter.period, {})
    with pytest.raises(MarinesimError, match="not a folder"):
        write_study(tmp_path / "study", data, summary_csv(result, NAMES), {})
