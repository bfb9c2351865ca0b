"""Own-ship's crane and its load, and the helicopter at her helideck, in the session: carried by her motions, ordered
at times, recorded, judged by the crane's criteria."""

import numpy as np
import pytest

from conftest import ROOT, write
from marinesim.criteria.quantities import set_down_velocity
from marinesim.errors import ScenarioError
from marinesim.pose import Pose
from marinesim.scenario import load_scenario
from marinesim.session.lifting import points_in_earth
from marinesim.session.timeline import Simulation

SUPPLY = ROOT / "rao" / "supply" / "input.re1"
SCENARIO = f"""
[ocean]
depth_m = 120.0
resolution = 64
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 2.5
tp_s = 9.0
from_deg = 120.0
spreading_s = 30.0

[vessel]
rao = "{SUPPLY}"
speed_kn = 0.0
heading_deg = 30.0

[vessel.points]
cargo_deck = [-25.0, 0.0, 3.0]
helideck = [20.0, 0.0, 12.0]

[run]
duration_s = 200.0
dt_s = 0.1
seed = 2
"""
CRANE = """
[crane]
pedestal_m = [-20.0, -7.5, 8.0]
boom_height_m = 12.0
radius_m = 8.73
slew_deg = 103.2
max_wire_m = 60.0
load_chart = [[4.0, 40.0], [8.0, 25.0], [12.0, 15.0]]
load_t = 10.0
wire_m = 16.5
landing_point = "cargo_deck"
"""


def test_points_on_board_move_as_the_pose_carries_them():
    """A body point's E-frame position is Pose.world's (the one rotation of CONVENTIONS), and its velocity the
    position's time derivative (a central difference, second method), for a ship turning, rolling and yawing."""
    from marinesim.offshore.route import Route

    route = Route((10.0, -5.0), 4.0, waypoints=np.array([[300.0, 0.0], [600.0, 250.0]]), turn_radius_m=150.0)
    t = np.linspace(40.0, 120.0, 161)

    def motion(times):
        w = 0.7
        linear = np.zeros((times.size, 19))
        amplitude = np.array([0.3, 0.2, 1.1, 0.09, 0.04, 0.02])
        linear[:, 0:6] = amplitude * np.sin(w * times[:, None] + np.arange(6))
        linear[:, 6:12] = amplitude * w * np.cos(w * times[:, None] + np.arange(6))
        return route.path(times), linear

    p = np.broadcast_to(np.array([-22.0, 12.0, 20.0]), (t.size, 3))
    position, velocity = points_in_earth(*motion(t), p)
    path, linear = motion(t)
    for i in (0, 60, 160):
        pose = Pose(path.x[i], path.y[i], path.heading[i], tuple(linear[i, :6]))
        np.testing.assert_allclose(position[i], pose.world(p[i:i + 1])[0], atol=1e-9)
    h = 1e-4
    ahead, _ = points_in_earth(*motion(t + h), p)
    behind, _ = points_in_earth(*motion(t - h), p)
    np.testing.assert_allclose(velocity, (ahead - behind) / (2 * h), atol=1e-5)


def test_her_motions_on_the_grid_are_hers_at_any_time(tmp_path):
    """What the crane and the helicopter read of her motions (computed every 1/16 s, interpolated to the load's steps)
    is her response at those times, computed directly: displacements and velocities within 2e-5 of their size but for
    the grid step (1/4 s) around the ends of a sea change's ramp, where her accelerations jump (there 1e-3)."""
    from marinesim.session.lifting import on_grid

    scenario = load_scenario(write(tmp_path, SCENARIO))
    with Simulation(scenario, wake=False) as sim:
        sim.change(hs_factor=1.5, ramp_s=10.0, at=5.0)
        sim.advance_to(30.0)
        times = np.sort(np.random.default_rng(1).uniform(0.0, 30.0, 400))
        _, interpolated = on_grid(sim.voyage.path, sim._motion_grid)(times)
        exact = sim._linear(times)[:, :12]
    error = np.abs(interpolated - exact) / np.abs(exact).max(axis=0)
    kinks = (np.abs(times - 5.0) < 0.25) | (np.abs(times - 15.0) < 0.25)
    assert error[~kinks].max() < 2e-5 and error.max() < 1e-3


@pytest.fixture(scope="module")
def crane(tmp_path_factory):
    return load_scenario(write(tmp_path_factory.mktemp("crane"), SCENARIO + CRANE))


