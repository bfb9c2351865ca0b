"""The criteria's formulas against values computed by hand (REFERENCES section 8) and against a
second method (counting on a Gaussian record against the Rayleigh and Rice formulas)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.constants import G
from marinesim.criteria import helideck, interruptions, sickness, statistics
from marinesim.errors import ParameterError

DT = 0.1


def _sine(amplitude: float, period: float, seconds: float, dt: float = DT, phase: float = 0.3) -> np.ndarray:
    t = np.arange(0.0, seconds, dt)
    return amplitude * np.sin(2.0 * math.pi * t / period + phase)


def _gaussian(seconds: float, seed: int, dt: float = DT, peak: float = 0.6, width: float = 0.05) -> np.ndarray:
    """A zero-mean narrow-band Gaussian record of unit variance: complex normal Fourier coefficients
    under a Gaussian-shaped spectrum about ``peak`` rad/s, one per frequency of the record (so it
    never repeats within it)."""
    n = round(seconds / dt)
    omega = 2.0 * math.pi * np.fft.rfftfreq(n, dt)
    rng = np.random.default_rng(seed)
    shape = np.exp(-0.25 * ((omega - peak) / width) ** 2)
    x = np.fft.irfft((rng.standard_normal(omega.size) + 1j * rng.standard_normal(omega.size)) * shape, n)
    return x / x.std()


def test_msi_of_a_one_sixth_hertz_sinusoid_is_17_8_percent():
    """O'Hanlon & McCauley at 1/6 Hz, 1 m/s^2: 17.8 %. Frequency in Hz instead of rad/s: 0.0008 %,
    the error of a widely used MATLAB revision."""
    omega = 2.0 * math.pi / 6.0
    assert sickness.msi_percent(2.0 / math.pi, omega) == pytest.approx(17.8, abs=0.05)
    assert sickness.msi_of_record(_sine(1.0, 6.0, 600.0), DT) == pytest.approx(17.8, abs=0.1)
    assert sickness.msi_percent(2.0 / math.pi, 1.0 / 6.0) < 0.001


def test_wf_weighting_matches_iso_2631():
    """|W_f| = 0.695 / 1.006 / 0.854 / 0.224 at 0.1 / 0.16 / 0.25 / 0.5 Hz (ISO 2631-1 Annex A)."""
    magnitude = np.abs(sickness.wf_response(np.array([0.1, 0.16, 0.25, 0.5])))
    assert magnitude == pytest.approx([0.695, 1.006, 0.854, 0.224], abs=6e-4)


@pytest.mark.parametrize("f, gain", [(0.1, 0.695), (0.16, 1.006), (0.25, 0.854), (0.5, 0.224)])
def test_digital_wf_gives_the_analog_gain(f, gain):
    """The sampled filter at dt 0.1 s passes a long sinusoid with the analog gain (1 %, the bilinear
    warp near 0.5 Hz), so the dose is the standard's and not the sampling's."""
    x = _sine(1.0, 1.0 / f, 1200.0)
    y = sickness.WfFilter(DT).apply(x)[-3000:]
    assert math.sqrt(2.0) * statistics.rms(y) == pytest.approx(gain, rel=0.011)


def test_wf_filter_in_blocks_equals_at_once():
    """The viewer feeds the filter a few rows a frame, assess in blocks: the output must not depend on it."""
    x = _gaussian(300.0, seed=1)
    once = sickness.WfFilter(DT).apply(x)
    blocks = sickness.WfFilter(DT)
    cuts = np.r_[0, np.sort(np.random.default_rng(2).choice(np.arange(1, x.size), 40, replace=False)), x.size]
    pieces = np.concatenate([blocks.apply(x[a:b]) for a, b in zip(cuts[:-1], cuts[1:])])
    assert np.allclose(pieces, once, rtol=0.0, atol=1e-12)


def test_wf_refuses_a_coarse_step():
    with pytest.raises(ParameterError, match="0..0.1 s"):
        sickness.WfFilter(0.25)


def test_msdv_of_a_sinusoid_over_two_hours():
    """0.16 Hz, 1 m/s^2, 7200 s: MSDV = |W_f| a_rms sqrt(T) = 1.006 sqrt(7200 / 2) = 60.4 m/s^1.5."""
    weighted = sickness.WfFilter(DT).apply(_sine(1.0, 1.0 / 0.16, 7200.0))
    assert sickness.msdv(weighted, DT) == pytest.approx(1.006 * math.sqrt(3600.0), rel=0.01)


def test_rms_and_maximum_of_a_regular_roll():
    """A regular roll of amplitude 8.49 deg has RMS 6.0 deg (amplitude / sqrt 2) and maximum 8.49."""
    roll = _sine(8.49, 12.0, 1200.0)
    assert statistics.rms(roll) == pytest.approx(6.0, abs=0.01)
    assert statistics.max_abs(roll) == pytest.approx(8.49, abs=0.01)


def test_inclination_combines_roll_and_pitch():
    """The deck normal tilts by arccos(cos 3 cos 4) = 4.99854 deg, nearly sqrt(3^2 + 4^2) = 5 deg, not 4 or 7."""
    assert statistics.inclination_deg(np.array([3.0]), np.array([4.0]))[0] == pytest.approx(4.99854, abs=1e-5)
    assert statistics.inclination_deg(np.array([-3.0]), np.array([0.0]))[0] == pytest.approx(3.0)


def test_helideck_heave_rates_of_a_sinusoid():
    """A heave of 2 m amplitude and 10 s period: MAHR 4A/T = 0.8 m/s; significant heave rate
    2 x RMS velocity = 2 (2 pi 2 / 10) / sqrt 2 = 1.777 m/s."""
    heave = _sine(2.0, 10.0, 1200.0)
    velocity = np.gradient(heave, DT)
    assert helideck.mahr(heave, DT) == pytest.approx(0.8, rel=0.01)
    assert helideck.significant_heave_rate(velocity) == pytest.approx(1.777, rel=0.005)
    assert math.isnan(helideck.mahr(heave[:50], DT))  # half a period: no complete oscillation


def test_mahr_takes_the_largest_oscillation():
    """A record whose one oscillation is twice as high as the others reports that one."""
    heave = _sine(1.0, 10.0, 600.0, phase=0.0)
    heave[(np.arange(heave.size) * DT >= 300.0) & (np.arange(heave.size) * DT < 310.0)] *= 2.0
    assert helideck.mahr(heave, DT) == pytest.approx(4.0 * 2.0 / 10.0, rel=0.02)


def test_rayleigh_exceedance():
    """A sinusoid of amplitude A has sigma = A/sqrt 2, so P(amplitude > h) = exp(-h^2/A^2)."""
    assert statistics.rayleigh_exceedance(2.0 / math.sqrt(2.0), 1.5) == pytest.approx(math.exp(-1.5 ** 2 / 4.0))
    assert statistics.rayleigh_exceedance(0.0, 1.0) == 0.0


def test_rayleigh_exceedance_agrees_with_counted_cycles():
    """On a narrow-band Gaussian record, the share of zero-upcrossing cycles whose crest exceeds h
    is the Rayleigh probability (within 3 binomial standard errors)."""
    x = _gaussian(40000.0, seed=3)
    sigma = statistics.rms(x)
    up = np.ceil(statistics.zero_upcrossings(x, DT) / DT).astype(int)
    crests = np.maximum.reduceat(x[:up[-1]], up[:-1])
    for h in (1.0, 1.5, 2.0):
        p = statistics.rayleigh_exceedance(sigma, h)
        counted = np.mean(crests > h)
        assert counted == pytest.approx(p, abs=3.0 * math.sqrt(p * (1 - p) / crests.size)), h


def test_tipping_of_a_sinusoidal_force_ratio():
    """Ratio amplitude 0.3 > l/h 0.25 at a 10 s period: one tip to each side per period, 12 per minute;
    amplitude 0.2: none."""
    normal = np.full(6000, G)
    assert interruptions.mii_per_minute(G * _sine(0.3, 10.0, 600.0), normal, DT) == pytest.approx(12.0, abs=0.1)
    assert interruptions.mii_per_minute(G * _sine(0.2, 10.0, 600.0), normal, DT) == 0.0


def test_tipping_rate_agrees_with_rice():
    """On a Gaussian record, counted tips equal Rice's rate 2 nu0 exp(-c^2 / (2 sigma^2)) (Poisson 3 sigma)."""
    ratio = 0.12 * _gaussian(40000.0, seed=4)
    sigma = statistics.rms(ratio)
    nu0 = 1.0 / statistics.mean_upcrossing_period(ratio, DT)
    c = 0.25
    expected = 2.0 * nu0 * math.exp(-c * c / (2.0 * sigma * sigma)) * 40000.0
    counted = interruptions.tipping_count(ratio, c)
    assert counted == pytest.approx(expected, abs=3.0 * math.sqrt(expected))


