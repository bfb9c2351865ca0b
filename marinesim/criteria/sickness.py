"""Motion sickness: the incidence of O'Hanlon & McCauley (1974) and the ISO 2631-1 dose value.

MSI (percentage of people who vomit within 2 h of vertical sinusoidal motion):
``MSI = 100 Phi(z)``, ``z = (log10(a/g) - mu) / 0.4``, ``mu = -0.819 + 2.32 (log10 w)^2`` with a the
mean absolute vertical acceleration (m/s^2) and w its frequency in rad/s. A revision of a widely
used MATLAB routine switched w to Hz and is wrong by orders of magnitude: a 1/6 Hz sinusoid of
amplitude 1 m/s^2 gives 17.8 % in rad/s, 0.0008 % in Hz. For an irregular record w is the
acceleration's mean zero-upcrossing frequency, sqrt(m2/m0) of its spectrum (Rice), the usual
choice in seakeeping (Lloyd, *Seakeeping*, 1989).

MSDV (ISO 2631-1:1997, 9.2.3): ``MSDV = sqrt(int a_w^2 dt)`` (m/s^1.5), a_w the vertical
acceleration weighted by W_f (Annex A, Tables A.1-A.2): a band limit between f1 = 0.08 Hz and
f2 = 0.63 Hz (Q = 1/sqrt 2), an acceleration-velocity transition at f4 = 0.25 Hz (Q4 = 0.86) and an
upward step from f5 = 0.0625 Hz to f6 = 0.1 Hz (Q5 = Q6 = 0.80):

    W_f(s) = s^2/(s^2 + w1 s/Q1 + w1^2) * w2^2/(s^2 + w2 s/Q2 + w2^2)
             * w4^2/(s^2 + w4 s/Q4 + w4^2) * (s^2 + w5 s/Q5 + w5^2)/(s^2 + w6 s/Q6 + w6^2)

|W_f| = 0.695 / 1.006 / 0.854 / 0.224 at 0.1 / 0.16 / 0.25 / 0.5 Hz.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ndtr

from marinesim.constants import G
from marinesim.criteria.statistics import mean_upcrossing_period
from marinesim.errors import ParameterError

F1, F2, F4, F5, F6 = 0.08, 0.63, 0.25, 0.0625, 0.1
"""W_f's corner frequencies (Hz)."""
Q1 = Q2 = 1.0 / math.sqrt(2.0)
Q4, Q5, Q6 = 0.86, 0.80, 0.80
MAX_WF_DT_S = 0.1
"""The coarsest time step the digital W_f takes (s): at 0.1 s its gain is within 0.1 % of the
analog one up to 0.25 Hz and 1 % at 0.5 Hz; at 0.25 s it would be 6 % low at 0.5 Hz."""


def msi_percent(mean_abs_acc_m_s2: float, omega_rad_s: float) -> float:
    """Motion sickness incidence (%) after 2 h of vertical motion of mean |acceleration| (m/s^2) at
    frequency ``omega_rad_s`` (rad/s)."""
    if mean_abs_acc_m_s2 <= 0.0:
        return 0.0
    mu = -0.819 + 2.32 * math.log10(omega_rad_s) ** 2
    return float(100.0 * ndtr((math.log10(mean_abs_acc_m_s2 / G) - mu) / 0.4))


def msi_of_record(az: np.ndarray, dt: float) -> float:
    """MSI (%) of a vertical acceleration record (m/s^2, every ``dt`` s): its mean |a| at its mean
    zero-upcrossing frequency; NaN with fewer than two upcrossings."""
    az = np.asarray(az, float)
    if az.size and not np.any(az):
        return 0.0
    period = mean_upcrossing_period(az, dt)
    return msi_percent(float(np.mean(np.abs(az))), 2.0 * math.pi / period) if math.isfinite(period) else math.nan


def _zpk(omega) -> tuple[np.ndarray, np.ndarray, float]:
    """W_f's zeros, poles and gain with the corner frequencies given by ``omega(f_hz)`` (rad/s)."""
    w1, w2, w4, w5, w6 = (omega(f) for f in (F1, F2, F4, F5, F6))

    def roots(w: float, q: float) -> np.ndarray:
        return np.roots([1.0, w / q, w * w])
    zeros = np.r_[0.0, 0.0, roots(w5, Q5)]
    poles = np.r_[roots(w1, Q1), roots(w2, Q2), roots(w4, Q4), roots(w6, Q6)]
    return zeros, poles, w2 * w2 * w4 * w4


def wf_response(f_hz: np.ndarray) -> np.ndarray:
    """W_f at frequencies ``f_hz`` (Hz): complex, the analog filter of ISO 2631-1."""
    zeros, poles, gain = _zpk(lambda f: 2.0 * math.pi * f)
    s = 2j * math.pi * np.asarray(f_hz, float)
    return gain * np.prod(s[..., None] - zeros, axis=-1) / np.prod(s[..., None] - poles, axis=-1)


class WfFilter:
    """W_f sampled every ``dt`` s (s <= :data:`MAX_WF_DT_S`): the bilinear transform of the analog
    filter, its corner frequencies pre-warped. :meth:`apply` carries the state from block to block,
    so a record filtered in blocks equals the record filtered at once."""

    def __init__(self, dt: float) -> None:
        from scipy import signal  # scipy.signal brings scipy.stats: only a dose needs it

        if not 0.0 < dt <= MAX_WF_DT_S:
            raise ParameterError(f"the W_f weighting needs a time step in 0..{MAX_WF_DT_S:g} s, got {dt!r}")
        fs = 1.0 / dt
        self._sos = signal.zpk2sos(*signal.bilinear_zpk(*_zpk(lambda f: 2.0 * fs * math.tan(math.pi * f / fs)), fs))
        self._state = np.zeros((self._sos.shape[0], 2))

    def apply(self, x: np.ndarray) -> np.ndarray:
        """The weighted acceleration (m/s^2) of the next samples ``x`` (m/s^2)."""
        from scipy.signal import sosfilt

        y, self._state = sosfilt(self._sos, np.asarray(x, float), zi=self._state)
        return y


def msdv(weighted_acc: np.ndarray, dt: float) -> float:
    """Motion sickness dose value ``sqrt(sum a_w^2 dt)`` (m/s^1.5) of a W_f-weighted record."""
    a = np.asarray(weighted_acc, float)
    return float(np.sqrt(np.sum(a * a) * dt))
