"""The RAO model: six complex transfer functions over frequency, relative heading and speed.

Conventions (docs/CONVENTIONS.md, "Transfer functions"): ``H_j(w, beta_rel, U)`` gives the
response ``x_j(t) = Re{H_j a exp(i w t)}`` to the wave ``a exp(i w t)`` at the body-frame origin
(the RAO reference point); positive phase = response leads. Translations in m/m, rotations in
rad/m. ``w`` is the wave (not encounter) frequency; ``beta_rel`` the direction the waves travel
towards relative to the bow (0 following, pi/2 towards port, pi head sea).

Interpolation is linear on Re/Im in frequency, heading (wrapping around the circle) and speed.
Outside the tabulated frequencies:

* below the lowest, ``H = L(w) + (H(w0) - L(w0)) (w / w0)^2``: the free-floating long-wave
  limit ``L`` (:func:`long_wave_limit`, in the table's water depth) plus the table's deviation
  from it, fading as w^2;
* above the highest, the last value tapered by ``cos^2`` to zero at 1.5 times that frequency.

A table of one frequency (a regular-wave result) is extended the same way from that frequency.

Speeds outside a multi-speed table are clamped to its ends (scenarios refuse them up front).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from marinesim.constants import G, KNOT
from marinesim.errors import ParameterError, require_positive
from marinesim.sea.dispersion import k_from_omega

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
ROTATIONS = (3, 4, 5)
MIRROR_SIGN = np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
"""Sign of each DOF under the port/starboard mirror beta -> -beta: sway, roll, yaw flip."""
TAPER_END = 1.5
"""Above the table, RAOs taper to zero at this multiple of the highest frequency."""
MAX_HEADING_GAP = math.pi / 2
"""Largest gap between tabulated headings (after mirroring) that interpolation may bridge; a wider gap makes
the table partial (it covers arcs of headings, :attr:`RaoTable.covered`)."""
HEADING_MARGIN = math.radians(15.0)
"""A partial table stands for headings up to this beyond the ends of each arc it covers (its end values
held): one step of the usual 15 deg table, so a table at 180 deg only serves head seas 165..195 deg."""
MAX_TRANSLATION_M_M = 50.0
"""Largest |RAO| of surge, sway, heave (m/m): resonant heave peaks of floating bodies stay under 10."""
MAX_ROTATION_RAD_M = 1.0
"""Largest |RAO| of roll, pitch, yaw (rad/m) at full scale: 57 deg per metre of wave amplitude, beyond any
ship's resonant roll; a model-scale table may reach :data:`MAX_ROTATION_SLOPES` times the wave slope k."""
SURGE_SPEED_FACTOR = 1.5
"""A surge RAO at forward speed above this multiple of the same table's largest surge at zero speed is noted
as implausible (no restoring force, no resonance to amplify it: strip-theory surge at speed, as VERES gives
it, is the usual cause)."""
MAX_ORBIT_FACTOR = 3.0
"""A surge or sway RAO above this multiple of the wave orbit's horizontal amplitude (``1 / tanh(kh)`` m/m) is
noted as implausible (couplings near a resonance reach about twice it: the HAMS cylinder's 2.1)."""
MAX_ROTATION_SLOPES = 50.0
"""Largest rotation |RAO| as a multiple of the wave slope per amplitude, k = w^2 / g (rad/m)."""


