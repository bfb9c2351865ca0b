"""Alpha factors for weather-restricted marine operations (DNV-OS-H101 4 B, DNV-ST-N001 4.3).

An operation planned on a weather forecast may start only when the forecast stays below
``OP_WF = alpha x OP_LIM``, its operational limit reduced for the forecast's uncertainty. Alpha grows with
the design Hs (the operational limit itself) and falls with the reference period
``T_R = T_POP + T_C`` (planned operation time plus contingency). A table gives it: rows of reference
periods (a row holds up to its hours), columns of design Hs (linear between them, the end columns'
values beyond them). ``configs/alpha/dnv_base_case.csv`` is the standard's base case.

A table file is CSV with ``#`` comment lines (the source goes there) and the header
``reference_period_h, hs_<H>_m, ...`` with increasing periods and heights, alpha in (0, 1].
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
    """``alpha`` (R, K) for reference periods up to ``periods_h`` (R,) h and design Hs ``hs_m`` (K,) m."""

    periods_h: np.ndarray
    hs_m: np.ndarray
    alpha: np.ndarray
    source: str = ""

    def factor(self, reference_period_h: float, design_hs: np.ndarray) -> np.ndarray:
        """Alpha for ``reference_period_h`` at each design Hs of ``design_hs`` (any shape, m; inf allowed).
        ParameterError beyond the table's longest period: such an operation is not weather-restricted."""
        if not reference_period_h > 0 or reference_period_h > self.periods_h[-1]:
            raise ParameterError(f"--reference-period-h must be in (0, {self.periods_h[-1]:g}] h (the alpha table "
                                 f"{self.source} ends there; a longer operation is designed for the season's "
                                 f"extremes, not a forecast), got {reference_period_h!r}")
        row = self.alpha[int(np.searchsorted(self.periods_h, reference_period_h))]
        hs = np.asarray(design_hs, float)
        return np.interp(np.where(np.isfinite(hs), hs, self.hs_m[-1]), self.hs_m, row)

    def forecast_limit(self, reference_period_h: float, design_hs: np.ndarray) -> np.ndarray:
        """``alpha x design_hs``, the highest forecast Hs at which the operation may start (m)."""
        hs = np.asarray(design_hs, float)
        return self.factor(reference_period_h, hs) * hs


def read_alpha_table(path: Path) -> AlphaTable:
    """Read an alpha table CSV (see the module docstring); any flaw is a FileFormatError naming the line."""
    path = Path(path)
    rows = [(number, line) for number, line in enumerate(read_text(path).splitlines(), 1)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise FileFormatError(path, None, "no header: expected reference_period_h, hs_<H>_m, ...")
    header_line, header = rows[0][0], [name.strip() for name in next(csv.reader([rows[0][1]]))]
    matches = [COLUMN.fullmatch(name) for name in header[1:]]
    if header[0] != "reference_period_h" or not matches or not all(matches) or len(header) > MAX_ENTRIES:
        raise FileFormatError(path, header_line, f"expected the columns reference_period_h, hs_<H>_m, ... "
                                                 f"(at most {MAX_ENTRIES}), got {', '.join(header)}")
    hs = np.array([float(m.group(1)) for m in matches])
    if not (np.diff(hs) > 0).all() or not hs[0] > 0:
        raise FileFormatError(path, header_line, "the hs_<H>_m columns must be > 0 and increasing")
    if len(rows) - 1 > MAX_ENTRIES or len(rows) < 2:
        raise FileFormatError(path, header_line, f"expected 1 to {MAX_ENTRIES} rows of reference periods")
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
                what = "a reference period (h) > 0" if j == 0 else "an alpha factor in (0, 1]"
                raise FileFormatError(path, number, f"expected {what} in column {header[j]}, got {cell.strip()!r}")
            values[i, j] = value
        if i and not values[i, 0] > values[i - 1, 0]:
            raise FileFormatError(path, number, "reference periods must increase down the table")
    return AlphaTable(values[:, 0], hs, values[:, 1:], str(path))
