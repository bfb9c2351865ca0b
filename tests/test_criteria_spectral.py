"""The criteria in the frequency domain (marinesim/criteria/spectral.py) against analytic limits and
against the time domain: the same criterion, the same response synthesis a live run uses."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT
from marinesim.criteria.monitor import Criterion
from marinesim.criteria.spectral import criteria_at_unit_hs
from marinesim.errors import ParameterError
from marinesim.sea.build import wave_system
from marinesim.study.timedomain import TimeDomainStudy, run_task
from marinesim.vessel import read_rao
from marinesim.vessel.native import read_native, write_native
from marinesim.vessel.rao import make_table

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
TP = np.array([3.0, 6.0, 10.0, 16.0, 24.0])


def constant_heave(tmp_path) -> "RaoTable":  # noqa: F821
    """A native-format table with heave 1 m/m in phase with the wave at every frequency and heading, nothing
    else: the vessel follows the sea's elevation at its reference point."""
    omega = np.geomspace(0.02, 40.0, 60)
    beta = np.radians(np.arange(0.0, 181.0, 15.0))
    values = np.zeros((1, beta.size, omega.size, 6), complex)
    values[..., 2] = 1.0
    write_native(make_table(omega, beta, [0.0], values, source="constant heave"), tmp_path / "heave.csv")
    return read_native(tmp_path / "heave.csv")


@pytest.mark.parametrize("spreading_s", [None, 4.0])
def test_a_vessel_that_follows_the_sea_has_limiting_hs_four_times_the_limit(tmp_path, spreading_s):
    """Heave RMS = sqrt(m0) = Hs / 4 whatever the Tp, the heading and the spreading: the limiting Hs of a
    heave RMS limit L is 4 L. A lost part of the spectrum, a wrong quadrature weight or a spreading that
    does not integrate to 1 shows here."""
    rao = constant_heave(tmp_path)
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0, gamma=3.3, spreading_s=spreading_s)
    estimates = criteria_at_unit_hs(rao, {}, 0.0, [Criterion("heave_rms_m", 0.5)], system, math.inf, TP,
                                    np.array([0.0, 90.0, 180.0, 240.0]), 10800.0)
    np.testing.assert_allclose(estimates.limiting_hs(np.array([0.5])), 2.0, rtol=2e-4)


def test_speed_changes_the_encounter_frequency_not_the_variance(tmp_path):
    """The encounter mapping moves energy in frequency only: heave RMS of the sea-following vessel is Hs/4
    at 10 m/s in head and following seas, while its vertical velocity (the m2 moment) rises in head seas
    and falls in following seas."""
    rao = constant_heave(tmp_path)
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0, gamma=3.3)
    criteria = [Criterion("heave_rms_m", 1.0), Criterion("heave_rate_significant_m_s", 1.0, point="deck")]
    points = {"deck": (0.0, 0.0, 0.0)}
    still = criteria_at_unit_hs(rao, points, 0.0, criteria, system, math.inf, TP[2:3], np.array([0.0, 180.0]), 60.0)
    moving = criteria_at_unit_hs(rao, points, 10.0, criteria, system, math.inf, TP[2:3], np.array([0.0, 180.0]), 60.0)
    np.testing.assert_allclose(moving.value1[..., 0], 0.25, rtol=2e-4)
    np.testing.assert_allclose(still.value1[0, 0, 1], still.value1[0, 1, 1], rtol=1e-9)
    assert moving.value1[0, 1, 1] > 1.5 * still.value1[0, 1, 1], "head seas are met faster"
    assert moving.value1[0, 0, 1] < 0.8 * still.value1[0, 0, 1], "following seas are met slower"


def test_interruptions_have_no_spectral_estimate():
    rao = read_rao(TANKER)
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0)
    with pytest.raises(ParameterError, match="no frequency-domain estimate for bridge.mii_per_min"):
        criteria_at_unit_hs(rao, {"bridge": (0.0, 0.0, 20.0)}, 0.0, [Criterion("mii_per_min", 1.0, point="bridge")],
                            system, math.inf, TP, np.array([180.0]), 600.0)


@pytest.mark.slow
def test_the_spectral_rms_and_maxima_of_the_tanker_are_what_its_records_give():
    """Independent check: 20 seeds x 3 h of the time-domain synthesis (the ocean's components and the
    response a live run uses), heave and pitch of the shipped tanker in head, bow-quartering and beam seas
    (Hs 4 m, Tp 10 s, cos-2s s = 10). The mean of the 20 records' RMS must equal the spectral sigma within 3
    standard errors of that mean (about 1 %; the components carry 99.9 % of the variance); the median of the 20 records' largest pitch within 5 % of the most probable maximum in 3 h
    (a Rayleigh extreme's median lies about 2.5 % above its mode for N ~ 1000 oscillations)."""
    rao = read_rao(TANKER)
    criteria = (Criterion("heave_rms_m", 1.0, window_s=10800.0), Criterion("pitch_rms_deg", 1.0, window_s=10800.0),
                Criterion("pitch_max_deg", 1.0, window_s=10800.0))
    system = wave_system("jonswap", from_deg=0.0, hs=1.0, tp=10.0, gamma=3.3, spreading_s=10.0)
    headings = np.array([180.0, 150.0, 90.0])
    study = TimeDomainStudy(rao, {}, 0.0, criteria, system, math.inf, np.array([4.0]), np.array([10.0]),
                            headings, tuple(range(20)), 10800.0)
    records = np.array([run_task(study, i) for i in range(study.tasks)]).reshape(len(headings), 20, 3)
    spectral = 4.0 * criteria_at_unit_hs(rao, {}, 0.0, list(criteria), system, math.inf, np.array([10.0]),
                                         headings, 10800.0).value1[0]                         # (H, C)
    for h, heading in enumerate(headings):
        for c in (0, 1):
            mean, error = records[h, :, c].mean(), records[h, :, c].std(ddof=1) / math.sqrt(20)
            assert abs(mean - spectral[h, c]) < 3 * error, (heading, c, mean, error, spectral[h, c])
        if heading != 90.0:  # no pitch worth the name in beam seas
            median = np.median(records[h, :, 2])
            assert median == pytest.approx(spectral[h, 2], rel=0.05), (heading, median, spectral[h, 2])
