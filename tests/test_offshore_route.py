"""A route of legs and turns: the geometry an ECDIS draws for it, sailed at one speed."""

import math

import numpy as np
import pytest

from marinesim.errors import ParameterError
from marinesim.offshore.route import Route

SPEED = 6.0
RADIUS = 300.0
WAYPOINTS = np.array([[2000.0, 0.0], [2000.0, 1500.0], [500.0, 3000.0]])


@pytest.fixture(scope="module")
def route():
    return Route((0.0, 0.0), SPEED, waypoints=WAYPOINTS, turn_radius_m=RADIUS)


def test_turns_are_circles_tangent_to_both_legs(route):
    """Each turn starts R tan(D/2) before its waypoint on the incoming leg and ends as far after it on the next: a
    turn placed anywhere else would leave the route off its legs (the ECDIS's wheel-over point)."""
    cut_90, cut_45 = RADIUS * math.tan(math.radians(45.0)), RADIUS * math.tan(math.radians(22.5))
    legs = [p for p in route.pieces if p.turn == 0.0]
    assert legs[0].start == (0.0, 0.0) and legs[0].length == pytest.approx(2000.0 - cut_90)
    np.testing.assert_allclose(legs[1].start, (2000.0, cut_90), atol=1e-9)
    assert legs[1].length == pytest.approx(1500.0 - cut_90 - cut_45)
    lead = np.array([-1.0, 1.0]) / math.sqrt(2.0)
    np.testing.assert_allclose(legs[2].start, WAYPOINTS[1] + cut_45 * lead, atol=1e-9)
    assert legs[2].heading == pytest.approx(math.radians(135.0))


def test_sailed_at_her_speed_with_heading_and_rate_continuous(route):
    """Distance along the track grows at U, the heading turns smoothly at U / R in the turns (port here) and not on
    the legs, and the velocity and acceleration given are the track's own derivatives."""
    t = np.arange(0.0, 900.0, 0.01)
    path = route.path(t)
    steps = np.hypot(np.diff(path.x), np.diff(path.y))
    np.testing.assert_allclose(steps, SPEED * 0.01, rtol=1e-6)
    heading = np.unwrap(path.heading)
    assert np.max(np.abs(np.diff(heading))) <= SPEED / RADIUS * 0.01 * (1 + 1e-9)
    assert set(np.round(np.unique(path.rate), 12)) == {0.0, round(SPEED / RADIUS, 12)}
    np.testing.assert_allclose(np.gradient(path.x, t)[1:-1], path.vx[1:-1], atol=SPEED * 0.01 / RADIUS * SPEED)
    turning = path.rate > 0
    np.testing.assert_allclose(np.hypot(path.ax, path.ay)[turning], SPEED**2 / RADIUS, rtol=1e-12)
    assert heading[-1] == pytest.approx(math.radians(135.0))


def test_a_leg_is_one_straight_track_from_t0(route):
    """Each leg's straight track (the response's fast path) places her where the route does at every time of the
    leg; the turns have none."""
    t = np.arange(0.0, 1200.0, 0.5)
    path = route.path(t)
    runs = route.runs(t)
    assert [route.track(i) is None for _, _, i in runs] == [False, True, False, True, False]
    for lo, hi, index in runs:
        track = route.track(index)
        if track is None:
            continue
        x = track.x0 + track.speed * math.cos(track.heading) * t[lo:hi]
        y = track.y0 + track.speed * math.sin(track.heading) * t[lo:hi]
        np.testing.assert_allclose(x, path.x[lo:hi], atol=1e-6)
        np.testing.assert_allclose(y, path.y[lo:hi], atol=1e-6)


def test_without_waypoints_she_goes_straight_on_her_heading():
    """No waypoints: her heading (math angle) and speed, forever."""
    path = Route((10.0, 20.0), 5.0, heading=math.radians(30.0)).path(np.array([0.0, 100.0]))
    np.testing.assert_allclose([path.x[1] - 10.0, path.y[1] - 20.0],
                               [500.0 * math.cos(math.radians(30.0)), 500.0 * math.sin(math.radians(30.0))])


@pytest.mark.parametrize("kwargs, words", [
    ({"waypoints": np.array([[100.0, 0.0], [100.0, 50.0]])}, r"leg 1 of the route \(100 m\) is too short"),
    ({"waypoints": np.array([[0.0, 0.0]])}, "waypoint 1 is where the route already is"),
    ({"waypoints": np.array([[1000.0, 0.0], [0.0, 1.0]])}, "turns the route back on itself"),
    ({"waypoints": np.array([[np.nan, 0.0]])}, "finite"),
])
def test_impossible_routes_are_refused_in_one_line(kwargs, words):
    """A turn that does not fit its legs, a waypoint on the route's own place, a turn back, a NaN: one line each."""
    with pytest.raises(ParameterError, match=words) as error:
        Route((0.0, 0.0), 5.0, turn_radius_m=RADIUS, **kwargs)
    assert "\n" not in str(error.value)
