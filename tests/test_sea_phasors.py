"""The phasor tables behind every sum of wave components in time: ``exp(i w j dt)`` built as products of a coarse
and a fine table is the direct exponential to rounding, and the vessel response summed block by block from them is
the response summed time by time. What would be wrong: a row of the table out of place (a motion shifted in time
by a step, an error of ``w dt`` of its amplitude, 0.1 at 1 rad/s and 0.1 s), or a block's start time lost."""

from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from marinesim.errors import ParameterError
from marinesim.scenario import load_scenario
from marinesim.sea.phasors import phasor_table
from marinesim.session.timeline import Simulation
from marinesim.vessel.response import BLOCK, SHARED_ROWS, PhasorTables, Response, Track


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


def test_responses_at_rest_on_several_headings_share_their_tables(response):
    """A vessel keeping station: responses at rest on headings half a degree apart share one store of tables, and
    runs of a few to a few hundred steps at two time steps, taken in turn on each heading, each equal that heading's
    response time by time; a run longer than a block makes its own table. What would be wrong: a shared table kept
    for another time step (the motions of the wrong times), one heading's coefficients summed for another (the
    motions of a ship on another heading), or each heading making tables of its own (the store left empty: the
    station's short runs paying for a table each)."""
    tables = PhasorTables(2)
    sharing = [Response(response.rao, response.components, Track(0.3 + np.radians(0.5 * i), 0.0),
                        {name: tuple(p) for name, p in response.points.items()}, strict=False, tables=tables)
               for i in range(3)]
    start = 200.0
    for i, (dt, steps) in enumerate([(0.1, 28), (0.1, 3), (0.05, 40), (0.1, 1), (0.1, 150), (0.05, 31), (0.1, 33),
                                      (0.1, BLOCK + 88)]):
        own = sharing[i % 3]
        blocks = np.concatenate([out for _, out in own.linear_steps(start, dt, steps)])
        direct = own.linear(start + dt * np.arange(steps))
        scale = np.abs(direct).max(axis=0)
        assert np.all(np.abs(blocks - direct) <= 1e-10 * scale + 1e-15), (dt, steps)
        other = sharing[(i + 1) % 3].linear(start + dt * np.arange(steps))
        assert np.abs(other - direct).max() > 1e-6 * scale.max(), "the headings' motions differ"
        start += dt * steps
    assert (0.1, SHARED_ROWS) in tables and (0.05, SHARED_ROWS) in tables and (0.1, BLOCK) not in tables
    with pytest.raises(ParameterError, match="at rest only"):
        Response(response.rao, response.components, Track(0.3, 2.0), strict=False, tables=tables)
