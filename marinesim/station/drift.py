"""Second-order wave drift loads for station keeping: the mean in a spectrum, and the slowly varying part in time.

Loads are (X, Y, N) in the manoeuvring axes of :mod:`marinesim.manoeuvring.state` (x forward, y to starboard,
z down; N positive turning the bow to starboard), in N, N and N m, from a :class:`~marinesim.vessel.drift.DriftTable`
``D(omega, beta)`` (per wave amplitude squared). Wave directions follow docs/CONVENTIONS.md: a component travels
towards the math angle ``direction`` in E, the vessel's heading is the math angle of her x axis, and the table is
looked up at ``beta_rel = direction - heading``.

- :func:`mean_drift`: a long-crested sea of one-sided spectrum ``S(omega)`` (m^2 s/rad) gives the mean load
  ``F = 2 integral S(omega) D(omega, beta) d omega``.
- :class:`SlowDrift`: Newman's approximation of the difference-frequency quadratic transfer function,
  ``T(w_j, w_k) ~ sign sqrt(|D_j| |D_k|)``, summed by sign groups so that per load
  ``F(t) = |sum_{D_j > 0} a_j sqrt(D_j) e^{i w_j t}|^2 - |sum_{D_j < 0} a_j sqrt(-D_j) e^{i w_j t}|^2``:
  only frequencies ``w_j - w_k`` appear (no sum frequencies), and the time mean is exactly ``sum |a_j|^2 D_j``.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Callable

import numpy as np
from scipy.integrate import trapezoid

from marinesim.compiled import compiled
from marinesim.errors import ParameterError, require_finite, require_within
from marinesim.sea.ocean import Components
from marinesim.vessel.drift import DriftTable

QUADRATURE_REFINE = 16
"""Sub-intervals per interval between the spectrum's and the table's frequencies in :func:`mean_drift`."""
HEADING_STEP = math.radians(0.1)
"""Headings are rounded to this (rad) before the table is looked up: one prepared set of sums per step."""
KEPT_SHARE = 0.999
"""Share of ``sum |a_j|^2 |D_j|`` (each load) held by the components :class:`SlowDrift` sums in time."""
CACHED_HEADINGS = 32
"""How many headings' prepared sums :class:`SlowDrift` keeps (least recently used dropped first)."""
FORCE_STEP = 0.1
"""Time grid (s) :meth:`SlowDrift.force` interpolates between."""
FORCE_WINDOW = 256
"""Most grid times summed at once, per heading, by :meth:`SlowDrift.force` (25.6 s of loads)."""
LAST_KEPT = 4
"""How many of the newest loads :meth:`SlowDrift.force` keeps by time and heading step: a Runge-Kutta step asks
twice at its middle, and its end is the next step's start."""
_BLOCK = 16


def mean_drift(table: DriftTable, spectrum_omega: np.ndarray,
               spectrum_density: np.ndarray | Callable[[np.ndarray], np.ndarray], beta: float) -> np.ndarray:
    """Mean drift load (3,) (N, N, N m) of a long-crested sea travelling at relative heading ``beta`` (rad).

    ``spectrum_density`` is ``S`` (m^2 s/rad) sampled at ``spectrum_omega`` (n,) rad/s (linear between the
    samples, zero outside them), or a callable ``S(omega)`` evaluated over ``spectrum_omega``'s range.
    ``F = 2 integral S D d omega`` by the trapezoidal rule on the union of the spectrum's and the table's
    frequencies, each interval cut into :data:`QUADRATURE_REFINE`.
    """
    w = np.asarray(spectrum_omega, dtype=float)
    if w.ndim != 1 or w.size < 2 or not np.all(np.isfinite(w)) or np.any(np.diff(w) <= 0.0):
        raise ParameterError("spectrum_omega must be two or more finite, increasing frequencies (rad/s)")
    beta = require_finite("beta", beta)
    if callable(spectrum_density):
        density = spectrum_density
    else:
        samples = np.asarray(spectrum_density, dtype=float)
        if samples.shape != w.shape or not np.all(np.isfinite(samples)):
            raise ParameterError(f"spectrum_density must be {w.size} finite values, one per frequency")
        def density(x: np.ndarray) -> np.ndarray:
            return np.interp(x, w, samples, left=0.0, right=0.0)
    inside = table.omega[(table.omega > w[0]) & (table.omega < w[-1])]
    knots = np.union1d(w, inside)
    steps = np.linspace(0.0, 1.0, QUADRATURE_REFINE + 1)[:-1]
    fine = np.append((knots[:-1, None] + np.diff(knots)[:, None] * steps).ravel(), knots[-1])
    s = np.asarray(density(fine), dtype=float)
    values = table(fine, np.full(fine.shape, beta))  # (m, 3)
    return 2.0 * trapezoid(s[:, None] * values, fine, axis=0)


