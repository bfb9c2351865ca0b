"""Alpha factors for weather-restricted marine operations (DNV-OS-H101 (October 2011) Table 4-1, the base case
of DNV-ST-N001 (2016) Table 2-1).

An operation planned on a weather forecast may start only when the forecast stays below
``OP_WF = alpha x OP_LIM``, its operational limit reduced for the forecast's uncertainty. Alpha grows with
the design Hs (the operational limit itself) and falls with the planned operation period ``T_POP`` (h; the
forecast must cover the reference period ``T_R = T_POP + T_C`` with contingency, but the standard's rows are
``T_POP``). A table gives it: rows of planned periods (a row holds up to its hours; a longer operation is not
weather-restricted), columns of design Hs (linear between them, the end columns' values beyond them: the
standard's last column, 6 m, holds for Hs >= 6 m). ``configs/alpha/dnv_base_case.csv`` is the standard's base
case.

A table file is CSV with ``#`` comment lines (the source goes there) and the header
``planned_period_h, hs_<H>_m, ...`` with increasing periods and heights, alpha in (0, 1].
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError, ParameterError
from marinesim.resources import resource_dir
from marinesim.tokens import read_text

MAX_ENTRIES = 1000
"""The most rows or columns an alpha table may have."""
COLUMN = re.compile(r"hs_(\d+(?:\.\d+)?)_m")


def default_table() -> Path:
    """The shipped base-case table of DNV-OS-H101 / DNV-ST-N001."""
    return resource_dir("configs") / "alpha" / "dnv_base_case.csv"


@dataclass(frozen=True)
class AlphaTable:
    """``alpha`` (R, K) for planned periods T_POP up to ``periods_h`` (R,) h and design Hs ``hs_m`` (K,) m."""

    periods_h: np.ndarray
    hs_m: np.ndarray
    alpha: np.ndarray
    source: str = ""

    def factor(self, planned_period_h: float, design_hs: np.ndarray) -> np.ndarray:
        """Alpha for the planned operation period ``planned_period_h`` (T_POP, h; the first row holding it) at
        each design Hs of ``design_hs`` (any shape, m; inf allowed). ParameterError beyond the table's longest
        period: such an operation is not weather-restricted."""
        if not planned_period_h > 0 or planned_period_h > self.periods_h[-1]:
            raise ParameterError(f"--planned-period-h (T_POP) must be in (0, {self.periods_h[-1]:g}] h (the alpha "
                                 f"table {self.source} ends there; a longer operation is not weather-restricted "
                                 f"and is designed for the season's extremes), got {planned_period_h!r}")
        row = self.alpha[int(np.searchsorted(self.periods_h, planned_period_h))]
        hs = np.asarray(design_hs, float)
        return np.interp(np.where(np.isfinite(hs), hs, self.hs_m[-1]), self.hs_m, row)

    def forecast_limit(self, planned_period_h: float, design_hs: np.ndarray) -> np.ndarray:
        """``alpha x design_hs``, the highest forecast Hs at which the operation may start (m)."""
        hs = np.asarray(design_hs, float)
        return self.factor(planned_period_h, hs) * hs


def read_alpha_table(path: Path) -> AlphaTable:
    """Read an alpha table CSV (see the module docstring); any flaw is a FileFormatError naming the line."""
    path = Path(path)
    rows = [(number, line) for number, line in enumerate(read_text(path).splitlines(), 1)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise FileFormatError(path, None, "no header: expected planned_period_h, hs_<H>_m, ...")
    header_line, header = rows[0][0], [name.strip() for name in next(csv.reader([rows[0][1]]))]
    matches = [COLUMN.fullmatch(name) for name in header[1:]]
    if header[0] != "planned_period_h" or not matches or not all(matches) or len(header) > MAX_ENTRIES:
        raise FileFormatError(path, header_line, f"expected the columns planned_period_h, hs_<H>_m, ... "
                                                 f"(at most {MAX_ENTRIES}), got {', '.join(header)}")
    hs = np.array([float(m.group(1)) for m in matches])
    if not (np.diff(hs) > 0).all() or not hs[0] > 0:
        raise FileFormatError(path, header_line, "the hs_<H>_m columns must be > 0 and increasing")
    if len(rows) - 1 > MAX_ENTRIES or len(rows) < 2:
        raise FileFormatError(path, header_line, f"expected 1 to {MAX_ENTRIES} rows of planned periods")
    values = np.empty((len(rows) - 1, len(header)))
    for i, (number, line) in enumerate(rows[1:]):
        cells = next(csv.reader(io.StringIO(line)))
        if len(cells) != len(header):
            raise FileFormatError(path, number, f"expected {len(header)} values, got {len(cells)}")
        for j, cell in enumerate(cells):
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            ok = value > 0 if j == 0 else 0 < value <= 1
            if not (math.isfinite(value) and ok):
                what = "a planned period T_POP (h) > 0" if j == 0 else "an alpha factor in (0, 1]"
                raise FileFormatError(path, number, f"expected {what} in column {header[j]}, got {cell.strip()!r}")
            values[i, j] = value
        if i and not values[i, 0] > values[i - 1, 0]:
            raise FileFormatError(path, number, "planned periods must increase down the table")
    return AlphaTable(values[:, 0], hs, values[:, 1:], str(path))
