"""The criteria in the frequency domain: each quantity of :mod:`.quantities` estimated from response
spectra instead of a record, for many peak periods and headings at once (an operability study).

A response x (a DOF, or a point's motion) has the transfer function T_x(w, b) to the wave at the
reference point, b the wave's direction of travel relative to the bow (the RAO convention). In a
short-crested sea of directional spectrum S(w) D(t; w) met at the heading h, its spectral moments in
the encounter frequency w_e = w - U k cos b are

    m_n = int int |T_x(w, h + t)|^2 |w_e|^n S(w) D(t; w) dt dw

integrated over the *wave* frequency, so the encounter mapping needs no Jacobian and a following sea
where several w share one w_e is counted correctly (the variance is that of the wave components).
The response series (small angles, as the criteria read them; REFERENCES section 8):

- a point p's vertical motion ``z = x3 + y_p x4 - x_p x5``, its velocity ``i w_e z``, acceleration ``-w_e^2 z``;
- its lateral specific force in the deck frame ``a_y + g x4`` with ``a_y = -w_e^2 (x2 + x_p x6 - z_p x4)``
  (static roll phi gives g sin phi, :mod:`.interruptions`);
- its motion relative to the incident wave at its mean position, ``z - exp(-i k (x_p cos b + y_p sin b))`` (the
  relative velocity's variance is that series' m2);
- the W_f-weighted vertical acceleration, ``|W_f(w_e / 2 pi)|^2`` on the acceleration's spectrum.

Short-term statistics of a zero-mean Gaussian response (sigma = sqrt(m0), Tz = 2 pi sqrt(m0 / m2)):

| quantity | spectral estimate | in Hs |
|---|---|---|
| ``*_rms_*``, ``lateral_acc_rms_m_s2`` | sigma | linear |
| ``roll_max_deg``, ``pitch_max_deg``, ``vertical_velocity_max_m_s`` | most probable maximum in the window, sigma sqrt(2 ln N), N = window / Tz (at least 2) | linear |
| ``inclination_max_deg`` | the same with sigma^2 = sigma_roll^2 + sigma_pitch^2 (approximation: the tilt's magnitude is not Gaussian; slightly conservative) | linear |
| ``heave_rate_significant_m_s`` | 2 sigma of the vertical velocity | linear |
| ``mahr_m_s`` | most probable largest oscillation height 2 sigma sqrt(2 ln N) over half of Tz (narrow band) | linear |
| ``relative_motion_exceedance`` | exp(-threshold^2 / (2 sigma^2)) (the record's formula) | not linear: limiting Hs in closed form |
| ``slamming_probability`` | exp(-threshold^2 / (2 m0) - threshold_velocity^2 / (2 m2)) (the record's formula) | not linear: limiting Hs in closed form |
| ``msi_pct`` | O'Hanlon & McCauley of mean abs(a) = sigma_a sqrt(2/pi) at sqrt(m2/m0) of the acceleration | not linear: limiting Hs in closed form |
| ``msdv_m_s1_5`` | sqrt(duration x m0 of the W_f-weighted acceleration) | linear |
| ``mii_per_min`` | none: interruptions count level crossings of a ratio of forces; run the time-domain check | - |
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.special import ndtri

from marinesim.constants import G
from marinesim.criteria.monitor import Criterion
from marinesim.criteria.sickness import msi_percent, wf_response
from marinesim.errors import ParameterError
from marinesim.sea.dispersion import k_from_omega
from marinesim.sea.seastate import WaveSystem
from marinesim.sea.spreading import LongCrested
from marinesim.vessel.rao import RaoTable

OMEGA_SPAN = (0.25, 10.0)
"""The quadrature's wave frequencies span these multiples of the lowest and highest peak frequency: the
spectrum below 0.25 w_p is nil and above 10 w_p holds 1e-4 of its variance (the w^-5 tail)."""
OMEGA_POINTS = 800
"""Log-spaced wave frequencies of the quadrature: a step of 0.6 % of w for Tp 2 to 25 s."""
SPREAD = np.radians(np.arange(-180.0, 180.0, 2.5))
"""Directions about the mean wave direction (rad) of a short-crested sea's quadrature."""
DEG = 180.0 / math.pi
LINEAR = {"roll_rms_deg", "pitch_rms_deg", "heave_rms_m", "vertical_acc_rms_m_s2", "lateral_acc_rms_m_s2",
          "roll_max_deg", "pitch_max_deg", "vertical_velocity_max_m_s", "inclination_max_deg",
          "heave_rate_significant_m_s", "mahr_m_s", "msdv_m_s1_5"}
