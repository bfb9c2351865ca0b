"""Criteria evaluated over a motion record as it grows: what the viewer shows live, what
``marinesim assess`` reports afterwards, and what an event's condition watches (one code path).

The record arrives in blocks of rows on the run's time grid (:meth:`Monitor.append`). Every
:data:`EVALUATE_S` of record (:attr:`Monitor.stride` rows) each criterion's quantity is computed
over its window, the last ``window_s`` seconds (:meth:`Monitor.evaluate`); doses accumulate from
the start. A windowed value counts once the window holds :data:`SETTLE_FRACTION` of ``window_s``
(or the whole run, if shorter): before that it is *settling* (``None``), as a monitoring system's
display is until it has enough record. A value above ``caution x limit`` is a caution, above the
limit an exceedance; every evaluation interval spent above the limit adds to its time exceeded.
"""

from __future__ import annotations

import enum
import math
import operator
import re
from dataclasses import dataclass, field

import numpy as np

from marinesim.criteria.interruptions import deck_specific_force
from marinesim.criteria.quantities import LATERAL, NORMAL, QUANTITIES, Measure, Options
from marinesim.errors import ParameterError

EVALUATE_S = 1.0
"""Record time between two evaluations of the criteria (s)."""
SETTLE_FRACTION = 0.25
"""Share of its window a windowed criterion needs before its value counts."""
MAX_WINDOW_ROWS = 2_000_000
"""The longest window in rows (16 MB per series): window_s / dt is bounded before anything is kept."""
CAUTION = 0.8
"""Fraction of the limit that raises a caution unless a criterion says otherwise."""


class Level(enum.StrEnum):
    """A criterion's level, in order: no value yet (its window still filling), within its limit, at or above the
    caution line, above the limit. Its value is the word the outputs write (JSON, tables, the HUD); ``<`` and
    ``max`` go by the order, never by the words."""

    SETTLING = "settling"
    OK = "ok"
    CAUTION = "caution"
    EXCEEDED = "exceeded"

    @property
    def rank(self) -> int:
        """Its place in the order: 0 settling ... 3 exceeded."""
        return list(Level).index(self)

    def _other(self, other: object) -> int:
        if not isinstance(other, Level):
            raise TypeError(f"a level compares with a level, not {other!r}")
        return other.rank

    def __lt__(self, other: object) -> bool:
        return self.rank < self._other(other)

    def __le__(self, other: object) -> bool:
        return self.rank <= self._other(other)

    def __gt__(self, other: object) -> bool:
        return self.rank > self._other(other)

    def __ge__(self, other: object) -> bool:
        return self.rank >= self._other(other)


@dataclass(frozen=True)
class Criterion:
    """``quantity`` (a :data:`QUANTITIES` name) at ``point`` (None: the vessel's DOFs) against ``limit``
    (in the quantity's unit; None: watched only, for an event's condition) over ``window_s`` (s; None:
    the quantity's default)."""

    quantity: str
    limit: float | None = None
    point: str | None = None
    name: str | None = None
    window_s: float | None = None
    caution: float = CAUTION
    options: Options = Options()

    @property
    def measure(self) -> Measure:
        return QUANTITIES[self.quantity]

    @property
    def label(self) -> str:
        """The criterion's name: as given, else ``point.quantity`` or ``quantity``."""
        return self.name or default_name(self.quantity, self.point)

    @property
    def window(self) -> float | None:
        """The running window (s); None for a dose, which runs over the whole record."""
        return None if self.measure.dose else (self.window_s or self.measure.window_s)

    def level(self, value: float | None) -> Level:
        """The level of ``value`` (in the quantity's unit; None: settling)."""
        if value is None:
            return Level.SETTLING
        if self.limit is None or value < self.caution * self.limit:
            return Level.OK
        return Level.EXCEEDED if value > self.limit else Level.CAUTION


def value_and_limit(value: float, limit: float) -> tuple[str, str]:
    """``value`` and ``limit`` (in the criterion's unit) as text with the same significant digits: the fewest, 3
    to 6, that tell them apart where they differ, so that a value just above its limit never reads as the limit
    (4.004 against 4 reads 4.004, not 4)."""
    for digits in range(3, 7):
        shown = f"{value:.{digits}g}", f"{limit:.{digits}g}"
        if shown[0] != shown[1] or value == limit:
            break
    return shown