class _Phasors:
    """``exp(i w j FORCE_STEP)``, j < :data:`_BLOCK`, of the distinct frequencies ``omega`` (u,) rad/s: (_BLOCK, u),
    computed when first asked and shared by every heading's sums."""

    def __init__(self, omega: np.ndarray) -> None:
        self.omega = omega
        self._table: np.ndarray | None = None

    def table(self) -> np.ndarray:
        if self._table is None:
            self._table = np.exp(1j * np.outer(np.arange(_BLOCK) * FORCE_STEP, self.omega))
        return self._table


class _Heading:
    """The sums of one heading: kept frequencies (m,) rad/s (``phasors``' columns ``present``), coefficients (m, 6)
    per sign group, the mean of the components left out (3,), the full mean (3,), and the window of loads (W, 3) on
    the time grid from index ``start`` (times ``(start + i) FORCE_STEP``)."""

    def __init__(self, phasors: _Phasors, present: np.ndarray, coefficients: np.ndarray, constant: np.ndarray,
                 mean: np.ndarray) -> None:
        self.omega, self.coefficients, self.constant, self.mean = phasors.omega[present], coefficients, constant, mean
        self._phasors, self._present = phasors, present
        self.start = 0
        self.window = np.empty((0, 3))

    def series(self, times: np.ndarray, chunk: int = 512) -> np.ndarray:
        """The loads (n_t, 3) at ``times`` (n_t,) s, summed exactly."""
        out = np.empty((times.size, 3))
        for lo in range(0, times.size, chunk):
            hi = min(lo + chunk, times.size)
            sums = np.exp(1j * np.outer(times[lo:hi], self.omega)) @ self.coefficients
            out[lo:hi] = (sums.real**2 + sums.imag**2) @ _GROUPS + self.constant
        return out

    def fill(self, start: int, length: int) -> None:
        """Sum the window of ``length`` (a multiple of ``_BLOCK``) grid times from index ``start``: the phases
        ``exp(i w t)`` advance block by block by multiplication (one exponential per component and window)."""
        block = self._phasors.table()[:, self._present]
        jump = np.exp(1j * self.omega * (_BLOCK * FORCE_STEP))
        phase = np.exp(1j * self.omega * (start * FORCE_STEP))
        sums = np.empty((length, 6), dtype=complex)
        for lo in range(0, length, _BLOCK):
            sums[lo:lo + _BLOCK] = (block * phase) @ self.coefficients
            phase = phase * jump
        self.start = start
        self.window = (sums.real**2 + sums.imag**2) @ _GROUPS + self.constant