EXCEEDANCES = {"relative_motion_exceedance", "slamming_probability"}
"""Probabilities ``exp(-E / (2 Hs^2))`` of the relative motion, E = threshold^2 / m0 (+ threshold_velocity^2 / m2 for
slamming) with the moments at Hs 1 m."""
NONLINEAR = EXCEEDANCES | {"msi_pct"}
"""Quantities the frequency domain estimates: proportional to Hs, or not (solved for the limiting Hs)."""


@dataclass(frozen=True)
class SpectralCriteria:
    """The criteria of a study at Hs = 1 m: ``value1`` (T, H, C) in each criterion's unit, and what the
    nonlinear ones need beyond it: ``sigma1`` (T, H, C) the standard deviation of the criterion's series
    and ``omega`` (T, H, C) its mean zero-upcrossing frequency (rad/s)."""

    criteria: tuple[Criterion, ...]
    value1: np.ndarray
    sigma1: np.ndarray
    omega: np.ndarray

    def moments1(self, c: int) -> tuple[np.ndarray, np.ndarray]:
        """m0, m2 (T, H) of criterion ``c``'s series at Hs 1 m (m2 nil where m0 is)."""
        m0 = self.sigma1[..., c] ** 2
        return m0, np.where(m0 > 0, m0 * self.omega[..., c] ** 2, 0.0)

    def value(self, hs: np.ndarray) -> np.ndarray:
        """Each criterion's value in seas of ``hs`` (T, H) m: (T, H, C)."""
        hs = np.asarray(hs, float)
        out = self.value1 * hs[..., None]
        for c, criterion in enumerate(self.criteria):
            if criterion.quantity in NONLINEAR:
                m0, m2 = self.moments1(c)
                out[..., c] = value_from_moments(criterion, m0 * hs ** 2, m2 * hs ** 2, duration_s=0.0)
        return out

    def limiting_hs(self, limits: np.ndarray) -> np.ndarray:
        """The largest Hs (m) within each criterion's limit (C,): (T, H, C); inf where nothing limits."""
        limits = np.asarray(limits, float)
        with np.errstate(divide="ignore", invalid="ignore"):
            out = np.where(self.value1 > 0, limits / self.value1, np.inf)
            for c, criterion in enumerate(self.criteria):
                sigma, limit = self.sigma1[..., c], limits[c]
                if criterion.quantity in EXCEEDANCES:
                    # exp(-E / (2 Hs^2)) <= p  <=>  Hs <= sqrt(E / (2 ln(1/p)))
                    out[..., c] = (np.inf if limit >= 1.0 else
                                   np.sqrt(_exponent(criterion, *self.moments1(c)) / (2.0 * math.log(1.0 / limit))))
                elif criterion.quantity == "msi_pct":
                    # 100 Phi((log10(a/g) - mu) / 0.4) <= MSI  <=>  a <= g 10^(mu + 0.4 Phi^-1(MSI / 100))
                    mu = -0.819 + 2.32 * np.log10(self.omega[..., c]) ** 2
                    z = ndtri(min(limit, 100.0) / 100.0) if limit < 100.0 else np.inf
                    out[..., c] = G * 10.0 ** (mu + 0.4 * z) / (sigma * math.sqrt(2.0 / math.pi))
        return np.where(np.isnan(out), np.inf, out)


