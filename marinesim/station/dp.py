"""The dynamic positioning computer: an observer, a reference model and a PID controller with wind feed-forward.

All in the horizontal plane, axes as :mod:`marinesim.manoeuvring.state`: positions ``eta`` = (north, east, psi)
(m, m, rad clockwise from north), velocities ``nu`` = (u, v, r) in body axes (m/s, m/s, rad/s), forces ``tau`` =
(X, Y, N) (N, N, N m); ``R(psi)`` turns body into earth axes. ``M`` and ``D`` (3, 3) are the vessel's
low-frequency mass (with added mass) and linear damping.

- **Observer** (Fossen & Strand 1999, the nonlinear passive observer; Fossen 2021, sec. 13.4): the measured
  position ``y`` is the low-frequency position plus the wave-frequency motion; a second-order wave model per
  degree of freedom (``xi``, peak ``omega_0``, damping ``zeta``) takes the wave-frequency part out, a bias ``b``
  (earth axes) takes the slowly varying environment, and the estimates ``eta_hat``, ``nu_hat`` follow the vessel's
  own equations::

      y~ = y - eta_hat - xi_2
      xi_1' = xi_2 + K1a y~,  xi_2' = -omega_0^2 xi_1 - 2 zeta omega_0 xi_2 + K1b y~
      eta_hat' = R nu_hat + K2 y~,  b' = -b / T_b + K3 y~,  M nu_hat' = -D nu_hat + R^T b + tau + R^T K4 y~

  with ``K1a = -2 (zeta_n - zeta) omega_c / omega_0``, ``K1b = 2 omega_0 (zeta_n - zeta)``, ``K2 = omega_c`` (the
  notch of depth ``zeta / zeta_n`` at ``omega_0``, cut-off ``omega_c`` above it) and ``K4``, ``K3 = K4 / 10``
  from the low-frequency loop's own bandwidth. Stepped by forward Euler at the DP computer's cycle.
- **Reference model**: the set point moves to an ordered position at no more than ``speed_limit`` and to an
  ordered heading at no more than ``rate_limit`` (DP operators move a vessel at 0.1 to 0.5 m/s, 10 deg/min); or,
  turning about a pivot (a shuttle tanker's DP weathervaning about the FPSO's stern), along the arc about it.
- **Controller** (Fossen 2021, sec. 12.2.6): ``tau = -R^T (Kp e + Ki z) - Kd nu_hat - tau_wind``, ``e`` the
  estimated position less the set point (heading wrapped), ``z' = e`` (held while the thrusters saturate), by pole
  placement per degree of freedom: ``Kp = M w_n^2``, ``Kd = 2 zeta w_n M - D``, ``Ki = w_n / 10 Kp``; ``tau_wind``
  the wind's load from the measured wind and the vessel's own coefficients (feed-forward).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.compiled import compiled
from marinesim.manoeuvring.autopilot import wrap

OBSERVER_ZETA = 0.1
OBSERVER_ZETA_N = 1.0
"""The wave model's relative damping and the notch's (Fossen & Strand 1999)."""


def rotation(psi: float) -> np.ndarray:
    """``R(psi)`` (3, 3): body (u, v, r) to earth (north, east, psi) rates."""
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@dataclass(frozen=True)
class Tuning:
    """The DP's tuning: the closed loop's natural periods (s) in surge, sway, yaw, its relative damping, the
    observer's wave peak frequency (rad/s), the bias time constant (s), and the reference model's limits (m/s,
    rad/s)."""

    periods_s: tuple[float, float, float] = (100.0, 100.0, 80.0)
    zeta: float = 0.9
    wave_omega: float = 2.0 * math.pi / 9.0
    bias_time_s: float = 1000.0
    speed_limit: float = 0.3
    rate_limit: float = math.radians(10.0 / 60.0)


class Dp:
    """The DP computer for a vessel of low-frequency mass ``m`` and damping ``d`` (3, 3) with ``tuning``."""

    def __init__(self, m: np.ndarray, d: np.ndarray, tuning: Tuning) -> None:
        self.m, self.d, self.tuning = np.ascontiguousarray(m, float), np.ascontiguousarray(d, float), tuning
        self.m_inv = np.linalg.inv(self.m)
        wn = np.array([2.0 * math.pi / p for p in tuning.periods_s])
        mdiag = np.diag(self.m)
        self.kp = mdiag * wn**2
        self.kd = np.maximum(2.0 * tuning.zeta * wn * mdiag - np.diag(self.d), 0.0)
        self.ki = wn / 10.0 * self.kp
        w0 = tuning.wave_omega
        wc = 1.1 * w0
        self.k1a = np.full(3, -2.0 * (OBSERVER_ZETA_N - OBSERVER_ZETA) * wc / w0)
        self.k1b = np.full(3, 2.0 * w0 * (OBSERVER_ZETA_N - OBSERVER_ZETA))
        self.k2 = np.full(3, wc)
        band = 4.0 * wn  # the observer's low-frequency loop: some times faster than the controller's
        self.k4 = mdiag * band**2
        self.k3 = self.k4 / 10.0
        self._observer_gains = np.array([self.k1a, self.k1b, self.k2, self.k3, self.k4])
        """(5, 3): K1a, K1b, K2, K3, K4 as :func:`_observed` reads them (read-only: set once from the tuning)."""
        self._observer_gains.flags.writeable = False

    def observe(self, est: np.ndarray, y: np.ndarray, tau: np.ndarray, h: float) -> np.ndarray:
        """The observer's state (15,: xi_1 (3), xi_2 (3), eta_hat (3), nu_hat (3), b (3)) ``h`` s after ``est``,
        given the measured position ``y`` (north m, east m, psi rad) and the thrust ``tau`` (3,) acting."""
        return _observed(np.asarray(est, float), np.asarray(y, float), np.asarray(tau, float), float(h),
                         float(self.tuning.wave_omega), float(self.tuning.bias_time_s), self._observer_gains,
                         self.m_inv, self.d)

    def reference(self, ref: np.ndarray, target: tuple[float, float, float], h: float) -> np.ndarray:
        """The set point (north, east, psi) ``h`` s after ``ref``, moving towards ``target`` within the limits."""
        return _referenced(np.asarray(ref, float), float(target[0]), float(target[1]), float(target[2]), float(h),
                           float(self.tuning.speed_limit), float(self.tuning.rate_limit))

    def reference_about(self, ref: np.ndarray, pivot: tuple[float, float, float, float], course: float, h: float
                        ) -> np.ndarray:
        """The set point (north, east, psi) ``h`` s after ``ref``, its heading turning towards ``course`` (rad,
        unwrapped near ``ref``'s) about ``pivot`` = (north m, east m, x m, y m): the point (north, east) keeps its
        place (x forward, y to starboard) in her body frame, so the set point sweeps an arc about it, at no more than
        ``rate_limit`` nor ``speed_limit`` along the arc."""
        north, east, x, y = pivot
        radius = math.hypot(x, y)
        rate = self.tuning.rate_limit if radius == 0.0 else min(self.tuning.rate_limit,
                                                                 self.tuning.speed_limit / radius)
        psi = ref[2] + max(min(wrap(course - ref[2]), rate * h), -rate * h)
        c, s = math.cos(psi), math.sin(psi)
        return np.array([north - (x * c - y * s), east - (x * s + y * c), psi])

    def command(self, est: np.ndarray, ref: np.ndarray, integral: np.ndarray, wind: np.ndarray
                ) -> np.ndarray:
        """The thrust demanded (X, Y, N) from the estimate ``est`` (observer state), the set point ``ref``, the
        integral of the error ``integral`` (earth axes) and the wind's load ``wind`` (body, (3,))."""
        return _commanded(np.asarray(est, float), np.asarray(ref, float), np.asarray(integral, float),
                          np.asarray(wind, float), self.kp, self.ki, self.kd)

    @staticmethod
    def error(est: np.ndarray, ref: np.ndarray) -> np.ndarray:
        """The estimated position less the set point (north m, east m, psi rad wrapped)."""
        return _error(np.asarray(est, float), np.asarray(ref, float))


# The observer's and the controller's arithmetic (the module docstring's equations), compiled: the DP computer runs
# every 0.1 s step of a station-keeping vessel. Within 1e-15 relative of numpy's products (their sums' order differs).

_wrapped = compiled(wrap)
"""The autopilot's :func:`~marinesim.manoeuvring.autopilot.wrap` (``angle`` rad to [-pi, pi)), compiled from its own
code for the functions below."""


@compiled
def _error(est: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """:meth:`Dp.error`: ``eta_hat - ref`` (3,), the heading wrapped."""
    e = est[6:9] - ref
    e[2] = _wrapped(e[2])
    return e


@compiled
def _referenced(ref: np.ndarray, north: float, east: float, psi: float, h: float, speed_limit: float,
                rate_limit: float) -> np.ndarray:
    """:meth:`Dp.reference`: the set point (3,) ``h`` s after ``ref`` towards (``north``, ``east``, ``psi``)."""
    out = ref.copy()
    gap_north, gap_east = north - ref[0], east - ref[1]
    distance = math.hypot(gap_north, gap_east)
    step = speed_limit * h
    if distance <= step:
        out[0], out[1] = north, east
    else:
        out[0], out[1] = ref[0] + gap_north * step / distance, ref[1] + gap_east * step / distance
    out[2] = ref[2] + max(min(_wrapped(psi - ref[2]), rate_limit * h), -rate_limit * h)
    return out


@compiled
def _commanded(est: np.ndarray, ref: np.ndarray, integral: np.ndarray, wind: np.ndarray, kp: np.ndarray,
               ki: np.ndarray, kd: np.ndarray) -> np.ndarray:
    """:meth:`Dp.command`: ``-R^T (Kp e + Ki z) - Kd nu_hat - tau_wind`` (3,)."""
    e = _error(est, ref)
    c, s = math.cos(est[8]), math.sin(est[8])
    p = kp * e + ki * integral
    return np.array([-(c * p[0] + s * p[1]), -(-s * p[0] + c * p[1]), -p[2]]) - kd * est[9:12] - wind


@compiled
def _observed(est: np.ndarray, y: np.ndarray, tau: np.ndarray, h: float, w0: float, bias_time: float,
              gains: np.ndarray, m_inv: np.ndarray, d: np.ndarray) -> np.ndarray:
    """:meth:`Dp.observe`: the observer's 15 states ``h`` s on (forward Euler); ``gains`` (5, 3) K1a, K1b, K2, K3,
    K4."""
    xi1, xi2, eta, nu, b = est[0:3], est[3:6], est[6:9], est[9:12], est[12:15]
    miss = y - eta - xi2
    miss[2] = _wrapped(miss[2])
    c, s = math.cos(eta[2]), math.sin(eta[2])
    k4 = gains[4] * miss
    body = np.array([c * (b[0] + k4[0]) + s * (b[1] + k4[1]), -s * (b[0] + k4[0]) + c * (b[1] + k4[1]),
                     b[2] + k4[2]])                                       # R^T (b + K4 y~)
    rates = np.empty(15)
    rates[0:3] = xi2 + gains[0] * miss
    rates[3:6] = -w0 * w0 * xi1 - 2.0 * OBSERVER_ZETA * w0 * xi2 + gains[1] * miss
    rates[6] = c * nu[0] - s * nu[1] + gains[2, 0] * miss[0]
    rates[7] = s * nu[0] + c * nu[1] + gains[2, 1] * miss[1]
    rates[8] = nu[2] + gains[2, 2] * miss[2]
    rates[12:15] = -b / bias_time + gains[3] * miss
    force = body + tau
    for i in range(3):
        force[i] -= d[i, 0] * nu[0] + d[i, 1] * nu[1] + d[i, 2] * nu[2]
    for i in range(3):
        rates[9 + i] = m_inv[i, 0] * force[0] + m_inv[i, 1] * force[1] + m_inv[i, 2] * force[2]
    return est + h * rates