def test_deck_specific_force():
    """At rest: (0, g). A static roll of 10 deg (port up): lateral g sin 10, normal g cos 10. A sway
    acceleration of 1 m/s^2 at even keel: lateral 1 m/s^2, normal g."""
    zeros = np.zeros((1, 3))
    offset = np.array([-70.0, 5.0, 20.0])
    assert interruptions.deck_specific_force(zeros, zeros, zeros, zeros, offset) == pytest.approx((0.0, G))
    roll = np.array([[10.0, 0.0, 0.0]])
    lateral, normal = interruptions.deck_specific_force(roll, zeros, zeros, zeros, offset)
    assert (lateral[0], normal[0]) == pytest.approx((G * math.sin(math.radians(10.0)), G * math.cos(math.radians(10.0))))
    sway = np.array([[0.0, 1.0, 0.0]])
    assert interruptions.deck_specific_force(zeros, zeros, zeros, sway, offset) == pytest.approx((1.0, G))


def test_roll_acceleration_is_felt_above_the_roll_axis():
    """A roll acceleration of 0.1 rad/s^2 at even keel pushes a point 20 m above the origin sideways
    by -20 x 0.1 m/s^2 (z up, roll positive port up: the top moves to starboard, -y)."""
    zeros = np.zeros((1, 3))
    acceleration = np.array([[math.degrees(0.1), 0.0, 0.0]])
    lateral, normal = interruptions.deck_specific_force(zeros, zeros, acceleration, zeros, np.array([0.0, 0.0, 20.0]))
    assert (lateral[0], normal[0]) == pytest.approx((-2.0, G))
