"""The simulation's timeline (marinesim.session.timeline): sea changes blend smoothly, start from the sea of the
moment, are prepared off the frame thread; orders to the ship act at once whatever the sea does; bad ones are
refused when asked; memory stays flat and the past exact."""

from __future__ import annotations

import math
import threading
import tracemalloc

import numpy as np
import pytest

from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.scenario import load_scenario
from marinesim.sea.cascades import cell_variances
from marinesim.session.assembly import Assembly
from marinesim.session.timeline import PREPARE_S, Simulation


def test_live_changes_blend_smoothly_and_do_not_depend_on_the_frame_rate(default):
    """A course order and a sea change at t = 5 s: the same poses at 60 and at 7 frames/s; no jump in heave or
    heading; the tanker comes round from 260 towards 200 deg at her autopilot's rate of turn (20 deg/min), not in
    the 10 s a sea change blends over."""
    def run(dt: float) -> Simulation:
        sim = Simulation(default, wake=False)
        while sim.time < 5.0 - 1e-9:
            sim.advance(min(dt, 5.0 - sim.time))
        sim.change(hs_factor=1.5, heading_deg=200.0, speed_kn=8.0, ramp_s=10.0)
        while sim.time < 60.0 - 1e-9:
            sim.advance(min(dt, 60.0 - sim.time))
        return sim
    fast, slow = run(1 / 60), run(1 / 7)
    times = np.arange(0.0, 60.0, 0.05)
    record = fast.frame(times)
    assert np.allclose(record["heave_m"], slow.frame(times)["heave_m"], atol=1e-9)
    a, b = fast.pose(17.3), slow.pose(17.3)
    assert np.allclose([a.x, a.y, a.heading, *a.motion], [b.x, b.y, b.heading, *b.motion], rtol=0, atol=1e-9)
    assert np.abs(np.diff(record["heave_m"])).max() < 0.1, "heave jumps during the blend"
    headings = np.unwrap(fast.voyage.path(times).heading)  # the poses' headings, at every time at once
    assert np.abs(np.diff(headings)).max() < math.radians(0.1)
    turned = 260.0 - record["heading_deg"][-1] - record["yaw_deg"][-1]
    assert 0.0 < turned < 20.0 / 60.0 * 55.0 * 1.1  # towards 200, at no more than the rate limit
    assert np.abs(record["rate_of_turn_deg_min"]).max() < 20.0 * 1.1
    assert fast.sea.hs == pytest.approx(1.5 * default.sea.hs, rel=1e-9)


def test_a_sea_change_during_another_starts_from_the_sea_of_that_moment(default):
    """Two presses of 'waves up' 2 s apart, each blending over 5 s: the second starts PREPARE_S after it is asked,
    from the sea of that moment (no jump in the waves at the reference point or in the ocean's amplitudes), and
    ends at 1.21 times the heights; it never waits for the first to end."""
    sim = Simulation(default, wake=False)
    sim.change(hs_factor=1.1, ramp_s=5.0)
    sim.advance(2.0)
    sim.change(hs_factor=1.1, ramp_s=5.0)
    sim.advance(10.0)
    assert [leg.start for leg in sim.legs] == pytest.approx([0.0, PREPARE_S, 2.0 + PREPARE_S], abs=1e-12)
    assert sim.sea.hs == pytest.approx(1.21 * default.sea.hs, rel=1e-9)
    start = 2.0 + PREPARE_S
    eta = sim.frame(np.array([start - 1e-6, start + 1e-6]))["wave_elevation_m"]
    assert abs(eta[1] - eta[0]) < 1e-5  # m; the waves move ~1e-6 m in 2 us
    amplitudes = [sim.ocean.amplitudes(t) for t in (start - 1e-6, start + 1e-6)]
    assert np.abs(amplitudes[1] - amplitudes[0]).max() < 1e-6 * np.abs(amplitudes[0]).max()
    assert sim.ocean.components(20.0).variance == pytest.approx(
        1.21**2 * Assembly(default).ocean.components().variance, rel=1e-9)
    sim.close()


def test_a_sea_change_is_prepared_off_the_frame_thread_and_starts_at_a_fixed_time(default, monkeypatch):
    """The costly part of a sea change (every cell's variance, 0.1-0.2 s at 4 x 256^2) runs on the
    change's worker while frames go on; on the frame thread it would stall the picture at each key
    press. The change starts PREPARE_S after it was asked for, however fast the worker was."""
    threads = []

    def variances(*args):
        threads.append(threading.current_thread().name)
        return cell_variances(*args)

    monkeypatch.setattr("marinesim.sea.ocean.cell_variances", variances)
    sim = Simulation(default, wake=False)
    sim.advance(1.0)
    threads.clear()
    sim.change(hs_factor=1.3, ramp_s=4.0)
    assert sim.sea.hs == pytest.approx(1.3 * default.sea.hs)  # the HUD shows what was asked for at once
    assert len(sim.legs) == 1
    while len(sim.legs) == 1:
        sim.advance(1 / 60)
    assert sim.legs[-1].start == pytest.approx(1.0 + PREPARE_S, abs=1e-12)
    assert threads and all(name.startswith("sea-change") for name in threads), threads
    sim.advance(10.0)
    assert sim.ocean.components(sim.time).variance == pytest.approx(1.3**2 * Assembly(default).ocean.components().variance,
                                                                    rel=1e-9)
    sim.close()


