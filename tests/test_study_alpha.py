"""Alpha tables (marinesim/study/alpha.py): the shipped DNV base case reads as the standard prints it, is
interpolated as the standard allows, and a flawed table is refused naming its line."""

from __future__ import annotations

import re

import numpy as np
import pytest

from marinesim.errors import FileFormatError, ParameterError
from marinesim.study.alpha import default_table, read_alpha_table


PUBLISHED = [[0.65, 0.76, 0.79, 0.80], [0.63, 0.73, 0.76, 0.78], [0.62, 0.71, 0.73, 0.76],
             [0.60, 0.68, 0.71, 0.74], [0.55, 0.63, 0.68, 0.72]]
"""DNV-OS-H101 (October 2011) Table 4-1, base case (DNV-ST-N001 (2016) Table 2-1): rows T_POP <= 12, 24, 36, 48,
72 h, columns design Hs 1, 2, 4, >= 6 m."""


def test_the_shipped_base_case_is_the_published_table():
    """The shipped file must be the standard's table: rows T_POP 12..72 h, columns 1 / 2 / 4 / 6 m and no more
    (a column the standard does not print would invent alphas above 6 m). What makes it an alpha table: a
    longer operation is forecast less certainly (alpha falls down each column), a higher design sea is forecast
    relatively better (alpha rises along each row), and alpha < 1."""
    table = read_alpha_table(default_table())
    assert table.periods_h.tolist() == [12, 24, 36, 48, 72] and table.hs_m.tolist() == [1, 2, 4, 6]
    np.testing.assert_array_equal(table.alpha, PUBLISHED)
    assert (np.diff(table.alpha, axis=0) <= 0).all() and (np.diff(table.alpha, axis=1) >= 0).all()
    assert table.alpha.max() < 1.0


def test_a_design_hs_beyond_6_m_takes_the_6_m_column():
    """The standard's last column holds for Hs >= 6 m: 8 m, 12 m and a criterion that never limits (inf) must
    get the 6 m alpha of their row, not an extrapolation; between columns alpha is linear (5 m at 36 h halfway
    between 0.73 and 0.76), below the first column the 1 m value."""
    table = read_alpha_table(default_table())
    for row, period_h in enumerate([12.0, 24.0, 36.0, 48.0, 72.0]):
        np.testing.assert_array_equal(table.factor(period_h, np.array([6.0, 8.0, 12.0, np.inf])),
                                      np.full(4, PUBLISHED[row][3]), err_msg=f"T_POP {period_h} h")
    np.testing.assert_allclose(table.forecast_limit(24.0, np.array([8.0])), [0.78 * 8.0], rtol=1e-12)
    np.testing.assert_allclose(table.factor(36.0, np.array([5.0, 0.5])), [0.745, 0.62], rtol=1e-12)
    assert np.isinf(table.forecast_limit(36.0, np.array([np.inf]))).all()


@pytest.mark.parametrize("period_h,row", [(0.5, 0), (12.0, 0), (12.5, 1), (20.0, 1), (24.0, 1), (24.01, 2),
                                          (48.0, 3), (60.0, 4), (72.0, 4)])
def test_the_row_is_picked_by_the_planned_period(period_h, row):
    """The standard's rows are T_POP <= 12, 24, 36, 48, 72 h: T_POP 20 h takes the <= 24 h row (0.73 at 2 m),
    and a row holds its own hours. Choosing by T_POP + T_C, or rounding down, would take another row."""
    table = read_alpha_table(default_table())
    np.testing.assert_array_equal(table.factor(period_h, np.array([1.0, 2.0, 4.0, 6.0])), PUBLISHED[row])


@pytest.mark.parametrize("period_h", [72.5, 96.0, 0.0, -1.0, float("nan")])
def test_a_planned_period_outside_the_table_is_refused_naming_the_option(period_h):
    """T_POP > 72 h is not weather-restricted (no alpha applies) and T_POP <= 0 is no operation: one line that
    names the option, not a row picked past the table's end."""
    with pytest.raises(ParameterError, match="--planned-period-h") as error:
        read_alpha_table(default_table()).factor(period_h, np.array([2.0]))
    assert "\n" not in str(error.value) and "(0, 72] h" in str(error.value), str(error.value)


@pytest.mark.parametrize("text,line,words", [
    ("planned_period_h,hs_2_m,hs_1_m\n12,0.7,0.6\n", 1, "increasing"),
    ("period,hs_1_m\n12,0.7\n", 1, "planned_period_h"),
    ("reference_period_h,hs_1_m\n12,0.7\n", 1, "planned_period_h"),
    ("planned_period_h,hs_1_m\n0,0.7\n", 2, "planned period T_POP (h) > 0"),
    ("planned_period_h,hs_1_m\n12,1.2\n", 2, "(0, 1]"),
    ("# c\nplanned_period_h,hs_1_m\n24,0.7\n12,0.8\n", 4, "increase"),
    ("planned_period_h,hs_1_m\n12,nan\n", 2, "alpha factor"),
    ("planned_period_h,hs_1_m\n12\n", 2, "expected 2 values"),
])
def test_a_flawed_table_is_refused_naming_the_line(tmp_path, text, line, words):
    """A user's table with its columns out of order, the wrong first column (a table of T_R = T_POP + T_C rows
    under the old name included), a period <= 0, alpha outside (0, 1] or a short row would give wrong alphas
    silently: each must be one FileFormatError naming the line."""
    path = tmp_path / "alpha.csv"
    path.write_text(text)
    with pytest.raises(FileFormatError, match=re.escape(words)) as error:
        read_alpha_table(path)
    assert f"alpha.csv, line {line}:" in str(error.value), str(error.value)