def criteria_at_unit_hs(rao: RaoTable, points: dict[str, tuple[float, float, float]], speed_m_s: float,
                        criteria: list[Criterion], system: WaveSystem, depth_m: float, tp: np.ndarray,
                        headings_deg: np.ndarray, duration_s: float) -> SpectralCriteria:
    """Every criterion in seas of Hs 1 m shaped as ``system`` (its spectrum's gamma, its spreading) at each
    peak period ``tp`` (T,) s, met at each relative heading ``headings_deg`` (H,) (the RAO convention),
    by a vessel (``rao``, body-frame ``points`` m, ``speed_m_s``); ``duration_s`` is the exposure of a dose."""
    unknown = [c.label for c in criteria if c.quantity not in LINEAR | NONLINEAR]
    if unknown:
        raise ParameterError(f"no frequency-domain estimate for {', '.join(unknown)} (interruptions count "
                             f"level crossings of a force ratio): leave it out of the study")
    tp, headings = np.asarray(tp, float), np.asarray(headings_deg, float)
    if tp.size == 0 or not np.all(tp > 0):
        raise ParameterError("the study needs peak periods > 0 s")
    omega = np.geomspace(OMEGA_SPAN[0] * 2 * math.pi / tp.max(), OMEGA_SPAN[1] * 2 * math.pi / tp.min(), OMEGA_POINTS)
    spread = np.array([0.0]) if isinstance(system.spreading, LongCrested) else SPREAD
    dtheta = 1.0 if spread.size == 1 else SPREAD[1] - SPREAD[0]
    domega = trapezoid_weights(omega)
    weight = np.stack([_directional(system, t, omega, spread) for t in tp]) * (domega[:, None] * dtheta)  # (T, W, D)
    k = k_from_omega(omega, depth_m, rao.g)
    shape = (tp.size, headings.size, len(criteria))
    value1, sigma1, upcrossing = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    for h, heading in enumerate(headings):
        beta = math.radians(heading) + spread                                                # (D,)
        grid_w, grid_b = np.meshgrid(omega, beta, indexing="ij")
        x = rao(grid_w.ravel(), grid_b.ravel(), speed_m_s).reshape(omega.size, beta.size, 6)  # (W, D, 6)
        omega_e = encounter_frequency(omega, k, beta, speed_m_s)                             # (W, D)
        series = ResponseSeries(x, omega_e, k, beta, points, weight)
        for c, criterion in enumerate(criteria):
            value1[:, h, c], sigma1[:, h, c], upcrossing[:, h, c] = _estimate(criterion, series, duration_s)
    return SpectralCriteria(tuple(criteria), value1, sigma1, upcrossing)


def trapezoid_weights(omega: np.ndarray) -> np.ndarray:
    """The trapezoid rule's weights (rad/s) on the increasing frequencies ``omega`` (W,)."""
    out = np.gradient(omega)
    out[[0, -1]] *= 0.5
    return out


def encounter_frequency(omega: np.ndarray, k: np.ndarray, beta: np.ndarray, speed_m_s: float) -> np.ndarray:
    """``|w - U k cos b|`` (W, D), rad/s, of waves ``omega`` (W,) of wave number ``k`` (W,) met at relative headings
    ``beta`` (D,) rad by a vessel at ``speed_m_s``."""
    return np.abs(omega[:, None] - speed_m_s * k[:, None] * np.cos(beta)[None, :])


def _directional(system: WaveSystem, tp: float, omega: np.ndarray, spread: np.ndarray) -> np.ndarray:
    """S(w) D(t; w) (W, D) of ``system`` with Hs 1 m and peak period ``tp`` at ``omega`` (W,) rad/s and
    ``spread`` (D,) rad about its mean direction."""
    spectrum = replace(system.spectrum, hs=1.0, tp=float(tp))
    density = spectrum.density(omega)
    if spread.size == 1:
        return density[:, None]
    shaped = WaveSystem(spectrum, 0.0, system.spreading)
    grid_w, grid_t = np.meshgrid(omega, spread, indexing="ij")
    return shaped.directional_density(grid_w, grid_t)


class ResponseSeries:
    """The transfer functions of one heading (W, D) and their spectral moments (T,) over ``weight``."""

    def __init__(self, x: np.ndarray, omega_e: np.ndarray, k: np.ndarray, beta: np.ndarray,
                 points: dict[str, tuple[float, float, float]], weight: np.ndarray) -> None:
        self.x, self.omega_e, self.k, self.beta, self.points, self.weight = x, omega_e, k, beta, points, weight

    def moments(self, transfer: np.ndarray, orders: tuple[int, ...] = (0, 2)) -> list[np.ndarray]:
        """m_n (T,) of the series of ``transfer`` (W, D) for each n in ``orders``."""
        power = np.abs(transfer) ** 2
        return [np.einsum("wd,twd->t", power * self.omega_e ** n, self.weight) for n in orders]

    def dof(self, j: int) -> np.ndarray:
        return self.x[..., j] * (DEG if j >= 3 else 1.0)

    def vertical(self, point: str) -> np.ndarray:
        px, py, _ = self.points[point]
        return self.x[..., 2] + py * self.x[..., 3] - px * self.x[..., 4]

    def lateral_force(self, point: str) -> np.ndarray:
        px, _, pz = self.points[point]
        sway = self.x[..., 1] + px * self.x[..., 5] - pz * self.x[..., 3]
        return -self.omega_e ** 2 * sway + G * self.x[..., 3]

    def relative(self, point: str) -> np.ndarray:
        px, py, _ = self.points[point]
        wave = np.exp(-1j * self.k[:, None] * (px * np.cos(self.beta) + py * np.sin(self.beta))[None, :])
        return self.vertical(point) - wave