def test_a_sea_change_the_ocean_cannot_carry_is_refused_when_asked(underway, tmp_path):
    """A regular wave's period change needs a tile the ocean does not have: the refusal must come
    from change() (the viewer shows it), not half a second later from the frame loop."""
    text = underway.path.read_text() + '\n[[sea]]\ntype = "regular"\nheight_m = 1.0\nperiod_s = 8.0\nfrom_deg = 90.0\n'
    path = tmp_path / "regular.toml"
    path.write_text(text)
    sim = Simulation(load_scenario(path), wake=False)
    with pytest.raises(ParameterError, match="cannot carry a regular wave of 8.4 s"):
        sim.change(tp_factor=1.05, ramp_s=5.0)
    sim.advance(1.0)  # nothing was left waiting
    assert len(sim.legs) == 1 and sim.sea.tp == pytest.approx(load_scenario(path).sea.tp)
    sim.change(hs_factor=1.1, ramp_s=5.0)  # heights can change
    sim.advance(6.0)
    assert len(sim.legs) == 2


def test_bad_change_arguments_are_refused_when_asked(default):
    """A sea change starts PREPARE_S later; its ramp time must still be refused by change(),
    where the viewer shows the message, and not by a later frame, which would lose the change. A speed is an order
    to the engine, given at once: no sea leg."""
    sim = Simulation(default, wake=False)
    for ramp_s in (0.0, -1.0, math.nan):
        with pytest.raises(ParameterError, match="ramp time"):
            sim.change(hs_factor=1.2, ramp_s=ramp_s)
    before = sim.voyage.orders
    with pytest.raises(ParameterError, match="ramp time"):  # the whole change refused, its order too
        sim.change(hs_factor=1.2, speed_kn=6.0, ramp_s=0.0)
    assert sim.voyage.orders == before
    sim.advance(2.0)
    assert len(sim.legs) == 1 and sim.sea.hs == pytest.approx(default.sea.hs)
    sim.change(speed_kn=6.0, ramp_s=0.0)
    orders = sim.voyage.orders
    assert orders.engine == "6.0 kn" and orders.rps == pytest.approx(default.vessel.ship.rps_for_speed(6.0 * KNOT))
    assert len(sim.legs) == 1
    for bad, match in (({"rudder_deg": 50.0}, "rudder order must be in -35..35"), ({"engine": "flank"}, "telegraph"),
                       ({"speed_kn": 30.0}, "faster than her engine"), ({"course_deg": 400.0}, "course must be")):
        with pytest.raises(ParameterError, match=match):
            sim.order(**bad)
    assert sim.voyage.orders == orders  # nothing refused was kept
    sim.close()


def test_a_long_session_of_changes_keeps_memory_flat_and_the_past_exact(default):
    """Twenty sea changes and speed orders, as an instructor makes in a training session: memory stays
    flat (each change used to keep its sea's amplitude grid and the ship's response to it, 10 MB
    at the default 4 x 256^2), and motions at times of the first change, whose states were since
    dropped, come back to the same bits."""
    sim = Simulation(default, wake=False)
    sim.advance(2.0)
    sim.change(hs_factor=1.2, speed_kn=6.0, ramp_s=1.0)  # starts at 2.5 s (PREPARE_S), settled at 3.5 s
    sim.advance(2.0)
    times = np.array([3.0, 3.75])  # blending into the first change, then settled in it
    past = sim.frame(times)
    tracemalloc.start()
    held = []
    for i in range(20):
        sim.advance(2.5)
        sim.change(hs_factor=0.9 if i % 2 else 1.1, speed_kn=5.0 + i % 3, ramp_s=2.0)
        held.append(tracemalloc.get_traced_memory()[0] / 2**20)
    tracemalloc.stop()
    assert held[-1] - held[4] < 5.0  # MB over 15 changes; kept, they were about 150
    again = sim.frame(times)
    for column, values in past.items():
        np.testing.assert_array_equal(again[column], values, err_msg=column)
    assert sim.sea.hs == pytest.approx(1.2 * 1.1**10 * 0.9**10 * default.sea.hs, rel=1e-9)