def default_name(quantity: str, point: str | None) -> str:
    return quantity if point is None else f"{point}.{quantity}"


_COMPARISONS = {">=": operator.ge, "<=": operator.le, ">": operator.gt, "<": operator.lt}
_CONDITION = re.compile(r"^\s*(?P<subject>.+?)\s*(?P<op>>=|<=|>|<)\s*(?P<number>[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)\s*$")


@dataclass(frozen=True)
class Condition:
    """``subject op number``: a criterion's name, or ``[point.]quantity``, compared with a number."""

    subject: str
    op: str
    number: float

    def holds(self, value: float | None) -> bool:
        return value is not None and _COMPARISONS[self.op](value, self.number)

    def __str__(self) -> str:
        return f"{self.subject} {self.op} {self.number:g}"


def parse_condition(text: str) -> Condition:
    """``"bridge.vertical_acc_rms_m_s2 > 1.0"`` as a :class:`Condition`; ParameterError if it is not one."""
    match = _CONDITION.match(text)
    if match is None:
        raise ParameterError(f"expected '<criterion or [point.]quantity> <op> <number>' with op one of "
                             f"{', '.join(_COMPARISONS)}, got {text!r}")
    return Condition(match["subject"], match["op"], float(match["number"]))


def watched(condition: Condition, criteria: list[Criterion], points: dict) -> Criterion:
    """The criterion ``condition`` watches: one of ``criteria`` by name, else its ``[point.]quantity``
    with the quantity's default window; ParameterError naming what is unknown."""
    for criterion in criteria:
        if criterion.label == condition.subject:
            return criterion
    point, _, quantity = condition.subject.rpartition(".")
    point = point or None
    if quantity not in QUANTITIES:
        raise ParameterError(f"{condition.subject!r} is neither a criterion ({', '.join(c.label for c in criteria) or 'none'})"
                             f" nor a quantity (known: {', '.join(QUANTITIES)})")
    check_point(quantity, point, points)
    if "threshold_m" in QUANTITIES[quantity].options:
        raise ParameterError(f"{quantity} needs a threshold_m: name a [[criteria]] entry that gives it")
    return Criterion(quantity, point=point)


def check_point(quantity: str, point: str | None, points: dict) -> None:
    """Refuse a point a quantity does not take, or that ``points`` does not name."""
    if QUANTITIES[quantity].at_point:
        if point is None:
            raise ParameterError(f"{quantity} is measured at a point: give one of the vessel's points "
                                 f"({', '.join(points) or 'none defined in [vessel.points]'})")
        if point not in points:
            raise ParameterError(f"unknown point {point!r} (known: {', '.join(points) or 'none'})")
    elif point is not None:
        raise ParameterError(f"{quantity} is a motion of the whole vessel: it takes no point")


@dataclass
class Tally:
    """A criterion over the record so far: its latest and worst values (with the time of the worst),
    the time spent above its limit, and when it first went above."""

    value: float | None = None
    worst: float | None = None
    worst_s: float | None = None
    time_exceeded_s: float = 0.0
    first_exceeded_s: float | None = None


class _History:
    """The last ``capacity`` samples of one series, kept contiguous (amortised O(1) appends)."""

    def __init__(self, capacity: int) -> None:
        self.capacity = capacity
        self._data = np.empty(2 * capacity)
        self._end = 0

    def extend(self, x: np.ndarray) -> None:
        x = x[-self.capacity:]
        if self._end + x.size > self._data.size:
            keep = min(self.capacity - x.size, self._end)
            self._data[:keep] = self._data[self._end - keep:self._end]
            self._end = keep
        self._data[self._end:self._end + x.size] = x
        self._end += x.size

    def last(self, n: int) -> np.ndarray:
        return self._data[max(self._end - n, 0):self._end]


