"""Wave scatter diagrams: how often each sea state (Hs, period) occurs at a site.

A scatter file is CSV with ``#`` comment lines (the source goes there) and a header naming the columns:

- ``hs_m``: significant wave height of the cell (m);
- ``tp_s`` (spectral peak period) or ``tz_s`` (mean zero-up-crossing period, as most published tables give
  it), s; a Tz table is turned into Tp by the study with the scenario's spectrum shape;
- ``probability`` or ``count`` (occurrences): normalised to sum to 1 when read.

The shipped diagrams (``configs/scatter/``) are the joint (Hs, T) models of :data:`JOINT_MODELS`
integrated over their cells by :func:`discretise`; ``tests/test_study_scatter.py`` rebuilds them.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import stats

from marinesim.constants import G
from marinesim.errors import FileFormatError
from marinesim.sea.kinds import BREAKING_STEEPNESS, MAX_HS_M, PERIOD_RANGE_S
from marinesim.tokens import read_text

MAX_CELLS = 10_000
"""The most cells a scatter diagram may have (a 100 x 100 table)."""
PERIODS = {"tp_s": "tp", "tz_s": "tz"}
"""Period column -> the period it is."""
WEIGHTS = ("probability", "count")
REAL_SEA = ((0.0, MAX_HS_M, "m"), (*PERIOD_RANGE_S, "s"))
"""The Hs and the period (either kind) of a real sea state: (low, high, unit)."""


@dataclass(frozen=True)
class Scatter:
    """Sea states ``hs`` (n,) m and ``period`` (n,) s (``period_kind`` 'tp' or 'tz') with their
    ``probability`` (n,), summing to 1; ``source`` names the file."""

    hs: np.ndarray
    period: np.ndarray
    probability: np.ndarray
    period_kind: str
    source: str = ""


def read_scatter(path: Path) -> Scatter:
    """Read a scatter CSV (see the module docstring); any flaw is a :class:`FileFormatError` naming the line."""
    path = Path(path)
    text = read_text(path)
    rows = [(number, line) for number, line in enumerate(text.splitlines(), 1)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise FileFormatError(path, None, "no header: expected columns hs_m, tp_s or tz_s, probability or count")
    header_line, header = rows[0][0], [name.strip() for name in next(csv.reader([rows[0][1]]))]
    period_names = [name for name in header if name in PERIODS]
    weight_names = [name for name in header if name in WEIGHTS]
    if "hs_m" not in header or len(period_names) != 1 or len(weight_names) != 1 or len(set(header)) != len(header):
        raise FileFormatError(path, header_line, f"expected the columns hs_m, one of tp_s/tz_s and one of "
                                                 f"probability/count, got {', '.join(header)}")
    if len(rows) - 1 > MAX_CELLS:
        raise FileFormatError(path, rows[MAX_CELLS + 1][0], f"more than {MAX_CELLS} cells")
    columns = [header.index(name) for name in ("hs_m", period_names[0], weight_names[0])]
    values = np.empty((len(rows) - 1, 3))
    seen: dict[tuple[float, float], int] = {}
    for i, (number, line) in enumerate(rows[1:]):
        cells = next(csv.reader(io.StringIO(line)))
        if len(cells) != len(header):
            raise FileFormatError(path, number, f"expected {len(header)} values, got {len(cells)}")
        for j, (column, what) in enumerate(zip(columns, ("Hs (m) > 0", "a period (s) > 0", "a weight >= 0"))):
            try:
                value = float(cells[column])
            except ValueError:
                raise FileFormatError(path, number, f"expected {what}, got {cells[column].strip()!r}") from None
            if not math.isfinite(value) or value < 0 or (j < 2 and value == 0):
                raise FileFormatError(path, number, f"expected {what}, got {cells[column].strip()!r}")
            if j < 2 and not (REAL_SEA[j][0] <= value <= REAL_SEA[j][1]):
                low, high, unit = REAL_SEA[j]
                raise FileFormatError(path, number, f"{header[column]} {value:g} is outside a real sea's "
                                                    f"{low:g}..{high:g} {unit} (is the table in other units?)")
            values[i, j] = value
        cell = (values[i, 0], values[i, 1])
        if cell in seen:
            raise FileFormatError(path, number, f"the cell Hs {cell[0]:g} m, {period_names[0]} {cell[1]:g} s "
                                                f"is already on line {seen[cell]}")
        seen[cell] = number
    total = values[:, 2].sum()
    if not total > 0:
        raise FileFormatError(path, header_line, f"the {weight_names[0]} column sums to 0: no sea state occurs")
    return Scatter(values[:, 0], values[:, 1], values[:, 2] / total, PERIODS[period_names[0]], str(path))


def steepness(hs: np.ndarray | float, tp: np.ndarray | float) -> np.ndarray | float:
    """Hs / Lp of sea states (m, s), Lp = g Tp^2 / (2 pi) the deep-water length of the peak."""
    return hs / (G * np.square(tp) / (2.0 * math.pi))


@dataclass(frozen=True)
class JointModel:
    """A joint long-term model of Hs and a period T: Hs with a three-parameter Weibull distribution
    (scale ``alpha`` m, shape ``beta``, location ``gamma`` m) or, below ``lognormal_below`` m, a lognormal
    one (``lognormal`` = mean and standard deviation of ln Hs: the hybrid model); ln T given Hs normal
    with mean ``a0 + a1 Hs^a2`` and standard deviation ``b0 + b1 exp(b2 Hs)``, or, with ``variance``,
    the square root of that sum. ``period`` names T ('tp' or 'tz')."""

    name: str
    source: str
    period: str
    alpha: float
    beta: float
    gamma: float
    a: tuple[float, float, float]
    b: tuple[float, float, float]
    lognormal: tuple[float, float] | None = None
    lognormal_below: float = 0.0
    variance: bool = False

    def hs_cdf(self, hs: np.ndarray) -> np.ndarray:
        """P(Hs <= hs)."""
        weibull = stats.weibull_min.cdf(hs, self.beta, loc=self.gamma, scale=self.alpha)
        if self.lognormal is None:
            return weibull
        mu, sigma = self.lognormal
        return np.where(hs <= self.lognormal_below, stats.lognorm.cdf(hs, sigma, scale=math.exp(mu)),
                        stats.lognorm.cdf(self.lognormal_below, sigma, scale=math.exp(mu))
                        + weibull - stats.weibull_min.cdf(self.lognormal_below, self.beta, loc=self.gamma,
                                                          scale=self.alpha))

    def period_cdf(self, period: np.ndarray, hs: np.ndarray) -> np.ndarray:
        """P(T <= period | Hs = hs)."""
        a0, a1, a2 = self.a
        b0, b1, b2 = self.b
        mu = a0 + a1 * hs ** a2
        spread = b0 + b1 * np.exp(b2 * hs)
        sigma = np.sqrt(spread) if self.variance else spread
        return stats.norm.cdf((np.log(period) - mu) / sigma)


JOINT_MODELS = {
    "north_atlantic": JointModel(
        "North Atlantic", "DNV-RP-C205 (2010, 2021) section 3.6.3, joint model for the North Atlantic "
        "(the sea of DNV's Table C-2 scatter diagram, Global Wave Statistics areas 8, 9, 15, 16)",
        "tz", 3.041, 1.484, 0.661, (0.70, 1.27, 0.131), (0.1334, 0.0264, -0.3869)),
    "world_wide": JointModel(
        "World wide trade", "DNV-RP-C205 (2010, 2021) section 3.6.3, joint model for world wide operation",
        "tz", 1.798, 1.214, 0.856, (-1.010, 2.847, 0.075), (0.161, 0.146, -0.683)),
    "northern_north_sea": JointModel(
        "Northern North Sea", "Li, Gao & Moan (2013), Joint environmental data at five European offshore sites, "
        "OMAE2013-10156: site 'Norway 5' (northern North Sea), hybrid lognormal-Weibull Hs",
        "tp", 2.547, 1.433, 0.0, (1.886, 0.365, 0.312), (0.001, 0.105, -0.264), lognormal=(0.871, 0.506),
        lognormal_below=5.0, variance=True),
}
"""The joint models the shipped scatter diagrams are made from, with their published parameters."""


def discretise(model: JointModel, hs_edges: np.ndarray, period_edges: np.ndarray, substeps: int = 20) -> np.ndarray:
    """P(cell) (len(hs_edges) - 1, len(period_edges) - 1) of ``model`` over the cells' edges (m, s): the
    conditional period probabilities integrated over each Hs bin (``substeps`` midpoints)."""
    hs_edges, period_edges = np.asarray(hs_edges, float), np.asarray(period_edges, float)
    out = np.empty((hs_edges.size - 1, period_edges.size - 1))
    for i, (lo, hi) in enumerate(zip(hs_edges[:-1], hs_edges[1:])):
        inner = np.linspace(lo, hi, substeps + 1)
        weight = np.diff(model.hs_cdf(inner))                                          # (substeps,)
        mid = 0.5 * (inner[:-1] + inner[1:])
        period = np.diff(model.period_cdf(period_edges[None, :], mid[:, None]), axis=1)  # (substeps, cells)
        out[i] = weight @ period
    return out


def scatter_csv(key: str, hs_edges: np.ndarray, period_edges: np.ndarray) -> str:
    """The scatter file of :data:`JOINT_MODELS` [``key``] over the given cell edges (m, s): cells at the
    edges' midpoints, probabilities normalised over the table and written to 6 decimals (cells that round
    to 0, and of a Tp table those steeper than breaking, left out), the source in the comment lines."""
    model = JOINT_MODELS[key]
    probability = discretise(model, hs_edges, period_edges)
    covered = probability.sum()
    probability = probability / covered
    hs = 0.5 * (np.asarray(hs_edges[:-1]) + np.asarray(hs_edges[1:]))
    period = 0.5 * (np.asarray(period_edges[:-1]) + np.asarray(period_edges[1:]))
    column = f"{model.period}_s"
    lines = [f"# {model.name}: wave scatter diagram of Hs and {model.period.capitalize()}",
             f"# from the joint model of {model.source}",
             f"# integrated over cells of {np.diff(hs_edges)[0]:g} m x {np.diff(period_edges)[0]:g} s by "
             f"marinesim.study.scatter.discretise; the table holds {covered:.2%} of the model's probability",
             f"hs_m,{column},probability"]
    lines += [f"{h:g},{t:g},{p:.6f}" for (i, h) in enumerate(hs) for (j, t) in enumerate(period)
              if (p := probability[i, j]) >= 5e-7 and (model.period != "tp" or steepness(h, t) <= BREAKING_STEEPNESS)]
    return "\n".join(lines) + "\n"
