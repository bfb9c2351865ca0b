"""Own-ship in the session (marinesim.session.timeline with marinesim.manoeuvring.voyage): the wave-frequency
motions follow her heading and speed as they change, without a jump and with the velocities the motions' own
derivatives; on a straight steady run they are those of a straight track; orders act at once whatever the sea is
doing; the voyage is the same whoever asks for it and in what order."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT, write
from marinesim.constants import KNOT
from marinesim.manoeuvring.voyage import Voyage
from marinesim.scenario import load_scenario
from marinesim.session.assembly import Assembly
from marinesim.session.timeline import Simulation
from marinesim.vessel import along
from marinesim.vessel.response import motion_columns

S175 = ROOT / "configs" / "training" / "heavy_weather_transit.toml"


@pytest.fixture(scope="module")
def transit():
    return load_scenario(S175)


def _derivative(values: np.ndarray, dt: float) -> np.ndarray:
    """The fourth-order central difference (NaN at the two ends)."""
    out = np.full(values.shape, np.nan)
    out[2:-2] = (-values[4:] + 8 * values[3:-1] - 8 * values[1:-3] + values[:-4]) / (12 * dt)
    return out


@pytest.mark.slow
def test_a_straight_steady_run_is_the_straight_track_response(transit):
    """With no order the S175's wave-frequency motions over 20 minutes at 20 Hz are those of the response on her
    straight track (the manoeuvring model in surge equilibrium) to 1e-9, and her own columns are those of a
    steady run: every bar and test of the response holds with the dynamics on."""
    sim = Simulation(transit, wake=False)
    record = sim.frame_steps(0.0, 0.05, 24001)
    straight = Assembly(transit).response.frame(0.05 * np.arange(24001))
    for name in motion_columns(transit.vessel.points):
        np.testing.assert_allclose(record[name], straight[name], rtol=0, atol=1e-9, err_msg=name)
    assert np.all(record["rate_of_turn_deg_min"] == 0.0) and np.all(record["rudder_deg"] == 0.0)
    assert np.allclose(record["speed_over_ground_kn"], transit.vessel.speed_m_s / KNOT, atol=1e-9)
    sim.close()


def test_through_a_hard_over_turn_the_velocities_are_the_motions_derivatives(transit):
    """Hard to starboard at 30 s, the S175 in a gale: over the next 3 minutes she turns some 90 deg and her speed
    falls, and the exported velocities are the exported motions' time derivatives (4th-order differences at 20 Hz)
    to 0.05 % of their range, as on a straight run; so are the ship's own positions and heading. A response whose
    phases jumped with the heading, or transfer functions switched at a change of course, would break this by
    the whole motion."""
    sim = Simulation(transit, wake=False)
    sim.advance_to(30.0)
    sim.order(rudder_deg=35.0)
    times = 30.0 + 0.05 * np.arange(3601)
    record = sim.frame(times)
    turned = record["heading_deg"][-1] - record["yaw_deg"][-1] - transit.vessel.heading_deg
    assert 60.0 < turned % 360.0 < 250.0
    assert record["speed_over_ground_kn"][-1] < 0.65 * transit.vessel.speed_m_s / KNOT  # 6.0 of 10 kn
    units = {"m": 1.0, "deg": 1.0}
    for dof in ("surge", "sway", "heave", "roll", "pitch", "yaw"):
        unit = "deg" if dof in ("roll", "pitch", "yaw") else "m"
        position, velocity = record[f"{dof}_{unit}"], record[f"{dof}_vel_{unit}_s"]
        error = np.nanmax(np.abs(_derivative(position, 0.05) - velocity))
        assert error < 5e-4 * np.ptp(velocity) * units[unit], dof
    north, east = record["north_m"], record["east_m"]
    speed = np.hypot(_derivative(north, 0.05), _derivative(east, 0.05))[2:-2]
    np.testing.assert_allclose(speed, record["speed_over_ground_kn"][2:-2] * KNOT, rtol=1e-5)
    rate = _derivative(np.unwrap(np.radians(record["heading_deg"] + record["yaw_deg"])), 0.05)[2:-2]
    np.testing.assert_allclose(np.degrees(rate) * 60.0, record["rate_of_turn_deg_min"][2:-2], atol=1e-3)
    sim.close()


def test_in_a_turn_the_motions_asked_one_time_at_a_time_are_those_asked_at_once(transit):
    """A sea change ramping from 20 s over 30 s, hard to starboard at 30 s: the motions over the next minute at
    5 Hz, asked one time at a time (as frames ask, each reading the transfer functions kept at the knots before
    it, of both sea legs while they blend; each summed on one core) and in one call from a fresh simulation (its
    passes of 80 steps summed on every core), are the same bits. What would be wrong: the two sets' knots kept in
    one store (frames ask them in turn), a knot kept from another time, or a step summed differently on one core
    and on many."""
    records = []
    for one_by_one in (True, False):
        sim = Simulation(transit, wake=False)
        n = sim.components(0).omega.size
        assert n < along.EVERY_CORE_FROM <= along.KNOTS_PER_PASS * 5 * n, "a time on one core, a pass on every core"
        sim.advance_to(20.0)
        sim.change(hs_factor=1.3, ramp_s=30.0)
        sim.advance_to(30.0)
        sim.order(rudder_deg=35.0)
        times = 30.0 + 0.2 * np.arange(301)
        if one_by_one:
            rows = [sim.frame(np.array([t])) for t in times]
            records.append({name: np.concatenate([row[name] for row in rows]) for name in rows[0]})
        else:
            records.append(sim.frame(times))
        assert len(sim.legs) == 2 and sim.legs[1].start < times[0] < sim.legs[1].start + sim.legs[1].ramp_s
        sim.close()
    assert abs(records[1]["heading_deg"][-1] - records[1]["heading_deg"][0]) > 20.0, "she turns"
    for name in motion_columns(transit.vessel.points):
        np.testing.assert_array_equal(records[0][name], records[1][name], err_msg=name)


def test_the_transfer_functions_kept_at_knots_are_those_of_their_own_heading_and_speed(transit):
    """Knots asked in a turning, slowing order, with repeats, a heading met again at another speed and a speed at
    another heading: each is the RAO table's transfer functions times the amplitudes at that heading and speed, as
    computed afresh. What would be wrong: a kept knot served for another heading or speed."""
    components = Assembly(transit).components()
    knots = along.Knots(transit.vessel.rao, components)
    wave_heading = np.arctan2(components.ky, components.kx)
    asked = [(0.3, 5.0), (0.31, 5.0), (0.3, 4.0), (0.32, 4.0), (0.3, 5.0), (0.33, 3.0), (0.31, 4.0), (0.3, 4.0),
             (0.34, 3.0), (0.35, 2.0), (0.3, 5.0)]
    for psi, speed in asked:
        fresh = transit.vessel.rao(components.omega, wave_heading - psi, speed) * components.amplitude[:, None]
        np.testing.assert_array_equal(knots.motion(psi, speed), fresh, err_msg=f"{psi} rad, {speed} m/s")


def test_a_course_order_during_a_long_sea_change_swings_the_bow_at_once(transit):
    """A sea change ramping over 15 minutes from 60 s; a course order at 120 s (from 120 to 180 deg): the bow
    swings within 30 s, at the ship's own rate of turn, the same as with no sea change at all; it never waits for
    the ramp (a course order at 400 s once took effect at 899 s behind a sea change)."""
    def run(sea: bool) -> dict[str, np.ndarray]:
        sim = Simulation(transit, wake=False)
        sim.advance_to(60.0)
        if sea:
            sim.change(hs_factor=1.5, ramp_s=900.0, at=60.0)
        sim.advance_to(120.0)
        sim.order(course_deg=180.0)
        record = sim.frame(np.arange(120.0, 400.0, 0.5))
        sim.close()
        return record
    ramping, calm = run(True), run(False)
    rot = ramping["rate_of_turn_deg_min"]
    assert rot[0] == 0.0 and rot[60] > 5.0  # swinging 30 s after the order
    np.testing.assert_array_equal(ramping["rate_of_turn_deg_min"], calm["rate_of_turn_deg_min"])
    np.testing.assert_array_equal(ramping["north_m"], calm["north_m"])


def test_the_voyage_is_the_same_whoever_asks_and_in_what_order(transit):
    """The voyage with its orders sampled at once, in pieces forwards, backwards after its blocks were let go, and
    with an order given first for later and then for earlier: the same bits each time."""
    ship = transit.vessel.ship

    def voyage() -> Voyage:
        state, orders = ship.start(15.0 * KNOT, math.radians(120.0))
        return Voyage(ship, state, orders, 0.1)

    times = np.arange(0.0, 1500.0, 0.7)
    first = voyage()
    first.order(10.0, rudder_deg=20.0)
    first.order(200.0, engine="half ahead")
    first.order(400.0, autopilot=True)
    whole = first.sample(times)["north"]

    pieces = voyage()
    pieces.order(10.0, rudder_deg=20.0)
    pieces.order(400.0, autopilot=True)      # given ahead, then one before it
    pieces.order(200.0, engine="half ahead")
    forward = np.concatenate([pieces.sample(times[i:i + 97])["north"] for i in range(0, times.size, 97)])
    np.testing.assert_array_equal(forward, whole)
    for piece in pieces._pieces:
        piece.rows = None if not piece.straight else piece.rows  # let every block go: they are stepped again
    np.testing.assert_array_equal(pieces.sample(times[::-1])["north"], whole[::-1])


def test_a_vessel_on_station_turns_to_an_ordered_heading_in_place(tmp_path):
    """The semisubmersible held on station: a heading order from 250 to 280 deg turns her at the DP rate (10
    deg/min) about her own origin; she does not move, and she takes no helm or engine orders."""
    scenario = load_scenario(ROOT / "configs" / "semisub_swell.toml")
    sim = Simulation(scenario, wake=False)
    sim.order(course_deg=280.0)
    record = sim.frame(np.arange(0.0, 600.0, 1.0))
    assert np.all(record["north_m"] == 0.0) and np.all(record["east_m"] == 0.0)
    assert np.max(record["rate_of_turn_deg_min"]) == pytest.approx(10.0, rel=0.01)
    assert (record["heading_deg"][-1] + record["yaw_deg"][-1]) == pytest.approx(280.0, abs=0.05)
    with pytest.raises(Exception, match="heading orders only"):
        sim.order(rudder_deg=10.0)
    sim.close()


def test_one_time_and_many_give_the_same_bits(transit):
    """The viewer samples the present alone (a path of its own), the export many times at once: the same bits."""
    sim = Simulation(transit, wake=False)
    sim.order(rudder_deg=-25.0, at=0.0)
    times = np.array([0.0, 0.05, 3.3, 17.77, 100.0, 250.05])
    many = sim.voyage.sample(times)
    for i, t in enumerate(times):
        one = sim.voyage.sample(np.array([t]))
        for name, values in many.items():
            assert one[name][0] == values[i], (name, t)
    sim.close()
