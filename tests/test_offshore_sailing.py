"""Another ship under her own manoeuvring model (``[[vessels]] manoeuvring``): she sails her route with her
autopilot from each wheel-over point, keeps to it, answers the instructor's orders instead once given, and gives the
same bits however she is asked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT, write
from marinesim.constants import KNOT
from marinesim.errors import ParameterError, ScenarioError
from marinesim.offshore.route import Route
from marinesim.offshore.sailing import Sailed
from marinesim.scenario import load_scenario
from marinesim.scenario.ship_file import load_ship
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation

WAYPOINTS = np.array([[4000.0, 0.0], [6000.0, 3000.0], [6000.0, 8000.0]])
"""East 4 km, then 56 deg to port onto 034, then 34 deg to port onto north: m east and north of her start."""
CROSSING = ROOT / "configs" / "training" / "crossing_situation.toml"


@pytest.fixture(scope="module")
def tanker():
    return load_ship(ROOT / "configs" / "vessels" / "tanker.toml")[1]


def _route(waypoints=WAYPOINTS) -> Route:
    return Route((0.0, 0.0), 12.0 * KNOT, 0.0, waypoints, 800.0)


def _off_route(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The distance (m) from (x, y) to the planned legs (the last one going on past its waypoint)."""
    points = np.vstack([[0.0, 0.0], WAYPOINTS])
    best = np.full(x.shape, np.inf)
    for i, (a, b) in enumerate(zip(points[:-1], points[1:])):
        d = b - a
        u = np.clip(((x - a[0]) * d[0] + (y - a[1]) * d[1]) / (d @ d), 0.0, np.inf if i == len(points) - 2 else 1.0)
        best = np.minimum(best, np.hypot(x - a[0] - u * d[0], y - a[1] - u * d[1]))
    return best


def test_on_a_straight_route_her_model_sails_it_exactly(tanker):
    """Started settled on her course at the route's speed, the tanker's model goes straight on: the same track as
    the planned route to a millimetre over 40 minutes. What would be wrong if not: a start off her steady state
    (the propeller at the wrong rate, a transient), or the voyage placed off the route's start."""
    route = Route((1500.0, -700.0), 12.0 * KNOT, math.radians(120.0))
    times = np.arange(0.0, 2400.0, 7.0)
    sailed, planned = Sailed(route, tanker).path(times), route.path(times)
    np.testing.assert_allclose(sailed.x, planned.x, atol=1e-3)
    np.testing.assert_allclose(sailed.y, planned.y, atol=1e-3)
    np.testing.assert_allclose(sailed.speed, 12.0 * KNOT, rtol=1e-6)


def test_she_keeps_to_her_route_through_its_turns_as_her_model_turns(tanker):
    """Two turns of 56 and 34 deg: she never strays from the planned legs by as much as her length (246 m), is on
    the last leg within 10 m once settled, turns no faster than her autopilot's 20 deg/min and loses speed in the
    turns (more than 5 %: her rudder's drag and the drift angle, which a kinematic route does not have) to regain it
    after (within 2 % of 12 kn). What would be wrong if not: a wheel-over too late for her turning circle (she
    overshoots the next leg), no track keeping (the error of each turn carried on for good), or a route sailed by
    rails."""
    times = np.arange(0.0, 2400.0, 1.0)
    path = Sailed(_route(), tanker).path(times)
    off = _off_route(path.x, path.y)
    assert off.max() < 246.0, f"{off.max():.0f} m off her route at {times[off.argmax()]:.0f} s"
    assert off[-300:].max() < 10.0
    assert math.degrees(np.abs(path.rate).max()) * 60.0 <= 20.0 + 1e-6
    assert path.speed.min() < 0.95 * 12.0 * KNOT
    assert path.speed[-1] == pytest.approx(12.0 * KNOT, rel=0.02)
    assert math.degrees(path.heading[-1]) == pytest.approx(90.0, abs=0.5), "on her last leg, north"


def test_the_same_route_gives_the_same_bits_however_she_is_asked(tanker):
    """Asked forwards in small pieces, or for the end first and then the start: the same voyage to the last bit.
    What would be wrong if not: wheel-overs found where the asking happened to look, so that a replay, the record
    and the picture disagree."""
    times = np.arange(0.0, 2000.0, 0.5)
    ahead = Sailed(_route(), tanker)
    pieces = [ahead.path(chunk) for chunk in np.array_split(times, 40)]
    backwards = Sailed(_route(), tanker)
    backwards.path(times[-10:])
    whole = backwards.path(times)
    assert np.array_equal(np.concatenate([p.x for p in pieces]), whole.x)
    assert np.array_equal(np.concatenate([p.heading for p in pieces]), whole.heading)