def long_wave_limit(omega: np.ndarray, beta: np.ndarray, g: float = G, depth: float = math.inf) -> np.ndarray:
    """Long-wave RAO of a free-floating body in water of ``depth`` (m; inf = deep), shape (n, 6).

    The body follows the wave orbit and slope at the surface: surge ``-i cos beta / tanh(kh)``,
    sway ``-i sin beta / tanh(kh)`` (the horizontal orbit is ``1 / tanh(kh)`` times the vertical
    one), heave 1, roll ``-i k sin beta``, pitch ``i k cos beta`` (pitch bow down = minus the
    slope along x), yaw 0, with ``k`` from ``w^2 = g k tanh(kh)`` (deep water: ``k = w^2 / g``,
    ``tanh = 1``).
    """
    omega = np.asarray(omega, dtype=float)
    beta = np.asarray(beta, dtype=float)
    k = k_from_omega(omega, depth, g)
    orbit = 1.0 if math.isinf(depth) else 1.0 / np.tanh(k * depth)
    c, s = np.cos(beta), np.sin(beta)
    zero = np.zeros(np.broadcast(omega, beta).shape)
    return np.stack([-1j * c * orbit + zero, -1j * s * orbit + zero, 1.0 + zero, -1j * k * s, 1j * k * c,
                     zero + 0j], axis=-1)


@dataclass(frozen=True)
class RaoTable:
    """Tabulated RAOs in the internal convention.

    ``values[s, b, w, j]``: speed ``speed[s]`` (m/s), heading ``beta[b]`` (rad, increasing in
    [0, 2 pi)), frequency ``omega[w]`` (rad/s, increasing), DOF j in :data:`DOFS` order.
    ``depth`` (m, inf = deep water) is the water depth the table was computed for: the long-wave
    limits and the extension below the table use it. Build with :func:`make_table`, which
    completes half-range tables by symmetry. ``covered`` is None for a table of the whole circle,
    else the arcs ``(first, last)`` (rad, counter-clockwise from first to last) its headings cover
    with no gap over :data:`MAX_HEADING_GAP` (a partial table: a single heading, or headings on one
    side only), each good to :data:`HEADING_MARGIN` beyond its ends.
    """

    omega: np.ndarray
    beta: np.ndarray
    speed: np.ndarray
    values: np.ndarray
    reference_point: tuple[float, float, float]
    rho: float
    g: float
    source: str
    source_format: str
    notes: tuple[str, ...] = field(default=())
    mirrored: bool = False
    depth: float = math.inf
    covered: tuple[tuple[float, float], ...] | None = None

    def __call__(self, omega: np.ndarray, beta: np.ndarray, speed: float = 0.0) -> np.ndarray:
        """Interpolated RAOs, shape (n, 6), at wave frequencies ``omega`` (rad/s, > 0) and
        relative headings ``beta`` (rad, any range) for forward speed ``speed`` (m/s)."""
        omega = np.asarray(omega, dtype=float).ravel()
        beta = np.mod(np.asarray(beta, dtype=float).ravel(), 2.0 * math.pi)
        table = self._at_speed(speed)
        w_lo, w_hi = self.omega[0], self.omega[-1]
        if self.covered is not None:
            beta = self._nearest_covered(beta)
        inside = _bilinear(self.omega, self._beta_wrapped, table, np.clip(omega, w_lo, w_hi), beta)
        below = omega < w_lo
        if np.any(below):
            fade = (omega[below] / w_lo) ** 2
            at_edge = inside[below]
            inside[below] = (long_wave_limit(omega[below], beta[below], self.g, self.depth)
                             + (at_edge - long_wave_limit(np.full(fade.size, w_lo), beta[below], self.g,
                                                          self.depth)) * fade[:, None])
        above = omega > w_hi
        if np.any(above):
            x = np.clip((omega[above] - w_hi) / ((TAPER_END - 1.0) * w_hi), 0.0, 1.0)
            inside[above] *= (np.cos(0.5 * math.pi * x) ** 2)[:, None]
        return inside

    def _nearest_covered(self, beta: np.ndarray) -> np.ndarray:
        """``beta`` (rad, in [0, 2 pi)) moved to the nearest heading of the covered arcs (its end values held
        beyond an arc's ends; interpolation never bridges a gap)."""
        best, moved = np.full(beta.shape, np.inf), beta.copy()
        for first, last in self.covered:
            length = np.mod(last - first, 2.0 * math.pi)
            offset = np.mod(beta - first, 2.0 * math.pi)
            after = offset - length                        # > 0: beyond the last heading
            before = 2.0 * math.pi - offset                # to the first heading, going back
            inside = offset <= length
            distance = np.where(inside, 0.0, np.minimum(after, before))
            target = np.where(inside, beta, np.where(after <= before, last, first))
            closer = distance < best
            best, moved = np.where(closer, distance, best), np.where(closer, target, moved)
        return np.mod(moved, 2.0 * math.pi)

    def covers(self, beta: np.ndarray) -> np.ndarray:
        """Whether each relative heading ``beta`` (rad, any range) is within the table's headings (a table of
        the whole circle covers every one; a partial table its arcs and :data:`HEADING_MARGIN` beyond them)."""
        beta = np.mod(np.asarray(beta, dtype=float), 2.0 * math.pi)
        if self.covered is None:
            return np.ones(beta.shape, dtype=bool)
        return np.abs(np.angle(np.exp(1j * (self._nearest_covered(beta) - beta)))) <= HEADING_MARGIN + 1e-9

    def covered_text(self) -> str:
        """The covered headings in words, e.g. ``"165..195 deg (tabulated 180)"``."""
        if self.covered is None:
            return "0..360 deg"
        margin = math.degrees(HEADING_MARGIN)
        arcs = []
        for first, last in self.covered:
            a, b = round(math.degrees(first), 6), round(math.degrees(last), 6)
            tabulated = f"{a:g}" if a == b else f"{a:g}..{b:g}"
            arcs.append(f"{(a - margin) % 360:g}..{(b + margin) % 360:g} deg (tabulated {tabulated})")
        return ", ".join(arcs)

    @property
    def _beta_wrapped(self) -> np.ndarray:
        return np.append(self.beta, self.beta[0] + 2.0 * math.pi)

    def _at_speed(self, speed: float) -> np.ndarray:
        """Table (nb + 1, nw, 6) at ``speed``, with the first heading repeated at the end."""
        if self.speed.size == 1:
            table = self.values[0]
        else:
            u = float(np.clip(speed, self.speed[0], self.speed[-1]))
            i = int(np.clip(np.searchsorted(self.speed, u, side="right") - 1, 0, self.speed.size - 2))
            f = (u - self.speed[i]) / (self.speed[i + 1] - self.speed[i])
            table = (1.0 - f) * self.values[i] + f * self.values[i + 1]
        return np.concatenate([table, table[:1]], axis=0)

    @property
    def speed_range(self) -> tuple[float, float]:
        return float(self.speed[0]), float(self.speed[-1])


