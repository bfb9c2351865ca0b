"""A criterion's expected value and the percentile of a realised one (marinesim.criteria.expectation), against the
windows of long Gaussian records synthesised from a spectrum, and against the operability study's spectral engine."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.criteria.expectation import (OMEGA, THETA, Met, Moments, Stretch, directional_density, run_expected,
                                            sea_moments, window_expected)
from marinesim.criteria.monitor import Criterion
from marinesim.criteria.quantities import Options
from marinesim.criteria.spectral import criteria_at_unit_hs
from marinesim.sea.seastate import SeaState, WaveSystem
from marinesim.sea.spectra import Jonswap
from marinesim.sea.spreading import Cos2s
from marinesim.vessel.read import read_rao

WINDOW_S, DT = 600.0, 0.25


@pytest.fixture(scope="module")
def record() -> tuple[np.ndarray, Moments]:
    """A 73-hour Gaussian record of a JONSWAP spectrum (Hs 1 m, Tp 10 s) by inverse FFT with seeded complex
    amplitudes, and the spectrum's moments at the window's resolution."""
    n = 2 ** 20
    omega = 2.0 * math.pi * np.fft.rfftfreq(n, DT)
    density = np.zeros_like(omega)
    density[1:] = Jonswap(hs=1.0, tp=10.0).density(omega[1:])
    d_omega = omega[1]
    rng = np.random.default_rng(7)
    amplitude = np.sqrt(density * d_omega) * (rng.standard_normal(omega.size) + 1j * rng.standard_normal(omega.size))
    x = np.fft.irfft(amplitude * n / 2.0, n)
    resolution = 2.0 * math.pi / WINDOW_S
    binned = np.histogram(omega, np.arange(0.0, omega[-1] + resolution, resolution), weights=density * d_omega)[0]
    moments = Moments(float(np.sum(density * d_omega)), float(np.sum(density * omega * d_omega)),
                      float(np.sum(density * omega ** 2 * d_omega)), float(np.sum(binned ** 2) / resolution))
    return x, moments


def _windows(x: np.ndarray) -> np.ndarray:
    rows = int(WINDOW_S / DT)
    return x[:x.size // rows * rows].reshape(-1, rows)


@pytest.mark.parametrize("quantity, statistic", [
    ("heave_rms_m", lambda w: np.sqrt(np.mean(w ** 2, axis=1))),
    ("heave_rate_significant_m_s", lambda w: 2.0 * np.sqrt(np.mean(w ** 2, axis=1))),
    ("roll_max_deg", lambda w: np.max(np.abs(w), axis=1)),
])
def test_the_windows_of_a_record_fall_evenly_over_the_percentiles(record, quantity, statistic):
    """Over 436 windows of 10 min, the share of windows below each quartile of the expected distribution is that
    quartile (within 3.3 binomial standard deviations): a distribution too narrow or too wide, or a largest value
    counted on one side only, would crowd the windows into its tails."""
    x, moments = record
    values = statistic(_windows(x))
    expected = window_expected(Criterion(quantity, 1.0, window_s=WINDOW_S), [Stretch(WINDOW_S, moments)])
    shares = np.array([expected.cdf(v) for v in values])
    for q in (0.1, 0.25, 0.5, 0.75, 0.9):
        tolerance = 3.3 * math.sqrt(q * (1.0 - q) / values.size)
        assert abs(np.mean(shares <= q) - q) < tolerance, (quantity, q, np.mean(shares <= q))
    assert abs(expected.median / np.median(values) - 1.0) < 0.02


def test_a_probability_of_the_mean_square_carries_its_distribution_over(record):
    """The relative-motion exceedance exp(-t^2 / (2 ms)) grows with the window's mean square ms, so the share of
    windows below a value is the share whose RMS gives less: the same windows, read either way."""
    x, moments = record
    threshold = 0.6
    windows = _windows(x)
    rms = np.sqrt(np.mean(windows ** 2, axis=1))
    options = Options(threshold_m=threshold)
    exceedance = window_expected(Criterion("relative_motion_exceedance", 0.05, window_s=WINDOW_S, options=options),
                                 [Stretch(WINDOW_S, moments)])
    by_rms = window_expected(Criterion("heave_rms_m", 1.0, window_s=WINDOW_S), [Stretch(WINDOW_S, moments)])
    for value in np.percentile(rms, [10, 50, 90]):
        assert exceedance.cdf(math.exp(-threshold ** 2 / (2.0 * value ** 2))) == pytest.approx(by_rms.cdf(value),
                                                                                               abs=1e-6)


def test_the_worst_of_a_run_is_scored_as_the_monitor_scores_it(record):
    """201 runs of 1,300 s cut from the record, each scored as the monitor does: a 600 s window's RMS every second,
    counted once the window is a quarter full, the run's worst the largest. The runs' worst values fall evenly over
    the percentiles of the expected worst (within 3.3 binomial standard deviations). What would be wrong: a model
    of full, disjoint windows only, which put 46 % of such runs above its 90th percentile."""
    x, moments = record
    rows, every = int(1300.0 / DT), int(1.0 / DT)
    runs = x[:x.size // rows * rows].reshape(-1, rows)
    total = np.concatenate([np.zeros((runs.shape[0], 1)), np.cumsum(runs ** 2, axis=1)], axis=1)
    ends = np.arange(int(150.0 / DT), rows + 1, every)
    length = np.minimum(ends, int(WINDOW_S / DT))
    worst = np.sqrt(((total[:, ends] - total[:, ends - length]) / length).max(axis=1))
    expected = run_expected(Criterion("heave_rms_m", 1.0, window_s=WINDOW_S), [Stretch(10.0, moments)] * 130)
    shares = np.array([expected.cdf(v) for v in worst])
    for q in (0.1, 0.25, 0.5, 0.75, 0.9):
        assert abs(np.mean(shares <= q) - q) < 3.3 * math.sqrt(q * (1.0 - q) / worst.size), (q, np.mean(shares <= q))


def test_a_runs_largest_value_is_that_of_its_whole_record(record):
    """The largest value over three windows is the largest over the whole record: the crossing rates add up."""
    _, moments = record
    largest = Criterion("roll_max_deg", 1.0, window_s=WINDOW_S)
    whole = window_expected(largest, [Stretch(3 * WINDOW_S, moments)])
    assert run_expected(largest, [Stretch(WINDOW_S, moments)] * 3).cdf(0.9) == pytest.approx(whole.cdf(0.9), rel=1e-9)


def test_the_moments_agree_with_the_operability_studys_engine():
    """The supply ship's heave, pitch and a point's vertical acceleration in a short-crested JONSWAP sea (Hs 1 m,
    Tp 9 s, s = 10) met 30 deg off the bow at rest: the RMS from this module's quadrature (absolute directions,
    2.5 deg) within 1 % of the study's (directions about the sea's, :mod:`marinesim.criteria.spectral`), two
    quadratures of one integral."""
    rao = read_rao("rao/supply/input.re1")
    criteria = [Criterion("heave_rms_m", 1.0), Criterion("pitch_rms_deg", 1.0),
                Criterion("vertical_acc_rms_m_s2", 1.0, point="bow")]
    points = {"bow": (35.0, 0.0, 5.0)}
    travel = math.radians(200.0)
    heading = travel - math.pi + math.radians(30.0)                   # the waves come 30 deg off the bow
    system = WaveSystem(Jonswap(hs=1.0, tp=9.0), travel, Cos2s(10.0))
    sea = SeaState((system,), depth=math.inf)
    mine = sea_moments(Met.of(rao, heading, 0.0, math.inf), points, criteria, directional_density(sea))
    study = criteria_at_unit_hs(rao, points, 0.0, criteria, system, math.inf, np.array([9.0]),
                                np.array([math.degrees(travel - heading)]), 600.0)
    for c, moments in enumerate(mine):
        assert math.sqrt(moments.m0) == pytest.approx(study.sigma1[0, 0, c], rel=0.01), criteria[c].quantity


def test_the_quadrature_spans_the_seas_of_ships():
    """Periods from 0.8 to 40 s and every direction: a sea of Tp 2.5 to 25 s has its variance inside."""
    assert 2.0 * math.pi / OMEGA[-1] == pytest.approx(0.8) and 2.0 * math.pi / OMEGA[0] == pytest.approx(40.0)
    assert THETA.size == 144
    for tp in (2.5, 25.0):
        total = Jonswap(hs=1.0, tp=tp).density(np.geomspace(1e-3, 60.0, 200_000))
        inside = Jonswap(hs=1.0, tp=tp).density(OMEGA)
        assert np.trapezoid(inside, OMEGA) / np.trapezoid(total, np.geomspace(1e-3, 60.0, 200_000)) > 0.98


def test_a_heel_in_a_turn_is_an_offset_under_the_waves(record):
    """A steady 3-unit heel under the waves: the RMS's median is sqrt(m0 + 9) (the mean squares add); with no waves
    at all the largest value is the heel itself, surely above a 2-unit limit and surely within a 4-unit one."""
    _, moments = record
    rms = window_expected(Criterion("roll_rms_deg", 1.0, window_s=WINDOW_S), [Stretch(WINDOW_S, moments, 9.0, 3.0)])
    assert rms.median == pytest.approx(math.sqrt(moments.m0 + 9.0), rel=0.01)
    calm = Moments(0.0, 0.0, 0.0, 0.0)
    largest = window_expected(Criterion("roll_max_deg", 1.0, window_s=WINDOW_S), [Stretch(WINDOW_S, calm, 9.0, 3.0)])
    assert largest.cdf(2.0) == 0.0 and largest.cdf(4.0) == 1.0