def test_the_load_hangs_from_the_tip_and_is_set_down_on_her_deck(crane):
    """At rest under the tip the wire holds m g; lowered at 0.3 m/s from 20 s for 15 s, the wire pays out 4.5 m, the
    load meets the heaving cargo deck (the deck pushes, the wire goes slack), and the set-down speed the criterion
    reads is the closing speed at the touchdown."""
    with Simulation(crane, wake=False) as sim:
        sim.order(hoist_m_s=-0.3, at=20.0)
        sim.order(hoist_m_s=0.0, at=35.0)
        rows = sim.frame_steps(0.0, 0.1, 600)
    assert rows["crane_tension_kn"][0] == pytest.approx(10.0 * 9.80665, rel=1e-3)
    assert rows["crane_wire_length_m"][-1] == pytest.approx(16.5 + 4.5, abs=1e-6)
    landed = rows["crane_deck_force_kn"] > 0.0
    assert landed[-100:].all() and not landed[:150].any()
    assert (rows["crane_tension_kn"][-100:] < 1.0).mean() > 0.5
    first = int(np.flatnonzero(landed)[0])
    speed = set_down_velocity(rows["crane_relative_velocity_m_s"], rows["crane_deck_force_kn"])
    assert speed == pytest.approx(max(rows["crane_relative_velocity_m_s"][i - 1]
                                      for i in np.flatnonzero(landed[1:] & ~landed[:-1]) + 1))
    assert speed >= rows["crane_relative_velocity_m_s"][first - 1] > 0.0


def test_set_down_velocity_reads_each_touchdown():
    """Two touchdowns closing at 0.4 and 0.7 m/s: the fastest; none: 0 (a bounce counts as a touchdown again)."""
    closing = np.array([0.1, 0.4, 0.0, 0.0, 0.3, 0.7, 0.1, 0.0])
    force = np.array([0.0, 0.0, 5.0, 9.0, 0.0, 0.0, 3.0, 4.0])
    assert set_down_velocity(closing, force) == pytest.approx(0.7)
    assert set_down_velocity(closing, np.zeros(8)) == 0.0


def test_the_helicopter_holds_alongside_then_lands_on_the_heaving_deck(tmp_path):
    """Held RED it hovers beside the deck, 30 ft up; given GREEN it crosses, settles and sits on the deck at the
    deck's wave-moved height (the deck point's own z from her motions)."""
    scenario = load_scenario(write(tmp_path, SCENARIO + '[helicopter]\ndeck_point = "helideck"\n'))
    with Simulation(scenario, wake=False) as sim:
        arrival = sim.helicopter.arrival_s
        sim.order(helicopter="permit", at=arrival + 20.0)
        times = np.array([arrival + 10.0, arrival + 19.0, arrival + 60.0, arrival + 80.0])
        rows = sim.frame(times)
        path, linear = sim.voyage.path(times), sim._linear(times)
    assert rows["helicopter_above_deck_m"][:2] == pytest.approx([30 * 0.3048] * 2, abs=0.6)
    deck = points_in_earth(path, linear, np.broadcast_to([20.0, 0.0, 12.0], (4, 3)))[0]
    np.testing.assert_allclose(rows["helicopter_z_m"][2:], deck[2:, 2], atol=1e-5)  # her motions interpolated
    np.testing.assert_allclose(rows["helicopter_east_m"][2:], path.x[2:] + 20.0 * np.cos(path.heading[2:]),
                               atol=1e-6)


@pytest.mark.parametrize("extra, words", [
    (CRANE.replace("load_t = 10.0", "load_t = 30.0"), "crane: load 30.0 t exceeds the crane's safe working load"),
    (CRANE.replace("max_wire_m = 60.0", "max_wire_m = 200.0"), "reaches below the sea floor"),
    (CRANE.replace('landing_point = "cargo_deck"', 'landing_point = "hatch"'), "crane.landing_point: 'hatch'"),
    (CRANE.replace("wire_m = 16.5", "wire_m = 70.0"), "crane: wire_m must be"),
    ('[helicopter]\ndeck_point = "helideck"\nstart_s = 500.0\n', "helicopter.start_s: 500 s is not before the run's"),
    ('[[events]]\nat_s = 5.0\nhoist_m_s = 0.2\n', "events[0].hoist_m_s: hoist and slew are orders to a crane"),
    ('[helicopter]\ndeck_point = "roof"\n', "helicopter.deck_point: 'roof' is not one of"),
    ('[[events]]\nat_s = 5.0\nhelicopter = "permit"\n', "events[0].helicopter: the scenario has no [helicopter]"),
    ('[[events]]\nat_s = 5.0\nhelicopter = "land"\n', "events[0].helicopter"),
    ('[[criteria]]\nquantity = "swing_max_deg"\nlimit = 5.0\n', "criteria[0].quantity: swing_max_deg is a crane"),
])
def test_bad_lifts_and_helicopters_are_refused_in_one_line(tmp_path, extra, words):
    """A load over the chart, a wire below the sea bed, an unknown deck, orders without their crane or helicopter, a
    word the helicopter does not know, a crane criterion without a crane: one line naming the key."""
    with pytest.raises(ScenarioError) as error:
        load_scenario(write(tmp_path, SCENARIO + extra))
    message = str(error.value)
    assert words in message and "\n" not in message, message
