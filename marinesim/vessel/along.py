"""The vessel's response along a manoeuvre: a track that turns and changes speed.

Each wave component's phase is that of the incident wave at the reference point where it is, ``phi = w t - k .
r(t)``: it accumulates the encounter frequency ``w_e = w - k . dr/dt`` as the ship goes, so a turn or a change of
speed never makes a motion jump. The transfer functions ``H(w, beta - psi, U)`` are taken at the heading and speed
of every :data:`KNOT_S` and between by a Catmull-Rom spline (through the knots, C1 in time, exact for a quadratic
change), two knots late: the motion at ``t`` reads the ship's heading and speed up to ``t`` and no later (an order
given after ``t`` cannot change it), and a response that settles over a few wave periods is not made to follow a
turn faster than that. The derivatives follow the product rule (exact for that interpolation):

- ``x = Re sum H a e^{i phi}``, ``dx/dt = Re sum (dH/dt + i w_e H) a e^{i phi}``,
- ``d2x/dt2 = Re sum (d2H/dt2 + 2 i w_e dH/dt + (i dw_e/dt - w_e^2) H) a e^{i phi}``, ``dw_e/dt = -k . d2r/dt2``;
- the elevation at a point ``p`` on board (body frame) is the incident wave at its mean position ``r + R(psi)
  p`` in the Earth frame.

On a straight track this is :class:`~marinesim.vessel.response.Response`'s sum, to rounding. The sum runs in a
compiled loop over time steps and components (numba; a long pass's time steps on every core).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numba
import numpy as np

from marinesim.compiled import compiled
from marinesim.recent import Newest
from marinesim.sea.ocean import Components
from marinesim.vessel.rao import RaoTable

KNOT_S = 1.0
"""The transfer functions are taken at the heading and speed of every second: a ship turning at 1 deg/s moves 1
deg of relative heading from one to the next, where RAO tables are tabulated every 10 to 30 deg."""
LAG_KNOTS = 2
"""The transfer functions at ``t`` are interpolated at ``t - LAG_KNOTS KNOT_S``: the last knot they read is at
``t`` or before."""
KNOTS_PER_PASS = 16
"""Knots whose transfer functions are held at once ((knots, components, 6) complex: 16 MB at 10,000 components)."""
KNOTS_KEPT = 4
"""How many knots' transfer functions :class:`Knots` keeps, the newest: the four one time reads, so that times
asked one by one (a frame's pose) and the next pass of :func:`linear_along` find them ((components, 6) complex
each: 19 MB at 50,000 components)."""
KNOT_SETS_KEPT = 2
"""Component sets whose :class:`Knots` a body keeps, the newest asked: a sea change blends two."""
EVERY_CORE_FROM = 200_000
"""Time steps times components from which a pass is summed on every core (about 40 ms of one core's work): a
smaller one, as a frame's few steps or a recorder's one, costs less on one core than waking the others, which a
busy machine may not have free. Each step is summed the same way on either path, to the same bits."""


@dataclass(frozen=True)
class ShipPath:
    """The track at ``times`` (T,) (s) of the manoeuvring model's origin (midship), taken as the RAO table's reference
    point: position ``x``, ``y`` (m, E frame), velocity ``vx``,
    ``vy`` (m/s) and acceleration ``ax``, ``ay`` (m/s^2), the heading (math angle of the bow, rad), its rate
    (rad/s) and acceleration (rad/s^2), the speed through the water (m/s), and the manoeuvre's own heel
    (CONVENTIONS' roll, rad) with its rate and acceleration."""

    times: np.ndarray
    x: np.ndarray
    y: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    ax: np.ndarray
    ay: np.ndarray
    heading: np.ndarray
    rate: np.ndarray
    rate_dot: np.ndarray
    speed: np.ndarray
    roll: np.ndarray
    roll_rate: np.ndarray
    roll_acc: np.ndarray


class Knots:
    """The motions' complex amplitudes ``H(w, beta - psi, U) a`` (n, 6) of ``components`` by the RAO table ``rao``
    at a knot's heading ``psi`` (rad, math angle) and speed ``U`` (m/s), the newest :data:`KNOTS_KEPT` kept by
    (heading, speed). Components beyond a partial table's headings take its nearest heading's."""

    def __init__(self, rao: RaoTable, components: Components) -> None:
        self.rao, self.components = rao, components
        self._kept: Newest[tuple[float, float], np.ndarray] = Newest(KNOTS_KEPT)

    def motion(self, psi: float, speed: float) -> np.ndarray:
        """The amplitudes (n, 6) (m, rad) on heading ``psi`` (rad) at ``speed`` (m/s); read-only."""
        psi, speed = float(psi), float(speed)
        return self._kept.get((psi, speed), lambda: self._computed(psi, speed))

    def _computed(self, psi: float, speed: float) -> np.ndarray:
        c = self.components
        out = self.rao(c.omega, c.direction - psi, speed) * c.amplitude[:, None]
        out.flags.writeable = False
        return out


def linear_along(knots: Knots, points: dict[str, tuple[float, float, float]],
                 path_at: Callable[[np.ndarray], ShipPath], times: np.ndarray) -> np.ndarray:
    """:meth:`Response.linear`'s outputs (T, 19 + points) at ``times`` (s, increasing) along the track that
    ``path_at(times)`` gives (see the module), the transfer functions at the knots from ``knots``."""
    times = np.asarray(times, dtype=float).ravel()
    c = knots.components
    offsets = np.array([np.asarray(p, dtype=float) for p in points.values()]).reshape(-1, 3)
    out = np.empty((times.size, 19 + len(offsets)))
    if not times.size:
        return out
    path = path_at(times)
    cos_psi, sin_psi = np.cos(path.heading), np.sin(path.heading)
    px = cos_psi[:, None] * offsets[:, 0] - sin_psi[:, None] * offsets[:, 1]     # (T, points), E frame
    py = sin_psi[:, None] * offsets[:, 0] + cos_psi[:, None] * offsets[:, 1]
    lagged = times - LAG_KNOTS * KNOT_S
    interval = np.floor(lagged / KNOT_S).astype(np.int64)
    weights = _catmull_rom((lagged - interval * KNOT_S) / KNOT_S)                 # (T, 3, 4)
    for lo_knot in range(int(interval[0]), int(interval[-1]) + 1, KNOTS_PER_PASS):
        hi_knot = min(lo_knot + KNOTS_PER_PASS, int(interval[-1]) + 1)
        at = path_at(np.maximum(np.arange(lo_knot - 1, hi_knot + 2) * KNOT_S, 0.0))
        motion = np.stack([knots.motion(psi, speed) for psi, speed in zip(at.heading, at.speed)])  # (knots, n, 6)
        rows = np.flatnonzero((interval >= lo_knot) & (interval < hi_knot))
        summed = _sum_on_every_core if rows.size * c.omega.size >= EVERY_CORE_FROM else _sum
        summed(times[rows], interval[rows] - lo_knot, weights[rows], path.x[rows], path.y[rows], path.vx[rows],
               path.vy[rows], path.ax[rows], path.ay[rows], np.ascontiguousarray(px[rows]),
               np.ascontiguousarray(py[rows]), c.omega, c.kx, c.ky, c.amplitude, motion, out, rows)
    return out


def _catmull_rom(s: np.ndarray) -> np.ndarray:
    """Weights (T, 3, 4) of the knots k-1..k+2 for the value and the first and second time derivatives (per
    KNOT_S) of the Catmull-Rom cubic at ``s`` in [0, 1) of the interval from knot k."""
    s = np.asarray(s, dtype=float)[:, None]
    s2, s3 = s * s, s * s * s
    value = np.hstack([-0.5 * s3 + s2 - 0.5 * s, 1.5 * s3 - 2.5 * s2 + 1.0, -1.5 * s3 + 2.0 * s2 + 0.5 * s,
                       0.5 * s3 - 0.5 * s2])
    slope = np.hstack([-1.5 * s2 + 2.0 * s - 0.5, 4.5 * s2 - 5.0 * s, -4.5 * s2 + 4.0 * s + 0.5, 1.5 * s2 - s])
    curve = np.hstack([-3.0 * s + 2.0, 9.0 * s - 5.0, -9.0 * s + 4.0, 3.0 * s - 1.0])
    return np.stack([value, slope / KNOT_S, curve / KNOT_S**2], axis=1)


@compiled
def _row(j, t, knot, weights, x, y, vx, vy, ax, ay, px, py, omega, kx, ky, amplitude, motion, out, rows):
    """The sums of the module for time step ``j`` into row ``rows[j]`` of ``out``: 6 motions, their rates and
    accelerations, the elevation at the reference point and at each point. ``motion[knot[j] + m]`` for m in 0..3
    are the knots around step j, ``weights[j]`` their Catmull-Rom weights."""
    points = px.shape[1]
    k = knot[j]
    w = weights[j]
    acc = np.zeros(19 + points)
    for i in range(omega.size):
        phase = omega[i] * t[j] - kx[i] * x[j] - ky[i] * y[j]
        ce, se = math.cos(phase), math.sin(phase)
        we = omega[i] - kx[i] * vx[j] - ky[i] * vy[j]
        wd = -(kx[i] * ax[j] + ky[i] * ay[j])
        fr, fi = -we * se, we * ce                                  # i w_e e^{i phi}
        gr, gi = -we * we * ce - wd * se, -we * we * se + wd * ce   # (i dw_e/dt - w_e^2) e^{i phi}
        for d in range(6):
            hr = hi = dhr = dhi = ddhr = ddhi = 0.0  # the knots' sums, real and imaginary parts apart
            for m in range(4):
                q = motion[k + m, i, d]
                qr, qi = q.real, q.imag
                hr += w[0, m] * qr
                hi += w[0, m] * qi
                dhr += w[1, m] * qr
                dhi += w[1, m] * qi
                ddhr += w[2, m] * qr
                ddhi += w[2, m] * qi
            acc[d] += hr * ce - hi * se
            acc[6 + d] += dhr * ce - dhi * se + hr * fr - hi * fi
            acc[12 + d] += ddhr * ce - ddhi * se + 2.0 * (dhr * fr - dhi * fi) + hr * gr - hi * gi
        a = amplitude[i]
        acc[18] += a.real * ce - a.imag * se
        for p in range(points):
            shifted = phase - kx[i] * px[j, p] - ky[i] * py[j, p]
            acc[19 + p] += a.real * math.cos(shifted) - a.imag * math.sin(shifted)
    out[rows[j], :] = acc


@compiled
def _sum(t, *rest):
    """:func:`_row` for each time step ``t`` (T,), one after another."""
    for j in range(t.size):
        _row(j, t, *rest)


@compiled(parallel=True)
def _sum_on_every_core(t, *rest):
    """:func:`_row` for each time step ``t`` (T,), the steps on every core."""
    for j in numba.prange(t.size):
        _row(np.int64(j), t, *rest)  # the serial driver's index type: one compiled kernel serves both
