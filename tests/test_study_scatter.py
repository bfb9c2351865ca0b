"""Scatter diagrams (marinesim/study/scatter.py): the shipped tables are what their cited joint models give,
the discretisation agrees with sampling the model, and a damaged file is refused on its line."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from marinesim.errors import FileFormatError
from marinesim.study.scatter import JOINT_MODELS, discretise, read_scatter, scatter_csv

SHIPPED = {"north_atlantic": (np.arange(0.0, 18.0), np.arange(3.0, 20.0)),
           "world_wide": (np.arange(0.0, 18.0), np.arange(3.0, 20.0)),
           "northern_north_sea": (np.arange(0.0, 15.0), np.arange(2.0, 25.0))}
"""Each shipped diagram's cell edges: Hs (m) and the period (s)."""


@pytest.mark.parametrize("key", sorted(SHIPPED))
def test_the_shipped_diagram_is_its_joint_model(key):
    """The file under configs/scatter is the cited model over its cells, to the byte: nobody edited a number."""
    path = ROOT / "configs" / "scatter" / f"{key}.csv"
    assert path.read_text() == scatter_csv(key, *SHIPPED[key])
    scatter = read_scatter(path)
    assert scatter.probability.sum() == pytest.approx(1.0, abs=1e-12)
    assert scatter.period_kind == JOINT_MODELS[key].period


@pytest.mark.parametrize("key", sorted(SHIPPED))
def test_the_cells_hold_what_sampling_the_model_gives(key):
    """Second method: draw 400 000 (Hs, T) pairs from the model (Hs by inverting its CDF, ln T normal given Hs)
    and count them per cell. Each cell's probability must lie within 4 binomial standard errors plus 2 % of the
    count (the sampler's Hs inversion is on a grid). A wrong conditional law, or cells shifted by one, fails."""
    model, (hs_edges, t_edges) = JOINT_MODELS[key], SHIPPED[key]
    rng = np.random.default_rng(3)
    grid = np.linspace(0.0, 25.0, 250_001)
    cdf = model.hs_cdf(grid)
    hs = np.interp(rng.uniform(cdf[0], cdf[-1], 400_000), cdf, grid)
    a0, a1, a2 = model.a
    b0, b1, b2 = model.b
    spread = b0 + b1 * np.exp(b2 * hs)
    period = np.exp(a0 + a1 * hs ** a2 + (np.sqrt(spread) if model.variance else spread) * rng.standard_normal(hs.size))
    counts, _, _ = np.histogram2d(hs, period, (hs_edges, t_edges))
    expected = discretise(model, hs_edges, t_edges) * hs.size
    tolerance = 4 * np.sqrt(expected + 1) + 0.02 * expected
    assert np.all(np.abs(counts - expected) <= tolerance), np.abs(counts - expected).max()


def test_counts_are_normalised_and_tz_is_kept_as_tz(tmp_path):
    path = tmp_path / "site.csv"
    path.write_text("# a hand-made table\nhs_m,tz_s,count\n1,6,30\n2,7,50\n3,8,20\n")
    scatter = read_scatter(path)
    np.testing.assert_allclose(scatter.probability, [0.3, 0.5, 0.2])
    assert scatter.period_kind == "tz" and scatter.hs.tolist() == [1.0, 2.0, 3.0]


@pytest.mark.parametrize("text,line,words", [
    ("hs_m,tp_s\n1,8\n", 1, "probability/count"),
    ("hs_m,tp_s,tz_s,probability\n1,8,6,1\n", 1, "one of tp_s/tz_s"),
    ("hs_m,tp_s,probability\n1,8\n", 2, "expected 3 values"),
    ("hs_m,tp_s,probability\n1,8,0.5\n-1,9,0.5\n", 3, "Hs (m) > 0"),
    ("hs_m,tp_s,probability\n1,0,0.5\n", 2, "a period (s) > 0"),
    ("hs_m,tp_s,probability\n1,8,nan\n", 2, "a weight >= 0"),
    ("hs_m,tp_s,probability\n1,8,abc\n", 2, "a weight >= 0"),
    ("hs_m,tp_s,probability\n1,8,0.5\n# note\n1,8,0.5\n", 4, "already on line 2"),
    ("hs_m,tp_s,count\n1,8,0\n", 1, "sums to 0"),
    ("# only comments\n", None, "no header"),
])
def test_a_damaged_scatter_is_refused_on_its_line(tmp_path, text, line, words):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(FileFormatError) as error:
        read_scatter(path)
    assert error.value.line == line and words in str(error.value) and str(path) in str(error.value)


def test_a_table_beyond_the_cell_limit_is_refused_before_it_is_read(tmp_path):
    path = tmp_path / "huge.csv"
    path.write_text("hs_m,tp_s,count\n" + "".join(f"{1 + i // 200},{1 + i % 200},1\n" for i in range(10_001)))
    with pytest.raises(FileFormatError, match="more than 10000 cells"):
        read_scatter(path)
