"""The phasor tables behind every sum of wave components in time: ``exp(i w j dt)`` built as products of a coarse
and a fine table is the direct exponential to rounding, and the vessel response summed block by block from them is
the response summed time by time. What would be wrong: a row of the table out of place (a motion shifted in time
by a step, an error of ``w dt`` of its amplitude, 0.1 at 1 rad/s and 0.1 s), or a block's start time lost."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from marinesim.scenario import load_scenario
from marinesim.sea.phasors import phasor_table
from marinesim.session.timeline import Simulation
from marinesim.vessel.response import Response, Track


@pytest.mark.parametrize("rows", [1, 2, 3, 16, 17, 28, 97, 512, 600])
def test_a_table_is_the_direct_exponential(rows):
    omega = np.linspace(0.05, 4.0, 301)
    dt = 0.1
    table = phasor_table(omega, dt, rows)
    direct = np.exp(1j * np.outer(np.arange(rows) * dt, omega))
    assert table.shape == (rows, omega.size)
    # each entry's phase w j dt (up to 240 rad) is itself rounded to about 5e-14 rad
    assert np.abs(table - direct).max() < 1e-13


@pytest.fixture(scope="module")
def response() -> Response:
    """The WAMIT tanker's response to configs/tanker_dp.toml's sea on a heading of 0.3 rad, at rest."""
    scenario = load_scenario(ROOT / "configs" / "tanker_dp.toml")
    with Simulation(scenario, wake=False) as simulation:
        components = simulation.components(0)
    return Response(scenario.vessel.rao, components, Track(0.3, 0.0), scenario.vessel.points, strict=False)


@pytest.mark.parametrize("steps", [1, 3, 17, 1300])
def test_the_block_product_is_the_response_time_by_time(response, steps):
    """1300 steps: blocks of 512 and a part block; 1, 3 and 17: a table of fewer rows than outputs (the viewer's
    frame), turned to the run's start instead of the coefficients."""
    start, dt = 1000.05, 0.1  # far from t = 0
    blocks = np.concatenate([out for _, out in response.linear_steps(start, dt, steps)])
    times = start + dt * np.arange(steps)
    direct = response.linear(times)
    scale = np.abs(direct).max(axis=0)
    assert blocks.shape == direct.shape
    assert np.all(np.abs(blocks - direct) <= 1e-10 * scale + 1e-15)
    shifted = response.linear(times + dt)
    assert np.abs(shifted - direct).max() > 1e-3 * scale.max(), "a step's shift would show"


def test_frames_of_a_few_steps_read_their_own_kept_tables(response):
    """A viewer's frames, one after another: two or three steps of 0.1 s, now and then one of 0.05 s, more
    distinct kinds than the response keeps. Each equals the response time by time. What would be wrong: a kept
    table served for another step or another number of steps (the motions of the wrong times)."""
    start = 500.0
    for dt, steps in [(0.1, 2), (0.1, 3), (0.1, 2), (0.05, 2), (0.1, 3), (0.05, 3), (0.1, 1), (0.2, 2), (0.1, 2),
                      (0.05, 2), (0.1, 3)]:
        blocks = np.concatenate([out for _, out in response.linear_steps(start, dt, steps)])
        direct = response.linear(start + dt * np.arange(steps))
        scale = np.abs(direct).max(axis=0)
        assert np.all(np.abs(blocks - direct) <= 1e-10 * scale + 1e-15), (dt, steps)
        start += dt * steps