class SlowDrift:
    """Slowly varying drift load (Newman's approximation, module docstring) of wave components at a fixed point.

    ``omega`` (n,) rad/s, ``direction`` (n,) rad (math angle in E each component travels towards) and complex
    ``amplitude`` (n,) m, the phase at the vessel's origin (``eta = Re sum a exp(i w t)`` there;
    :meth:`from_components` refers an ocean's components to a point). For speed, per heading (rounded to
    :data:`HEADING_STEP`, the last :data:`CACHED_HEADINGS` kept) the table is looked up once, components of equal
    frequency are added together (exact), and only the largest components holding ``kept_share``
    (:data:`KEPT_SHARE`) of ``sum |a_j|^2 |D_j|`` (each load; those equal to the smallest of them too) are summed in
    time; the others add their mean ``|a_j|^2 D_j`` as a constant, so the time mean stays exactly :meth:`mean`.
    """

    def __init__(self, omega: np.ndarray, direction: np.ndarray, amplitude: np.ndarray, table: DriftTable, *,
                 kept_share: float = KEPT_SHARE) -> None:
        self.omega = np.asarray(omega, dtype=float).ravel()
        self.direction = np.asarray(direction, dtype=float).ravel()
        self.amplitude = np.asarray(amplitude, dtype=complex).ravel()
        n = self.omega.size
        if self.direction.size != n or self.amplitude.size != n:
            raise ParameterError(f"omega, direction and amplitude must have one value per component, got "
                                 f"{n}, {self.direction.size} and {self.amplitude.size}")
        if not (np.all(np.isfinite(self.omega)) and np.all(np.isfinite(self.direction))
                and np.all(np.isfinite(self.amplitude))):
            raise ParameterError("wave component frequencies, directions and amplitudes must be finite")
        if np.any(self.omega <= 0.0):
            raise ParameterError(f"wave component frequencies must be > 0 rad/s, got {self.omega.min():g}")
        self.table = table
        self.kept_share = require_within("kept_share", kept_share, 0.0, 1.0)
        self._power = np.abs(self.amplitude) ** 2
        frequencies, self._of_frequency = np.unique(self.omega, return_inverse=True)
        """Each component's among the distinct frequencies (n,)."""
        self._phasors = _Phasors(frequencies)
        self._by_frequency = table.at_frequencies(frequencies)
        """The drift coefficients of each distinct frequency on every table heading, (u, n_b, 3)."""
        self._cache: OrderedDict[int, _Heading] = OrderedDict()
        self._last: dict[tuple[float, int], np.ndarray] = {}  # (t, heading step) -> the load, the newest few

    @classmethod
    def from_components(cls, components: Components, table: DriftTable, x: float = 0.0, y: float = 0.0,
                        kept_share: float = KEPT_SHARE) -> SlowDrift:
        """The slow drift at the fixed point (``x``, ``y``) (m, E frame) of an ocean's ``components``."""
        at_point = components.amplitude * np.exp(-1j * (components.kx * x + components.ky * y))
        return cls(components.omega, components.direction, at_point, table,
                   kept_share=kept_share)

    def force(self, t: float, heading: float) -> np.ndarray:
        """The load (3,) (N, N, N m; manoeuvring axes) at time ``t`` (s) on the vessel heading ``heading``
        (rad, math angle of her x axis in E).

        Interpolated (cubic Lagrange, four points) on the grid ``t = k FORCE_STEP``, whose values are summed
        exactly in windows (up to :data:`FORCE_WINDOW` grid times, per heading) as the calls move along: exact at
        the grid times, and within about ``0.023 (nu FORCE_STEP)^4`` of the amplitude of a difference frequency
        ``nu`` between them. The newest :data:`LAST_KEPT` loads are kept (read-only), as asked again.
        """
        key = (require_finite("t", t), self._key(heading))
        found = self._last.get(key)
        if found is not None:
            return found
        h = self._prepared_at(key[1])
        x = key[0] / FORCE_STEP
        first = math.floor(x) - 1
        s = x - first - 1.0
        offset = first - h.start
        if not 0 <= offset <= h.window.shape[0] - 4:
            # a window twice the last one (up to FORCE_WINDOW) when the calls move on along the same heading
            grown = h.window.shape[0] * 2 if 0 <= offset <= h.window.shape[0] + _BLOCK else _BLOCK * 2
            h.fill(first, min(max(grown, _BLOCK * 2), FORCE_WINDOW))
            offset = 0
        load = _lagrange(h.window, offset, s)
        load.flags.writeable = False
        if len(self._last) >= LAST_KEPT:
            self._last.pop(next(iter(self._last)))
        self._last[key] = load
        return load

    def force_series(self, times: np.ndarray, heading: float) -> np.ndarray:
        """The load (n_t, 3) at each of ``times`` (n_t,) s on a constant ``heading`` (rad), summed exactly."""
        return self._prepared(heading).series(np.asarray(times, dtype=float).ravel())

    def mean(self, heading: float) -> np.ndarray:
        """The mean load (3,) ``sum |a_j|^2 D_j`` (N, N, N m) on ``heading`` (rad, rounded as :meth:`force`)."""
        return self._prepared(heading).mean.copy()

    @staticmethod
    def _key(heading: float) -> int:
        """``heading`` (rad) as a whole number of :data:`HEADING_STEP` round the circle."""
        return int(round(require_finite("heading", heading) / HEADING_STEP)) % round(2.0 * math.pi / HEADING_STEP)

    def _prepared(self, heading: float) -> _Heading:
        return self._prepared_at(self._key(heading))

    def _prepared_at(self, key: int) -> _Heading:
        """The sums of heading step ``key`` (:meth:`_key`), prepared when first asked (the newest kept)."""
        found = self._cache.get(key)
        if found is not None:
            self._cache.move_to_end(key)
            return found
        prepared = self._prepare(key * HEADING_STEP)
        self._cache[key] = prepared
        if len(self._cache) > CACHED_HEADINGS:
            self._cache.popitem(last=False)
        return prepared

    def _prepare(self, heading: float) -> _Heading:
        d = self.table.at_headings(self._by_frequency, self.direction - heading, self._of_frequency)  # (n, 3)
        contribution = self._power[:, None] * d               # |a_j|^2 D_j
        mean = contribution.sum(axis=0)
        keep = np.zeros(self.omega.size, dtype=bool)
        weight = np.abs(contribution)
        descending = np.sort(weight, axis=0)[::-1]
        cumulative = np.cumsum(descending, axis=0)
        for load in range(3):
            if cumulative.size and cumulative[-1, load] > 0.0:
                count = int(np.searchsorted(cumulative[:, load], self.kept_share * cumulative[-1, load])) + 1
                keep |= weight[:, load] >= descending[count - 1, load]
        constant = contribution[~keep].sum(axis=0)
        # components of one frequency beat at zero difference frequency: added into one, exactly
        sums, count = np.zeros((self._phasors.omega.size, 6), dtype=complex), np.zeros(self._phasors.omega.size, int)
        _sign_group_sums(d, self.amplitude, self._of_frequency, keep, sums, count)
        present = np.flatnonzero(count)
        return _Heading(self._phasors, present, sums[present], constant, mean)


