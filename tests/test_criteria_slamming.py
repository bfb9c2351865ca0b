"""The slamming probability (Ochi 1964, NORDFORSK 1987): the forefoot emerges and the relative velocity at the crossing
exceeds a threshold. Checked against slams counted on a long Gaussian record, against the emergence probability it
refines, in the frequency domain (value and limiting Hs), and for its refusals of bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from conftest import ROOT, VESSEL_SCENARIO, cli, write
from marinesim.constants import G
from marinesim.criteria.monitor import Criterion
from marinesim.criteria.quantities import QUANTITIES, Options
from marinesim.criteria.spectral import criteria_at_unit_hs, value_from_moments
from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario
from marinesim.sea.build import wave_system
from marinesim.vessel import read_rao

HS, TP = 4.0, 10.0
BAND = (0.3, 2.0)
"""The record's spectrum: Pierson-Moskowitz of HS m, TP s, cut to this band of angular frequency (rad/s)."""
DT = 0.1
COMPONENTS = 400
OSCILLATIONS = 25_000


def spectrum(omega: np.ndarray | float) -> np.ndarray | float:
    """Pierson-Moskowitz S(w) (m^2 s/rad) of HS, TP: ``5/16 Hs^2 wp^4 w^-5 exp(-5/4 (wp/w)^4)``."""
    wp = 2.0 * math.pi / TP
    return 5.0 / 16.0 * HS ** 2 * wp ** 4 * omega ** -5.0 * np.exp(-1.25 * (wp / omega) ** 4)


def moments() -> tuple[float, float]:
    """m0 (m^2) and m2 (m^2/s^2) of :func:`spectrum` over BAND, by adaptive quadrature."""
    return tuple(quad(lambda w, n=n: w ** n * spectrum(w), *BAND, limit=200)[0] for n in (0, 2))


def gaussian_record(seed: int = 7) -> tuple[np.ndarray, np.ndarray]:
    """A relative motion record r (m) and its exact rate (m/s), every DT s, long enough for OSCILLATIONS
    zero-upcrossings: COMPONENTS random-phase sinusoids, one at a random frequency in each of equal bins of BAND
    (so the record never repeats), of amplitude ``sqrt(2 S(w) dw)``."""
    rng = np.random.default_rng(seed)
    edges = np.linspace(*BAND, COMPONENTS + 1)
    omega = rng.uniform(edges[:-1], edges[1:])
    coefficients = np.sqrt(2.0 * spectrum(omega) * np.diff(edges)) * np.exp(2j * math.pi * rng.uniform(size=omega.size))
    m0, m2 = moments()
    steps = int(OSCILLATIONS * 2.0 * math.pi * math.sqrt(m0 / m2) / DT)
    block = 4096
    table = np.exp(1j * np.outer(np.arange(block) * DT, omega))                      # (block, components)
    r, v = np.empty(steps), np.empty(steps)
    for lo in range(0, steps, block):
        n = min(block, steps - lo)
        shifted = coefficients * np.exp(1j * omega * lo * DT)
        both = table[:n] @ np.stack([shifted, 1j * omega * shifted], axis=1)
        r[lo:lo + n], v[lo:lo + n] = both.real.T
    return r, v


def counted(r: np.ndarray, v: np.ndarray, level: float, speed: float) -> tuple[int, int]:
    """(upcrossings of ``level`` whose rate, interpolated at the crossing, exceeds ``speed``; zero-upcrossings)."""
    up = np.flatnonzero((r[:-1] < level) & (r[1:] >= level))
    at = (level - r[up]) / (r[up + 1] - r[up])
    rate = v[up] + at * (v[up + 1] - v[up])
    return int(np.count_nonzero(rate > speed)), int(np.count_nonzero((r[:-1] < 0.0) & (r[1:] >= 0.0)))


@pytest.fixture(scope="module")
def record() -> tuple[np.ndarray, np.ndarray]:
    return gaussian_record()


def slamming(threshold_m: float, velocity: float, limit: float | None = None) -> Criterion:
    return Criterion("slamming_probability", limit, point="forefoot",
                     options=Options(threshold_m=threshold_m, threshold_velocity_m_s=velocity))


def emergence(threshold_m: float, limit: float | None = None) -> Criterion:
    return Criterion("relative_motion_exceedance", limit, point="forefoot", options=Options(threshold_m=threshold_m))


def test_the_slamming_probability_is_the_share_of_oscillations_that_slam(record):
    """Slams counted on a record of more than 20,000 oscillations (upcrossings of T = 1.5 sigma_r with the rate
    above 1.2 sigma_v, over the zero-upcrossings) agree within 4 binomial standard errors with the quantity on that
    record and with the spectral estimate of its spectrum. If this fails, the formula is not Rice's rate of fast
    crossings (a lost velocity factor gives about twice the count), or the record's rate is wrong."""
    r, v = record
    m0, m2 = moments()
    threshold, speed = 1.5 * math.sqrt(m0), 1.2 * math.sqrt(m2)
    slams, oscillations = counted(r, v, threshold, speed)
    assert oscillations >= 20_000
    share = slams / oscillations
    error = math.sqrt(share * (1.0 - share) / oscillations)
    on_record = QUANTITIES["slamming_probability"].value([r], DT, slamming(threshold, speed).options)
    spectral = float(value_from_moments(slamming(threshold, speed), m0, m2, duration_s=0.0))
    assert abs(on_record - share) < 4.0 * error, (on_record, share, error)
    assert abs(spectral - share) < 4.0 * error, (spectral, share, error)
    assert share < float(value_from_moments(emergence(threshold), m0, m2, 0.0)) - 20.0 * error, \
        "the velocity condition must remove the slow crossings"


