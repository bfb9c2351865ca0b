"""A dynamically positioned vessel's thrusters and the allocation of a demanded force over them.

Axes as :mod:`marinesim.manoeuvring.state`: body x forward, y to starboard; a force (Fx, Fy) at (x, y) gives the
yaw moment ``N = x Fy - y Fx`` (positive turning the bow to starboard). Each thruster is one or two *virtual*
forces: a tunnel thruster pushes along y, a main propeller along x (less astern than ahead), an azimuth thruster in
any direction (Fx and Fy, its resultant no more than its rating). The configuration matrix ``B`` (3, m) maps the
virtual forces ``f`` (N) to (X, Y, N).

Allocation (Fossen 2021, ch. 11.3): the least-norm ``f = B^T (B B^T)^-1 tau`` when it is within every thruster's
limits; otherwise the bounded least squares over the limits (:func:`bounded_least_squares`: the last cycle's
bounds tried first, else :func:`scipy.optimize.lsq_linear`'s BVLS), the yaw moment weighted by one over the
vessel's length so that a metre of force and a ship length of moment count alike, and a small penalty on ``f``
keeping the answer unique. An azimuth's box is then pulled in to its circle. A lost thruster has both bounds zero;
a thruster stuck at full thrust (a drive-off) is held there and the others answer the rest.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import lsq_linear

from marinesim.compiled import compiled
from marinesim.errors import ParameterError

KINDS = ("tunnel", "main", "azimuth")
PENALTY = 1e-6
"""Weight of ``|f|^2`` against the residual in the bounded problem (both scaled by the largest rating)."""


@dataclass(frozen=True)
class Thruster:
    """``name``; ``kind`` (:data:`KINDS`); at ``x``, ``y`` (m, body: forward, to starboard); ``max_thrust`` (N);
    ``astern`` the fraction of it a main propeller gives astern; ``time_constant_s`` of its thrust following its
    order (first order)."""

    name: str
    kind: str
    x: float
    y: float
    max_thrust: float
    astern: float = 0.7
    time_constant_s: float = 2.0

    @property
    def width(self) -> int:
        """Its virtual forces: 2 for an azimuth, else 1."""
        return 2 if self.kind == "azimuth" else 1


@dataclass(frozen=True)
class Thrusters:
    """The vessel's thrusters; ``length`` (m) weighs the yaw moment in the allocation."""

    units: tuple[Thruster, ...]
    length: float
    b: np.ndarray = field(init=False, repr=False, compare=False)
    _least: dict = field(init=False, repr=False, compare=False)
    _problems: dict = field(init=False, repr=False, compare=False)
    _bounded: dict = field(init=False, repr=False, compare=False)
    _slices: tuple[slice, ...] = field(init=False, repr=False, compare=False)
    _lag: np.ndarray = field(init=False, repr=False, compare=False)
    _bounds: dict = field(init=False, repr=False, compare=False)
    _all_free: tuple[bool, ...] = field(init=False, repr=False, compare=False)
    _circles: np.ndarray = field(init=False, repr=False, compare=False)
    """Each azimuth's first virtual force and rating (N), (n_azimuths, 2)."""

    def __post_init__(self) -> None:
        if not self.units:
            raise ParameterError("a vessel on DP needs at least one thruster")
        columns = []
        for t in self.units:
            if t.kind not in KINDS:
                raise ParameterError(f"thruster {t.name}: kind {t.kind!r}, expected one of {', '.join(KINDS)}")
            if t.kind in ("main", "azimuth"):
                columns.append((1.0, 0.0, -t.y))
            if t.kind in ("tunnel", "azimuth"):
                columns.append((0.0, 1.0, t.x))
        object.__setattr__(self, "b", np.array(columns, dtype=float).T)
        object.__setattr__(self, "_least", {})
        object.__setattr__(self, "_problems", {})
        object.__setattr__(self, "_bounded", {})  # per set of free forces: the last bounded answer's bounds held
        slices, at = [], 0
        for t in self.units:
            slices.append(slice(at, at + t.width))
            at += t.width
        lag = np.concatenate([[t.time_constant_s] * t.width for t in self.units])
        lag.flags.writeable = False
        object.__setattr__(self, "_slices", tuple(slices))
        object.__setattr__(self, "_lag", lag)
        object.__setattr__(self, "_bounds", {})  # per set of lost thrusters (read-only): the DP asks every cycle
        object.__setattr__(self, "_all_free", (True,) * self.width)
        object.__setattr__(self, "_circles", np.array([(part.start, t.max_thrust) for t, part in zip(self.units, slices)
                                                       if t.kind == "azimuth"], dtype=float).reshape(-1, 2))

    @property
    def width(self) -> int:
        """The number of virtual forces m."""
        return self.b.shape[1]

    def slices(self) -> tuple[slice, ...]:
        """Each thruster's virtual forces in ``f``."""
        return self._slices

    def index(self, name: str) -> int:
        """The thruster named ``name``; :class:`ParameterError` naming those there are."""
        for i, t in enumerate(self.units):
            if t.name == name:
                return i
        raise ParameterError(f"no thruster {name!r}: the vessel has {', '.join(t.name for t in self.units)}")

    def bounds(self, lost: frozenset[str] = frozenset()) -> tuple[np.ndarray, np.ndarray]:
        """(lower, upper) bounds of ``f`` (N, (m,) each, read-only), a lost thruster's zero."""
        key = frozenset(lost)
        if key not in self._bounds:
            lo, hi = [], []
            for t in self.units:
                top = 0.0 if t.name in lost else t.max_thrust
                low = -t.astern * top if t.kind == "main" else -top
                lo += [low] * t.width
                hi += [top] * t.width
            lo, hi = np.array(lo), np.array(hi)
            lo.flags.writeable = hi.flags.writeable = False
            self._bounds[key] = lo, hi
        return self._bounds[key]

    def stuck(self, name: str) -> np.ndarray:
        """The virtual forces (m,) of thruster ``name`` stuck at full thrust along its own axis (a main propeller or
        an azimuth ahead, a tunnel thruster to starboard), the others zero."""
        f = np.zeros(self.width)
        i = self.index(name)
        f[self.slices()[i].start] = self.units[i].max_thrust  # an azimuth's first virtual force is its Fx
        return f

    def allocate(self, tau: np.ndarray, lost: frozenset[str] = frozenset(),
                 fixed: dict[str, np.ndarray] | None = None) -> np.ndarray:
        """The virtual forces ``f`` (N, (m,)) that give ``tau`` (X N, Y N, N N m) as nearly as the thrusters can:
        ``lost`` thrusters give nothing, ``fixed`` ones (name -> their virtual forces) give what they are stuck at."""
        tau = np.asarray(tau, dtype=float)
        lo, hi = self.bounds(lost)
        if not lost and not fixed:  # every thruster free, as a DP asks every cycle: the least-norm answer first
            f = np.empty(self.width)
            if _least_norm_within(self._least_norm(self._all_free), tau, lo, hi, self._circles, f):
                return f
            return self._bounded_answer(self._all_free, np.zeros(self.width), slice(None), tau, lo.copy(), hi.copy())
        free = np.ones(self.width, dtype=bool)
        f = np.zeros(self.width)
        slices = self.slices()
        for name, value in (fixed or {}).items():
            part = slices[self.index(name)]
            f[part], free[part] = value, False
        for name in lost:
            free[slices[self.index(name)]] = False
        rest = tau - self.b @ f
        if not free.any():
            return f
        key = tuple(free)
        lo, hi = lo[free], hi[free]
        least = self._least_norm(key) @ rest
        if np.isfinite(least).all() and (least >= lo - 1e-9).all() and (least <= hi + 1e-9).all() \
                and self._within_circles(f, free, least):
            f[free] = least
            return f
        return self._bounded_answer(key, f, free, rest, lo, hi)

    def _bounded_answer(self, key: tuple[bool, ...], f: np.ndarray, free: np.ndarray | slice, rest: np.ndarray,
                        lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        """``f`` (m,) with its ``free`` forces (``key``: which, as a tuple) the bounded problem's answer to ``rest``
        (X N, Y N, N N m) within their bounds ``lo``, ``hi``, the azimuths then pulled in to their circles."""
        a, scale, top, inverses = self._bounded_problem(key, hi)
        target = np.concatenate([rest * scale / top, np.zeros(a.shape[1])])
        f[free], self._bounded[key] = bounded_least_squares(a, target, lo, np.maximum(hi, lo + 1e-12),
                                                            self._bounded.get(key), inverses)
        return self._onto_circles(f)

    def forget(self) -> None:
        """Forget the bounds the last saturated answers held: a new run's first answers owe nothing to another
        run's."""
        self._bounded.clear()

    def _least_norm(self, free: tuple[bool, ...]) -> np.ndarray:
        """``B^T (B B^T)^-1`` of the ``free`` virtual forces' columns ((k, 3)); NaN where they cannot give every
        (X, Y, N) (rank below 3: the bounded problem decides). Kept per set of free forces."""
        if free not in self._least:
            b = self.b[:, np.array(free)]
            scaled = b * np.array([1.0, 1.0, 1.0 / self.length])[:, None]
            full = np.linalg.matrix_rank(scaled) == 3
            self._least[free] = b.T @ np.linalg.inv(b @ b.T) if full else np.full((b.shape[1], 3), np.nan)
        return self._least[free]

    def _bounded_problem(self, free: tuple[bool, ...], hi: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray, float, dict[bytes, np.ndarray]]:
        """The bounded problem of the ``free`` virtual forces (their upper bounds ``hi``): its matrix ``a``
        ((3 + k, k): the scaled columns over the penalty's rows), the rows' scale (3,), the largest rating (N) both
        are divided by, and the pseudo-inverses of its columns left free by each set of bounds held, as met
        (:func:`bounded_least_squares`). Kept per set of free forces: a free force's bound is its thruster's rating
        (a lost or stuck thruster's forces are not free)."""
        if free not in self._problems:
            b = self.b[:, np.array(free)]
            scale = np.array([1.0, 1.0, 1.0 / self.length])
            top = max(float(np.max(hi)), 1.0)
            a = np.vstack([b * scale[:, None] / top, math.sqrt(PENALTY) * np.eye(b.shape[1]) / top])
            self._problems[free] = a, scale, top, {}
        return self._problems[free]

    def _within_circles(self, f: np.ndarray, free: np.ndarray, values: np.ndarray) -> bool:
        trial = f.copy()
        trial[free] = values
        return _inside_circles(trial, self._circles)

    def _onto_circles(self, f: np.ndarray) -> np.ndarray:
        """``f`` with each azimuth's resultant pulled in to its rating."""
        for t, part in zip(self.units, self.slices()):
            if t.kind == "azimuth":
                size = math.hypot(*f[part])
                if size > t.max_thrust:
                    f[part] *= t.max_thrust / size
        return f

    def use(self, f: np.ndarray) -> np.ndarray:
        """Each thruster's thrust as a fraction of its rating (0..1, (n,)); a lost or stopped one 0."""
        out = []
        for t, part in zip(self.units, self.slices()):
            out.append(math.hypot(*f[part]) / t.max_thrust)
        return np.array(out)

    def lag(self) -> np.ndarray:
        """Each virtual force's time constant (s, (m,), read-only)."""
        return self._lag

    def can_hold(self, tau: np.ndarray, lost: frozenset[str] = frozenset(), tolerance: float = 1e-3) -> bool:
        """Whether the thrusters (less ``lost``) give ``tau`` to within ``tolerance`` of each component's size
        (forces against the largest rating, the moment against it times the vessel's length)."""
        f = self.allocate(tau, lost)
        miss = (self.b @ f - np.asarray(tau, float)) * np.array([1.0, 1.0, 1.0 / self.length])
        top = max(t.max_thrust for t in self.units)
        return bool(np.all(np.abs(miss) <= tolerance * top))


@compiled
def _least_norm_within(least_norm: np.ndarray, tau: np.ndarray, lo: np.ndarray, hi: np.ndarray, circles: np.ndarray,
                       f: np.ndarray) -> bool:
    """:meth:`Thrusters.allocate`'s least-norm answer ``least_norm @ tau`` ((m, 3) @ (3,)) into ``f`` (m,) with every
    thruster free; whether it is the answer: finite, within the bounds ``lo``, ``hi`` (m,) and each azimuth's
    resultant within its rating (:func:`_inside_circles`)."""
    for i in range(f.size):
        f[i] = least_norm[i, 0] * tau[0] + least_norm[i, 1] * tau[1] + least_norm[i, 2] * tau[2]
        if not (math.isfinite(f[i]) and lo[i] - 1e-9 <= f[i] <= hi[i] + 1e-9):
            return False
    return _inside_circles(f, circles)


@compiled
def _inside_circles(f: np.ndarray, circles: np.ndarray) -> bool:
    """Whether each azimuth's resultant in ``f`` (m,) is within its rating (``circles``: (first virtual force,
    rating N) rows), as np.allclose tells ``f`` from the same forces pulled in to their circles."""
    for row in range(circles.shape[0]):
        j, rating = int(circles[row, 0]), circles[row, 1]
        size = math.hypot(f[j], f[j + 1])
        if size > rating:
            for k in (j, j + 1):
                if abs(f[k] * (rating / size) - f[k]) > 1e-8 + 1e-5 * abs(f[k]):
                    return False
    return True


def bounded_least_squares(a: np.ndarray, target: np.ndarray, lower: np.ndarray, upper: np.ndarray,
                          hint: np.ndarray | None = None, inverses: dict[bytes, np.ndarray] | None = None
                          ) -> tuple[np.ndarray, np.ndarray]:
    """``x`` minimising ``|a x - target|^2`` over ``lower <= x <= upper`` (``a`` (k, m) of rank m: one answer), and
    which bounds it holds ((m,): -1 at ``lower``, 1 at ``upper``, 0 between).

    The bounds ``hint`` holds (the last answer's: a DP's demand moves little from one cycle to the next) are tried
    first: the free values solved with them held answer when they meet the optimality conditions (within their
    bounds; the gradient ``g = a^T (a x - target)`` at least 0 at a held lower bound and at most 0 at an upper
    one, so that moving any held value inwards would not help). Else scipy's BVLS finds the bounds (its active
    set), and its free values are solved in the same way, so that the answer's bits follow from its bounds alone,
    not from whether the hint held. The free values are the pseudo-inverse of ``a``'s free columns times what the
    held ones leave of ``target``; ``inverses`` (by the bounds held, for this ``a``) keeps them for the next call."""
    m = a.shape[1]
    if lower.shape != (m,) or upper.shape != (m,) or (hint is not None and np.shape(hint) != (m,)):
        raise ParameterError(f"bounded least squares: {m} unknowns need {m} lower and upper bounds (and held ones)")
    inverses = {} if inverses is None else inverses
    if hint is not None:
        x = _with_bounds_held(a, target, lower, upper, hint, inverses)
        if x is not None:
            return x, hint
    result = lsq_linear(a, target, bounds=(lower, upper), method="bvls")
    held = result.active_mask.astype(int)
    solved = _with_bounds_held(a, target, lower, upper, held, inverses)
    return (np.clip(result.x, lower, upper) if solved is None else solved), held


def _with_bounds_held(a: np.ndarray, target: np.ndarray, lower: np.ndarray, upper: np.ndarray,
                      held: np.ndarray, inverses: dict[bytes, np.ndarray]) -> np.ndarray | None:
    """The least squares answer with the bounds ``held`` (as :func:`bounded_least_squares` gives them) and the other
    values free; None where it breaks a bound or a held value would rather move inwards."""
    held = np.ascontiguousarray(held, dtype=np.int64)
    key = held.tobytes()
    inverse = inverses.get(key)
    if inverse is None:
        free = held == 0
        inverse = np.linalg.pinv(a[:, free]) if free.any() else np.zeros((0, a.shape[0]))
        inverses[key] = inverse
    x = np.empty(a.shape[1])
    return x if _held_solution(a, target, lower, upper, held, inverse, x) else None


@compiled
def _held_solution(a: np.ndarray, target: np.ndarray, lower: np.ndarray, upper: np.ndarray, held: np.ndarray,
                   inverse: np.ndarray, x: np.ndarray) -> bool:
    """:func:`_with_bounds_held`'s answer into ``x`` (m,): the held values at their bounds, the free ones
    ``inverse`` ((free, k): the pseudo-inverse of ``a``'s free columns) times ``target`` less the held columns'
    part; whether it stays within its bounds and no held value would rather move inwards."""
    rows, m = a.shape
    rest = target.copy()
    for j in range(m):
        if held[j] != 0:
            x[j] = lower[j] if held[j] < 0 else upper[j]
            for i in range(rows):
                rest[i] -= a[i, j] * x[j]
    k = 0
    for j in range(m):
        if held[j] == 0:
            value = 0.0
            for i in range(rows):
                value += inverse[k, i] * rest[i]
            if value <= lower[j] or value >= upper[j]:
                return False
            x[j] = value
            k += 1
    fitted = np.zeros(rows)                                      # a x
    for i in range(rows):
        for j in range(m):
            fitted[i] += a[i, j] * x[j]
    largest_pull, largest_fit, gradient = 0.0, 0.0, np.zeros(m)  # |a^T target|, |a^T a x|, a^T (a x - target)
    for j in range(m):
        pull, fit = 0.0, 0.0
        for i in range(rows):
            pull += a[i, j] * target[i]
            fit += a[i, j] * fitted[i]
            gradient[j] += a[i, j] * (fitted[i] - target[i])
        largest_pull, largest_fit = max(largest_pull, abs(pull)), max(largest_fit, abs(fit))
    tolerance = 1e-9 * (largest_pull + largest_fit)
    for j in range(m):
        if (held[j] < 0 and gradient[j] < -tolerance) or (held[j] > 0 and gradient[j] > tolerance):
            return False
    return True