def _mpm(m0: np.ndarray, m2: np.ndarray, window_s: float) -> np.ndarray:
    """Most probable maximum of a Gaussian response over ``window_s``: sigma sqrt(2 ln N), N = window / Tz >= 2."""
    with np.errstate(divide="ignore", invalid="ignore"):
        count = np.where(m2 > 0, window_s / (2.0 * math.pi * np.sqrt(m0 / m2)), 2.0)
    return np.sqrt(m0) * np.sqrt(2.0 * np.log(np.maximum(count, 2.0)))


def transfers(criterion: Criterion, s: ResponseSeries) -> list[np.ndarray]:
    """The transfer functions (W, D) of ``criterion``'s series to the wave, whose spectral moments add up to the
    series' (one, or roll and pitch for the inclination)."""
    q, p = criterion.quantity, criterion.point
    if q in ("roll_rms_deg", "pitch_rms_deg", "heave_rms_m", "roll_max_deg", "pitch_max_deg"):
        return [s.dof({"roll": 3, "pitch": 4, "heave": 2}[q.split("_")[0]])]
    if q == "inclination_max_deg":
        return [s.dof(3), s.dof(4)]
    if q in ("vertical_acc_rms_m_s2", "msi_pct"):
        return [-s.omega_e ** 2 * s.vertical(p)]
    if q == "msdv_m_s1_5":
        return [-s.omega_e ** 2 * s.vertical(p) * wf_response(s.omega_e / (2.0 * math.pi))]
    if q in ("vertical_velocity_max_m_s", "heave_rate_significant_m_s"):
        return [1j * s.omega_e * s.vertical(p)]
    if q == "mahr_m_s":
        return [s.vertical(p)]
    if q == "lateral_acc_rms_m_s2":
        return [s.lateral_force(p)]
    return [s.relative(p)]  # relative_motion_exceedance, slamming_probability


def value_from_moments(criterion: Criterion, m0: np.ndarray, m2: np.ndarray, duration_s: float) -> np.ndarray:
    """``criterion``'s spectral estimate (the table above) from the moments m0, m2 of its series (any shape);
    ``duration_s`` the exposure of a dose (s)."""
    q, window = criterion.quantity, criterion.window
    m0, m2 = np.asarray(m0, float), np.asarray(m2, float)
    sigma = np.sqrt(m0)
    with np.errstate(divide="ignore", invalid="ignore"):
        omega = np.where(m0 > 0, np.sqrt(m2 / m0), np.nan)
    if q.endswith("_max_deg") or q == "vertical_velocity_max_m_s":
        return _mpm(m0, m2, window)
    if q == "heave_rate_significant_m_s":
        return 2.0 * sigma
    if q == "mahr_m_s":
        return 2.0 * _mpm(m0, m2, window) / (np.pi / np.where(omega > 0, omega, np.inf))
    if q == "msdv_m_s1_5":
        return np.sqrt(duration_s * m0)
    if q in EXCEEDANCES:
        return np.exp(-0.5 * _exponent(criterion, m0, m2))
    if q == "msi_pct":
        return np.vectorize(lambda a, w: msi_percent(a, w) if np.isfinite(w) else 0.0, otypes=[float])(
            sigma * math.sqrt(2.0 / math.pi), omega)
    return sigma


def _exponent(criterion: Criterion, m0: np.ndarray, m2: np.ndarray) -> np.ndarray:
    """E of an exceedance (:data:`EXCEEDANCES`), its probability being ``exp(-E / 2)``: ``threshold_m^2 / m0``, plus
    ``threshold_velocity_m_s^2 / m2`` for slamming (Rice: the relative motion and its rate are independent Gaussians
    of variances m0, m2); inf where a moment is nil."""
    options = criterion.options
    with np.errstate(divide="ignore"):
        exponent = options.threshold_m ** 2 / m0
        if criterion.quantity == "slamming_probability":
            exponent = exponent + options.threshold_velocity_m_s ** 2 / m2
    return exponent


def _estimate(criterion: Criterion, s: ResponseSeries, duration_s: float
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(value at Hs 1 m, sigma of its series, the series' zero-upcrossing frequency), each (T,)."""
    moments = [s.moments(transfer) for transfer in transfers(criterion, s)]
    m0, m2 = sum(m[0] for m in moments), sum(m[1] for m in moments)
    with np.errstate(divide="ignore", invalid="ignore"):
        omega = np.where(m0 > 0, np.sqrt(m2 / m0), np.nan)
    return value_from_moments(criterion, m0, m2, duration_s), np.sqrt(m0), omega