def test_slamming_is_the_emergence_times_the_velocity_factor(record):
    """On the record and in the frequency domain, slamming over emergence is exp(-v^2 / (2 sigma_v^2)), sigma_v the
    RMS of the exact rate (m2 in the frequency domain). If this fails, the record's finite-difference rate is
    biased, or the two probabilities do not share their emergence term."""
    r, v = record
    threshold, speed = 2.0, 1.5
    ratio = (QUANTITIES["slamming_probability"].value([r], DT, slamming(threshold, speed).options)
             / QUANTITIES["relative_motion_exceedance"].value([r], DT, emergence(threshold).options))
    assert ratio == pytest.approx(math.exp(-speed ** 2 / (2.0 * np.mean(v * v))), rel=1e-4)
    m0, m2 = np.array([0.5, 1.0, 4.0]), np.array([0.3, 0.9, 2.0])
    np.testing.assert_allclose(value_from_moments(slamming(threshold, speed), m0, m2, 0.0),
                               value_from_moments(emergence(threshold), m0, m2, 0.0) * np.exp(-speed ** 2 / (2 * m2)),
                               rtol=1e-12)


def test_the_limiting_hs_gives_the_limit_back():
    """The closed-form limiting Hs of the slamming and emergence probabilities at the forefoot of the tanker (L 252 m,
    draft 10 m) at 5 m/s, fed back to
    SpectralCriteria.value, gives each limit; slightly below it the value is within the limit. If this fails, the
    closed form and the estimate disagree (a wrong moment at Hs 1 m, or the velocity term left out of one)."""
    rao = read_rao(ROOT / "rao" / "tanker" / "tanker.4")
    criteria = [Criterion("slamming_probability", 0.0225, point="bow",
                          options=Options(threshold_m=9.0, threshold_velocity_m_s=0.093 * math.sqrt(G * 252.0))),
                Criterion("relative_motion_exceedance", 0.0225, point="bow", options=Options(threshold_m=9.0))]
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0, gamma=3.3, spreading_s=10.0)
    estimates = criteria_at_unit_hs(rao, {"bow": (125.0, 0.0, -9.0)}, 5.0, criteria, system, math.inf,
                                    np.array([7.0, 10.0, 14.0]), np.array([180.0, 150.0]), 600.0)
    limits = np.array([c.limit for c in criteria])
    hs = estimates.limiting_hs(limits)
    assert np.all(np.isfinite(hs)) and np.all(hs[..., 0] > hs[..., 1]), "slamming needs a higher sea than emergence"
    for c in range(len(criteria)):
        np.testing.assert_allclose(estimates.value(hs[..., c])[..., c], limits[c], rtol=1e-9)
        assert np.all(estimates.value(0.99 * hs[..., c])[..., c] < limits[c])


SLAMMING = """
[[criteria]]
name = "slamming"
point = "bow"
quantity = "slamming_probability"
threshold_m = 9.0
limit = 0.0225
"""


def test_the_threshold_velocity_is_ochis_for_the_ships_length():
    """The S175 scenario's slamming criterion takes v_th = 0.093 sqrt(g L) with L her hull's length: within 2 % of
    175 m's (her length between perpendiculars). If this fails, the default reads another length or formula."""
    criterion = next(c for c in load_scenario(ROOT / "configs" / "s175_heavy_weather.toml").criteria
                     if c.quantity == "slamming_probability")
    assert criterion.options.threshold_velocity_m_s == pytest.approx(0.093 * math.sqrt(G * 175.0), rel=0.02)


@pytest.mark.parametrize("change, message", [
    (('point = "bow"\n', ""), "slamming_probability is measured at a point"),
    (("threshold_m = 9.0\n", ""), "criteria[0].threshold_m: required by slamming_probability"),
    (('quantity = "slamming_probability"', 'quantity = "relative_motion_exceedance"\nthreshold_velocity_m_s = 4.0'),
     "criteria[0].threshold_velocity_m_s: relative_motion_exceedance takes no threshold_velocity_m_s"),
    (("", ""), "criteria[0].threshold_velocity_m_s: required by slamming_probability: the ship's length L for "
               "Ochi's 0.093 sqrt(g L) is unknown"),
])
def test_bad_slamming_criteria_are_refused_in_one_line(tmp_path, change, message):
    """The tanker without her hull (her WAMIT file states no length, she has no manoeuvring model): a slamming
    criterion without a point, without threshold_m, or without a length to take Ochi's velocity from is refused by
    `marinesim assess` in one line (exit 2) naming the key. If this fails, bad input reaches the run (a traceback)
    or the message no longer says what to give."""
    text = VESSEL_SCENARIO.replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "")
    assert "hull" not in text
    path = write(tmp_path, text + SLAMMING.replace(*change))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value).startswith(f"{path}: ") and message in str(info.value)
    done = cli("assess", str(path))
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and message in lines[0], done.stderr


def test_a_given_threshold_velocity_needs_no_length(tmp_path):
    """With threshold_velocity_m_s given, the hull-less tanker's slamming criterion loads and keeps it."""
    text = VESSEL_SCENARIO.replace(f'hull = "{ROOT / "hulls" / "tanker.gdf"}"\n', "")
    path = write(tmp_path, text + SLAMMING + "threshold_velocity_m_s = 4.5\n")
    (criterion,) = load_scenario(path).criteria
    assert criterion.options.threshold_velocity_m_s == 4.5 and criterion.options.threshold_m == 9.0