@dataclass
class Monitor:
    """``criteria`` over the record of a vessel with ``points`` (name -> body-frame offset, m) sampled
    every ``dt`` s, for a run of ``duration_s`` s."""

    criteria: list[Criterion]
    points: dict[str, tuple[float, float, float]]
    dt: float
    duration_s: float
    tallies: list[Tally] = field(init=False)

    def __post_init__(self) -> None:
        self.stride = max(1, round(EVALUATE_S / self.dt))
        self.rows = 0
        self.time: float | None = None
        self._last_evaluation: float | None = None
        self.tallies = [Tally() for _ in self.criteria]
        rows: dict[str, int] = {}
        for criterion in self.criteria:
            check_point(criterion.quantity, criterion.point, self.points)
            if criterion.window is not None:
                n = self.window_rows(criterion)
                if n > MAX_WINDOW_ROWS:
                    raise ParameterError(f"criterion {criterion.label!r}: a {criterion.window:g} s window at dt "
                                         f"{self.dt:g} s is {n} rows, more than {MAX_WINDOW_ROWS}")
                for name in criterion.measure.columns(criterion.point):
                    rows[name] = max(rows.get(name, 0), n)
        self._histories = {name: _History(n) for name, n in rows.items()}
        self._doses = {i: c.measure.dose(self.dt) for i, c in enumerate(self.criteria) if c.measure.dose}
        dosed = (self.criteria[i] for i in self._doses)
        self._needed = frozenset(self._histories).union(*(c.measure.columns(c.point) for c in dosed))

    @property
    def columns(self) -> frozenset[str]:
        """The record's columns the criteria read (a point's deck-frame forces, derived from the motions' columns,
        named as :data:`LATERAL` and :data:`NORMAL` say)."""
        return self._needed

    def window_rows(self, criterion: Criterion) -> int:
        return max(1, round(criterion.window / self.dt))

    def append(self, block: dict[str, np.ndarray]) -> None:
        """Rows of the record (motion columns, as :meth:`Response.frame` gives them), in time order."""
        series = self._series(block)
        for name, history in self._histories.items():
            history.extend(series[name])
        for i, dose in self._doses.items():
            criterion = self.criteria[i]
            dose.feed([series[name] for name in criterion.measure.columns(criterion.point)])
        self.rows += block["time_s"].size
        self.time = float(block["time_s"][-1])

    def due(self, row: int) -> bool:
        """Whether the criteria are evaluated at grid row ``row``."""
        return row % self.stride == 0

    def evaluate(self) -> list[float | None]:
        """Every criterion's value over its window ending at the last row appended (None: settling);
        the tallies take it in."""
        interval = self.time - (self._last_evaluation if self._last_evaluation is not None else self.time)
        self._last_evaluation = self.time
        values = []
        for i, (criterion, tally) in enumerate(zip(self.criteria, self.tallies)):
            value = self._doses[i].value() if i in self._doses else self.windowed(criterion)
            tally.value = value
            if value is not None:
                if tally.worst is None or value > tally.worst:
                    tally.worst, tally.worst_s = value, self.time
                if criterion.limit is not None and value > criterion.limit:
                    tally.time_exceeded_s += interval
                    if tally.first_exceeded_s is None:
                        tally.first_exceeded_s = self.time
            values.append(value)
        return values

    def windowed(self, criterion: Criterion) -> float | None:
        """``criterion``'s value over its window ending at the last row appended (None: settling); the
        tallies are not touched."""
        n = min(self.rows, self.window_rows(criterion))
        settle_s = min(SETTLE_FRACTION * criterion.window, self.duration_s)
        if n * self.dt < settle_s - 1e-9 * self.dt:
            return None
        columns = criterion.measure.columns(criterion.point)
        value = criterion.measure.value([self._histories[name].last(n) for name in columns], self.dt,
                                        criterion.options)
        return None if not math.isfinite(value) else float(value)

    def _series(self, block: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
        """The block's columns and the derived deck-frame forces of the points that need them."""
        needed = self._needed
        series = {name: block[name] for name in needed if name in block}
        for point, offset in self.points.items():
            lateral, normal = LATERAL.format(p=point), NORMAL.format(p=point)
            if lateral in needed or normal in needed:
                series[lateral], series[normal] = deck_specific_force(
                    np.column_stack([block[f"{d}_deg"] for d in ("roll", "pitch", "yaw")]),
                    np.column_stack([block[f"{d}_vel_deg_s"] for d in ("roll", "pitch", "yaw")]),
                    np.column_stack([block[f"{d}_acc_deg_s2"] for d in ("roll", "pitch", "yaw")]),
                    np.column_stack([block[f"{d}_acc_m_s2"] for d in ("surge", "sway", "heave")]),
                    np.asarray(offset, float))
        return series