@compiled
def _sign_group_sums(d: np.ndarray, amplitude: np.ndarray, of_frequency: np.ndarray, keep: np.ndarray,
                     sums: np.ndarray, count: np.ndarray) -> None:
    """Each kept component's ``a_j sqrt(|D_j|)`` added, in the components' order, into its distinct frequency's
    row of ``sums`` (u, 6) in its sign group's column (X+, X-, Y+, Y-, N+, N-); ``count`` (u,) the components
    added to each row."""
    for i in range(d.shape[0]):
        if not keep[i]:
            continue
        f = of_frequency[i]
        count[f] += 1
        for load in range(3):
            value = d[i, load]
            sums[f, 2 * load + (0 if value > 0.0 else 1)] += amplitude[i] * math.sqrt(abs(value))


@compiled
def _lagrange(window: np.ndarray, offset: int, s: float) -> np.ndarray:
    """The cubic through rows ``offset`` to ``offset + 3`` of ``window`` (W, 3), at ``s`` (0 to 1) between the middle
    two: :meth:`SlowDrift.force`'s interpolation, (3,)."""
    a, b, c = s + 1.0, s - 1.0, s - 2.0
    out = np.empty(3)
    for k in range(3):
        out[k] = (-s * b * c * window[offset, k] + 3.0 * a * b * c * window[offset + 1, k]
                  - 3.0 * a * s * c * window[offset + 2, k] + a * s * b * window[offset + 3, k]) / 6.0
    return out


_GROUPS = np.kron(np.eye(3), [[1.0], [-1.0]])
"""(6, 3): the squared sums of the sign groups (X+, X-, Y+, Y-, N+, N-) -> the loads X, Y, N."""