def _bilinear(omega_grid: np.ndarray, beta_grid: np.ndarray, table: np.ndarray,
              omega: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """Linear on Re/Im in frequency and heading; ``table`` is (len(beta_grid), len(omega_grid), 6).
    A one-frequency table holds its value at every frequency."""
    iw, fw = _locate(omega_grid, omega)
    ib, fb = _locate(beta_grid, beta)
    iw1 = np.minimum(iw + 1, omega_grid.size - 1)
    fw, fb = fw[:, None], fb[:, None]
    return ((1 - fb) * ((1 - fw) * table[ib, iw] + fw * table[ib, iw1])
            + fb * ((1 - fw) * table[ib + 1, iw] + fw * table[ib + 1, iw1]))


def _locate(grid: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cell index and fraction of each ``x`` in the increasing ``grid`` (x within its range)."""
    if grid.size == 1:
        return np.zeros(x.size, dtype=int), np.zeros(x.size)
    i = np.clip(np.searchsorted(grid, x, side="right") - 1, 0, grid.size - 2)
    return i, (x - grid[i]) / (grid[i + 1] - grid[i])


def refer_phases(values: np.ndarray, omega: np.ndarray, headings_deg: np.ndarray, offset_m: tuple[float, float],
                 depth: float, g: float) -> np.ndarray:
    """RAOs ``values`` (headings, frequencies, ...) relative to the incident wave at one point -> relative to
    the wave at the point ``offset_m`` (dx, dy) from it: the wave there lags by ``k (dx cos b + dy sin b)``, so
    the RAOs gain that phase (``exp(+i w t)``, lead). ``omega`` rad/s, headings the travel direction."""
    dx, dy = offset_m
    if dx == 0.0 and dy == 0.0:
        return values
    k = k_from_omega(np.asarray(omega, float), depth if math.isfinite(depth) else math.inf, g)
    beta = np.radians(np.asarray(headings_deg, float))[:, None]
    factor = np.exp(1j * k[None, :] * (dx * np.cos(beta) + dy * np.sin(beta)))
    return values * factor.reshape(factor.shape + (1,) * (values.ndim - 2))


def make_table(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray, *,
               reference_point=(0.0, 0.0, 0.0), rho: float = 1025.0, g: float = G, source: str = "",
               source_format: str = "", notes: tuple[str, ...] = (), depth: float = math.inf) -> RaoTable:
    """Validate and complete an RAO table already in the internal convention.

    ``values`` has shape (speeds, headings, frequencies, 6). Headings (rad) spanning exactly
    0..pi are completed by the port/starboard mirror (:data:`MIRROR_SIGN`); headings that leave a
    gap wider than :data:`MAX_HEADING_GAP` make a partial table (:attr:`RaoTable.covered`).
    ``depth``: water depth (m, > 0; inf = deep). Raises :class:`ParameterError` on anything else.
    """
    depth = require_positive("water depth", depth, allow_infinite=True)
    omega = np.asarray(omega, dtype=float)
    beta = np.asarray(beta, dtype=float)
    speed = np.atleast_1d(np.asarray(speed, dtype=float))
    values = np.asarray(values, dtype=complex)
    if values.shape != (speed.size, beta.size, omega.size, 6):
        raise ParameterError(f"RAO values have shape {values.shape}, expected "
                             f"(speeds, headings, frequencies, 6) = ({speed.size}, {beta.size}, {omega.size}, 6)")
    if not np.all(np.isfinite(values)):
        raise ParameterError("RAO values must be finite")
    _check_increasing("frequencies", omega, minimum=0.0)
    _check_amplitudes(omega, beta, values, g)
    _check_increasing("speeds", speed, minimum=None)
    if beta.size == 0 or not np.all(np.isfinite(beta)):
        raise ParameterError("RAO headings must be finite and at least one")
    order = np.argsort(beta, kind="stable")
    beta, values = beta[order], values[:, order]
    eps = 1e-9
    mirrored = bool(abs(beta[0]) < eps and abs(beta[-1] - math.pi) < eps)
    if mirrored:
        inner = (beta > eps) & (beta < math.pi - eps)
        beta = np.concatenate([beta, 2.0 * math.pi - beta[inner][::-1]])
        values = np.concatenate([values, values[:, inner][:, ::-1] * MIRROR_SIGN], axis=1)
    beta = np.mod(beta, 2.0 * math.pi)
    beta[beta > 2.0 * math.pi - eps] = 0.0
    order = np.argsort(beta, kind="stable")
    beta, values = beta[order], values[:, order]
    same = np.flatnonzero(np.diff(beta) < eps)
    if same.size:
        raise ParameterError(f"RAO heading {math.degrees(beta[same[0]]):g} deg is given twice "
                             "(after wrapping to 0..360)")
    gaps = np.diff(np.append(beta, beta[0] + 2.0 * math.pi))
    wide = gaps > MAX_HEADING_GAP + eps
    covered = None
    if wide.any():
        ends = np.flatnonzero(wide)                      # the gap after these headings is too wide to bridge
        starts = (ends + 1) % beta.size
        covered = tuple((float(beta[a]), float(beta[b])) for a, b in zip(starts, np.roll(ends, -1), strict=True))
    notes = tuple(notes) + _implausible(omega, beta, speed, values, g, depth)
    return RaoTable(omega, beta, speed, values, tuple(float(v) for v in reference_point), float(rho),
                    float(g), str(source), source_format, notes, mirrored, depth, covered)


def _implausible(omega: np.ndarray, beta: np.ndarray, speed: np.ndarray, values: np.ndarray, g: float,
                 depth: float) -> tuple[str, ...]:
    """Notes on surge and sway RAOs a floating body does not have (:data:`SURGE_SPEED_FACTOR`,
    :data:`MAX_ORBIT_FACTOR`): each names where the largest is and what it was compared with."""
    def where(index: tuple) -> str:
        s, b, w = index
        return f"{speed[s] / KNOT:.3g} kn, heading {math.degrees(beta[b]):g} deg, T {2 * math.pi / omega[w]:.3g} s"

    notes = []
    k = k_from_omega(omega, depth, g)
    orbit = np.ones_like(k) if math.isinf(depth) else 1.0 / np.tanh(k * depth)
    for j, dof in ((0, "surge"), (1, "sway")):
        ratio = np.abs(values[..., j]) / orbit
        peak = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
        if ratio[peak] > MAX_ORBIT_FACTOR:
            notes.append(f"implausible {dof} RAO: {abs(values[peak + (j,)]):.3g} m/m at {where(peak)}, "
                         f"{ratio[peak]:.2g} times the wave orbit; check the file's units and reference point")
    at_rest = np.flatnonzero(np.abs(speed) < 1e-9)
    if at_rest.size and speed.size > 1:
        surge = np.abs(values[..., 0])
        still = surge[at_rest].max()
        peak = np.unravel_index(int(np.argmax(surge)), surge.shape)
        if still > 0.0 and surge[peak] > SURGE_SPEED_FACTOR * still:
            notes.append(f"implausible surge RAO at speed: {surge[peak]:.3g} m/m at {where(peak)}, "
                         f"{surge[peak] / still:.2g} times the largest at 0 kn ({still:.3g} m/m); surge has no "
                         "restoring force to resonate with, so this is the source's (strip-theory surge at "
                         "speed is unreliable): treat surge at this speed with caution")
    return tuple(notes)


def _check_amplitudes(omega: np.ndarray, beta: np.ndarray, values: np.ndarray, g: float) -> None:
    """Refuse an |RAO| no floating body has (:data:`MAX_TRANSLATION_M_M`, :data:`MAX_ROTATION_RAD_M`)."""
    limit = np.full((omega.size, 6), MAX_TRANSLATION_M_M)
    limit[:, list(ROTATIONS)] = np.maximum(MAX_ROTATION_RAD_M, MAX_ROTATION_SLOPES * omega**2 / g)[:, None]
    over = np.abs(values) > limit
    if over.any():
        s, b, w, j = np.argwhere(over)[0]
        unit = "rad/m" if j in ROTATIONS else "m/m"
        raise ParameterError(f"RAO {DOFS[j]} amplitude {abs(values[s, b, w, j]):.3g} {unit} at {omega[w]:.4g} rad/s, "
                             f"heading {math.degrees(beta[b]):g} deg is beyond any floating body's "
                             f"(<= {limit[w, j]:.3g} {unit}): check the units")


def _check_increasing(name: str, grid: np.ndarray, minimum: float | None) -> None:
    if grid.ndim != 1 or grid.size == 0 or not np.all(np.isfinite(grid)):
        raise ParameterError(f"RAO {name} must be a non-empty list of finite numbers")
    if minimum is not None and grid[0] <= minimum:
        raise ParameterError(f"RAO {name} must be > {minimum:g}, got {grid[0]:g}")
    if np.any(np.diff(grid) <= 0):
        at = int(np.flatnonzero(np.diff(grid) <= 0)[0])
        raise ParameterError(f"RAO {name} must be strictly increasing: {grid[at]:g} then {grid[at + 1]:g}")
