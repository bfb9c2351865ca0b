"""Alpha tables (marinesim/study/alpha.py): the shipped DNV base case reads as the standard prints it, is
interpolated as the standard allows, and a flawed table is refused naming its line."""

from __future__ import annotations

import re

import numpy as np
import pytest

from marinesim.errors import FileFormatError, ParameterError
from marinesim.study.alpha import default_table, read_alpha_table


def test_the_shipped_base_case_rises_with_hs_and_falls_with_the_reference_period():
    """What makes a table an alpha table: a longer forecast is less certain (alpha falls down each column), a
    higher design sea is forecast relatively better (alpha rises along each row), and alpha < 1."""
    table = read_alpha_table(default_table())
    assert table.periods_h.tolist() == [12, 24, 36, 48, 72] and table.hs_m.tolist() == [1, 2, 4, 6, 8]
    assert (np.diff(table.alpha, axis=0) <= 0).all() and (np.diff(table.alpha, axis=1) >= 0).all()
    assert table.alpha.max() < 1.0
    # T_R 30 h uses the 36 h row; Hs 5 m halfway between 0.73 (4 m) and 0.76 (6 m); beyond the columns the
    # end values; a design Hs of inf (a criterion that never limits) stays inf
    np.testing.assert_allclose(table.factor(30.0, np.array([5.0, 0.5, 12.0])), [0.745, 0.62, 0.77])
    assert np.isinf(table.forecast_limit(30.0, np.array([np.inf]))).all()


def test_a_reference_period_beyond_the_table_is_refused():
    with pytest.raises(ParameterError, match="ends there"):
        read_alpha_table(default_table()).factor(73.0, np.array([2.0]))


@pytest.mark.parametrize("text,line,words", [
    ("reference_period_h,hs_2_m,hs_1_m\n12,0.7,0.6\n", 1, "increasing"),
    ("period,hs_1_m\n12,0.7\n", 1, "reference_period_h"),
    ("reference_period_h,hs_1_m\n12,1.2\n", 2, "(0, 1]"),
    ("# c\nreference_period_h,hs_1_m\n24,0.7\n12,0.8\n", 4, "increase"),
    ("reference_period_h,hs_1_m\n12,nan\n", 2, "alpha factor"),
    ("reference_period_h,hs_1_m\n12\n", 2, "expected 2 values"),
])
def test_a_flawed_table_is_refused_naming_the_line(tmp_path, text, line, words):
    path = tmp_path / "alpha.csv"
    path.write_text(text)
    with pytest.raises(FileFormatError, match=re.escape(words)) as error:
        read_alpha_table(path)
    assert f"alpha.csv, line {line}:" in str(error.value), str(error.value)