def test_the_instructor_takes_her_over_and_her_route_lets_go(tanker):
    """An order of course 180 at 300 s: until then the same bits as on her route; from then she comes round to
    south and stays on it (her route's wheel-over at some 580 s is not given), and a second order from the
    instructor, half speed, stands on the first: she slows to 6 kn, still heading south. An order out of her range
    is refused before anything changes; one given before her track was ever asked for keeps the route's turns
    before it. What would be wrong if not: the route taking her back, or the instructor's order rewriting what
    she did before it."""
    times = np.arange(0.0, 2400.0, 1.0)
    free = Sailed(_route(), tanker).path(times)
    driven = Sailed(_route(), tanker)
    driven.order(300.0, course_deg=180.0)
    path = driven.path(times)
    before = times < 300.0
    assert np.array_equal(path.x[before], free.x[before]) and np.array_equal(path.y[before], free.y[before])
    compass = (90.0 - np.degrees(path.heading)) % 360.0
    assert compass[times >= 1200.0] == pytest.approx(180.0, abs=0.5)
    driven.order(1500.0, speed_kn=6.0)
    slowed = driven.path(times)
    assert np.array_equal(slowed.x[times < 1500.0], path.x[times < 1500.0])
    late = driven.path(np.array([6000.0]))  # a laden tanker takes the better part of an hour to lose half her way
    assert late.speed[-1] == pytest.approx(6.0 * KNOT, rel=0.05)
    assert (90.0 - math.degrees(slowed.heading[-1])) % 360.0 == pytest.approx(180.0, abs=0.5)
    with pytest.raises(ParameterError, match="rudder"):
        driven.order(1600.0, rudder_deg=80.0)
    assert np.array_equal(driven.path(times).x, slowed.x), "the refused order changed nothing"
    after_a_turn = Sailed(_route(), tanker)  # taken over before anyone asked where she was: her turn at 580 s stands
    after_a_turn.order(1000.0, speed_kn=10.0)
    early = times < 1000.0
    assert np.array_equal(after_a_turn.path(times).x[early], free.x[early])


def test_an_event_drives_the_crossing_tanker_and_the_record_follows(tmp_path):
    """The crossing exercise's tanker (her own model, standing on at 12 kn: the planned CPA of 51 m) altered by the
    instructor to 320 at 500 s: the record's heading for her comes to 320, and the CPA own-ship would have with her
    grows past 1 km. What would be wrong if not: an order that does not reach the other ship, or a record still
    showing her planned track."""
    text = CROSSING.read_text().replace('"../../', f'"{ROOT.as_posix()}/')
    text += '\n[[events]]\nat_s = 500.0\nvessel = "tanker"\nheading_deg = 320.0\nmessage = "tanker alters"\n'
    scenario = load_scenario(write(tmp_path, text))
    with Simulation(scenario, wake=False) as sim:
        Exercise(sim).advance_to(1100.0)
        rows = sim.frame(np.array([0.0, 490.0, 1100.0]))
    assert rows["tanker_cpa_m"][0] == pytest.approx(51.0, abs=2.0)
    assert rows["tanker_heading_deg"][1] == pytest.approx(270.0, abs=1e-6)
    assert rows["tanker_heading_deg"][2] == pytest.approx(320.0, abs=0.5)
    assert rows["tanker_cpa_m"][2] > 1000.0


@pytest.mark.parametrize("change, words", [
    (("", '\n[[vessels]]\nname = "mark"\nkind = "buoy"\nposition_m = [100.0, 100.0]\nmanoeuvring = "tanker"\n'),
     "vessels[1].manoeuvring: a buoy does not sail: manoeuvring is a ship's"),
    (("", '\n[[events]]\nat_s = 600.0\nvessel = "ferry"\nheading_deg = 320.0\n'),
     "events[2].vessel: 'ferry' is not a ship of [[vessels]] under her manoeuvring model (tanker)"),
    (("", '\n[[events]]\nat_s = 600.0\nvessel = "tanker"\nmessage = "x"\n'),
     "events[2].vessel: orders to another ship are her helm, engine and autopilot"),
    (("", '\n[[events]]\nat_s = 600.0\nvessel = "tanker"\nheading_deg = 320.0\nfault = "line:x"\n'),
     "not fault"),
    (("", '\n[[events]]\nat_s = 600.0\nvessel = "tanker"\nspeed_kn = 40.0\n'), "events[2].speed_kn"),
    (('manoeuvring = "tanker"', 'manoeuvring = "ferry"'), "vessels[0].manoeuvring"),
])
def test_bad_orders_to_another_ship_are_refused_in_one_line(tmp_path, change, words):
    """An order to a body that is not a ship under a model, one she cannot take, a model for a body that does not
    sail, a model that is not there: one line naming the key."""
    text = CROSSING.read_text().replace('"../../', f'"{ROOT.as_posix()}/')
    old, new = change
    text = text.replace(old, new, 1) if old else text + new
    with pytest.raises(ScenarioError) as error:
        load_scenario(write(tmp_path, text))
    message = str(error.value)
    assert words in message and "\n" not in message, message
