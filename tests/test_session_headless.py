"""The headless run (marinesim.session.headless): the wave elevation it records at a point has the
sea state's variance."""

import numpy as np
import pytest

from conftest import SEA_SCENARIO as GOOD, write
from marinesim.scenario import load_scenario
from marinesim.session.assembly import VARIANCE_FRACTION, Assembly


def test_run_time_series_has_the_sea_states_variance(tmp_path):
    # a long record at one point: time-averaged eta^2 = sum |a|^2 / 2 of the kept components
    text = GOOD.replace("duration_s = 60.0", "duration_s = 3600.0")
    scenario = load_scenario(write(tmp_path, text))
    ocean = Assembly(scenario).ocean
    components = ocean.components(variance_fraction=VARIANCE_FRACTION)
    times = np.arange(0.0, 3600.0, 0.5)
    series = components.elevation(0.0, 0.0, times)
    assert np.var(series) == pytest.approx(components.variance, rel=0.1)  # 1 h record: ~5% scatter
    assert components.variance >= VARIANCE_FRACTION * ocean.components().variance
