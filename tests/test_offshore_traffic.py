"""The geometry of traffic: the closed-form CPA against the sampled distance's minimum and analytic special cases,
bearings, and the COLREG encounter on textbook situations (Rules 13, 14, 15) with the boundaries the Rules draw."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.constants import NAUTICAL_MILE
from marinesim.errors import ParameterError
from marinesim.offshore.traffic import (DCPA_LIMIT_M, HEAD_ON_DEG, Encounter, bearing_deg, cpa,
                                        encounter, relative_bearing_deg)


def velocity(course_deg: float, speed: float) -> np.ndarray:
    """A velocity (E, m/s) on a compass course."""
    return speed * np.array([math.sin(math.radians(course_deg)), math.cos(math.radians(course_deg))])


def test_cpa_is_the_minimum_of_the_sampled_distance():
    """40 random pairs of straight tracks (range up to 4 km, relative speed 3-20 m/s, so |tcpa| < 1400 s): the
    distance sampled every 0.18 s over +-30 min has its minimum at the sample nearest tcpa (the distance grows
    with |t - tcpa| both ways), and that minimum lies between dcpa and dcpa + |v| dt / 2. A wrong sign in tcpa
    (the past closest point for the future one) or a dcpa not at tcpa would miss by seconds and metres."""
    rng = np.random.default_rng(7)
    n = 40
    own_xy, other_xy = rng.uniform(-2000, 2000, (n, 2)), rng.uniform(-2000, 2000, (n, 2))
    own_v = rng.uniform(-8, 8, (n, 2))
    angles = rng.uniform(0, 360, n)
    speeds = rng.uniform(3, 20, n)
    rel_v = np.stack([velocity(a, s) for a, s in zip(angles, speeds)])
    other_v = own_v + rel_v
    dcpa, tcpa = cpa(own_xy, own_v, other_xy, other_v)
    assert dcpa.shape == tcpa.shape == (n,) and np.abs(tcpa).max() < 1400.0

    dt = 0.18
    t = np.arange(-10000, 10001) * dt
    gap = (other_xy - own_xy)[None] + t[:, None, None] * rel_v[None]
    distance = np.hypot(gap[..., 0], gap[..., 1])
    nearest = distance.min(axis=0)
    assert np.all(np.abs(t[distance.argmin(axis=0)] - tcpa) <= dt / 2 + 1e-9)
    assert np.all(nearest >= dcpa - 1e-9) and np.all(nearest <= dcpa + speeds * dt / 2)


def test_head_on_on_one_line_meets_at_range_over_closing_speed():
    """Own ship north at 6 m/s, the other 5 km ahead coming south at 4 m/s: they meet (dcpa 0) in 5000 / 10 s;
    swapped roles give the same. Had the relative velocity been taken own minus other, tcpa would be -500 s."""
    dcpa, tcpa = cpa([0.0, 0.0], [0.0, 6.0], [0.0, 5000.0], [0.0, -4.0])
    assert dcpa == pytest.approx(0.0, abs=1e-9) and tcpa == pytest.approx(500.0, rel=1e-12)
    assert cpa([0.0, 5000.0], [0.0, -4.0], [0.0, 0.0], [0.0, 6.0])[1] == pytest.approx(500.0, rel=1e-12)


def test_opening_tracks_have_their_closest_point_in_the_past():
    """The same two ships 500 s after they met, 5 km apart and opening: the closest point was 500 s ago."""
    dcpa, tcpa = cpa([0.0, 3000.0], [0.0, 6.0], [0.0, -2000.0], [0.0, -4.0])
    assert dcpa == pytest.approx(0.0, abs=1e-9) and tcpa == pytest.approx(-500.0, rel=1e-12)


def test_equal_velocities_keep_the_present_range_and_tcpa_is_now():
    """Two ships on parallel tracks at the same velocity: the range never changes, so dcpa is the present range
    (3-4-5) and tcpa is 0 by definition (not NaN from 0 / 0)."""
    dcpa, tcpa = cpa([[10.0, 20.0]], [[3.0, -1.0]], [[310.0, 420.0]], [[3.0, -1.0]])
    assert dcpa.tolist() == [500.0] and tcpa.tolist() == [0.0]


def test_passing_abeam_at_a_known_distance():
    """A ship crossing own ship's bow at right angles, both at 5 m/s, starting 1 km south-east of the meeting point
    of the tracks and own ship 1 km south of it, 200 m later on her track: relative motion along (-5, -5) from
    (1000, 200) gives tcpa = (1000 + 200) * 5 / 50 = 120 s and dcpa = |(1000, 200) - 120 (5, 5)| = 400 sqrt 2."""
    dcpa, tcpa = cpa([0.0, -1000.0], [0.0, 5.0], [1000.0, -800.0], [-5.0, 0.0])
    assert tcpa == pytest.approx(120.0, rel=1e-12) and dcpa == pytest.approx(400.0 * math.sqrt(2.0), rel=1e-12)


def test_arrays_broadcast_and_the_result_drops_the_last_axis():
    """One own ship against a (3, 4) grid of others: each result is the one computed alone."""
    others = np.random.default_rng(1).uniform(-1000, 1000, (3, 4, 2))
    dcpa, tcpa = cpa([0.0, 0.0], [0.0, 5.0], others, [2.0, 0.0])
    assert dcpa.shape == tcpa.shape == (3, 4)
    single = cpa([0.0, 0.0], [0.0, 5.0], others[2, 1], [2.0, 0.0])
    assert (dcpa[2, 1], tcpa[2, 1]) == (single[0], single[1])


def test_bearings_are_compass_and_relative_to_the_bow():
    """North 0, east 90, south-west 225 (a math angle would give 90, 0 and -135); relative to a ship heading 300,
    a contact bearing 030 is 90 on the starboard beam and one bearing 210 is on the port beam (270)."""
    others = np.array([[0.0, 10.0], [10.0, 0.0], [-10.0, -10.0]])
    assert bearing_deg([0.0, 0.0], others) == pytest.approx([0.0, 90.0, 225.0], abs=1e-12)
    assert relative_bearing_deg(300.0, np.array([30.0, 210.0, 300.0])).tolist() == [90.0, 270.0, 0.0]


def test_bad_shapes_and_values_name_the_argument():
    with pytest.raises(ParameterError, match=r"^own_v must be an array of shape \(\.\.\., 2\)"):
        cpa([0.0, 0.0], [1.0, 2.0, 3.0], [0.0, 1.0], [0.0, 0.0])
    with pytest.raises(ParameterError, match="^other_xy must be finite"):
        cpa([0.0, 0.0], [1.0, 2.0], [np.nan, 1.0], [0.0, 0.0])
    with pytest.raises(ParameterError, match="^other_rel_xy must have shape"):
        encounter(0.0, [0.0, 5.0], [[0.0, 1.0]], 180.0, [0.0, -5.0])
    with pytest.raises(ParameterError, match="^dcpa_limit_m must be > 0"):
        encounter(0.0, [0.0, 5.0], [0.0, 1.0], 180.0, [0.0, -5.0], dcpa_limit_m=0.0)


def collision(own_course: float, own_speed: float, other_course: float, other_speed: float,
              t: float = 600.0) -> tuple:
    """encounter()'s arguments for two ships that would collide in ``t`` s (dcpa 0), headings on their courses."""
    own_v, other_v = velocity(own_course, own_speed), velocity(other_course, other_speed)
    return own_course, own_v, (own_v - other_v) * t, other_course, other_v


def approaching(own_course: float, own_speed: float, relative_deg: float, closing: float) -> tuple:
    """encounter()'s arguments for a ship 1 km away at ``relative_deg`` off own ship's bow coming straight at her
    (dcpa 0) at ``closing`` m/s relative speed, heading on her course over ground."""
    own_v = velocity(own_course, own_speed)
    bearing = own_course + relative_deg
    other_v = own_v + velocity(bearing + 180.0, closing)
    other_course = float(bearing_deg([0.0, 0.0], other_v))
    return own_course, own_v, velocity(bearing, 1000.0), other_course, other_v


def test_reciprocal_courses_are_head_on_within_the_practical_bound():
    """Rule 14: courses 180 deg apart, and up to HEAD_ON_DEG off, are head-on (both alter to starboard). One
    degree more and she is crossing: fine on the starboard bow, own ship gives way (Rule 15); fine on the port bow,
    own ship stands on (Rule 17). Had the bound been taken on the wrong side, 186 and 174 would differ."""
    assert HEAD_ON_DEG == 6.0
    for other in (180.0, 186.0, 174.0):
        assert encounter(*collision(10.0, 6.0, 10.0 + other, 5.0)) is Encounter.HEAD_ON
    assert encounter(*collision(10.0, 6.0, 197.0, 5.0)) is Encounter.CROSSING_GIVE_WAY
    assert encounter(*collision(10.0, 6.0, 183.0, 5.0)) is Encounter.CROSSING_STAND_ON
    assert Encounter.HEAD_ON.gives_way


def test_crossing_the_vessel_with_the_other_on_her_starboard_side_keeps_out_of_the_way():
    """Rule 15: own ship north, the other heading west from the starboard bow: own ship gives way; heading east
    from the port bow: own ship stands on (the roles swap if the side is read as a math angle)."""
    give_way = encounter(*collision(0.0, 6.0, 270.0, 6.0))
    stand_on = encounter(*collision(0.0, 6.0, 90.0, 6.0))
    assert give_way is Encounter.CROSSING_GIVE_WAY and give_way.gives_way
    assert stand_on is Encounter.CROSSING_STAND_ON and not stand_on.gives_way


def test_overtaken_from_more_than_22_5_deg_abaft_the_beam_and_crossing_short_of_it():
    """Rule 13(b): a ship coming up on own ship at 113.5 deg (starboard quarter) or 246.5 deg (port quarter) off
    her bow is overtaking her (own ship stands on); at 111.5 or 248.5 she is crossing: from starboard own ship
    gives way, from port she stands on. A boundary at 90 deg (the beam) or a sign slip would change some of the
    four."""
    cases = {113.5: Encounter.OVERTAKEN, 246.5: Encounter.OVERTAKEN,
             111.5: Encounter.CROSSING_GIVE_WAY, 248.5: Encounter.CROSSING_STAND_ON}
    for relative, expected in cases.items():
        assert encounter(*approaching(40.0, 5.0, relative, 3.0)) is expected, relative


def test_own_ship_overtaking_from_abaft_the_others_beam_keeps_out_of_the_way():
    """Rule 13: own ship at 10 m/s coming up on a slower ship 1 km ahead on the same course overtakes her and
    gives way; seen at 113.5 deg off the other's bow she still overtakes, at 111.5 deg she is crossing (the other
    has her on the starboard side: own ship, seeing the other on her port bow, stands on)."""
    ahead = encounter(0.0, [0.0, 10.0], [0.0, 1000.0], 0.0, [0.0, 4.0])
    assert ahead is Encounter.OVERTAKING and ahead.gives_way
    for aspect, expected in ((113.5, Encounter.OVERTAKING), (111.5, Encounter.CROSSING_STAND_ON)):
        other_v = velocity(0.0, 4.0)
        own_v = other_v + velocity(aspect + 180.0, 6.0)  # own ship at `aspect` off her bow, coming straight at her
        own_course = float(bearing_deg([0.0, 0.0], own_v))
        assert encounter(own_course, own_v, -velocity(aspect, 1000.0), 0.0, other_v) is expected, aspect


def test_no_risk_of_collision_is_clear():
    """A ship crossing from starboard that passes 1 nm off (over the 0.5 nm limit), one that has passed (tcpa < 0),
    and one keeping the same velocity 200 m off (no relative motion) are clear; the first is a crossing (own ship
    gives way) under a 1.5 nm limit."""
    passing = (0.0, [0.0, 6.0], [3000.0, 3000.0 + math.sqrt(2.0) * NAUTICAL_MILE], 270.0, [-6.0, 0.0])
    assert cpa([0.0, 0.0], passing[1], passing[2], passing[4])[0] == pytest.approx(NAUTICAL_MILE, rel=1e-12)
    assert DCPA_LIMIT_M == 926.0
    assert encounter(*passing) is Encounter.CLEAR and not Encounter.CLEAR.gives_way
    assert encounter(*passing, dcpa_limit_m=1.5 * NAUTICAL_MILE) is Encounter.CROSSING_GIVE_WAY
    assert encounter(0.0, [0.0, 6.0], [0.0, -1000.0], 180.0, [0.0, -5.0]) is Encounter.CLEAR
    assert encounter(0.0, [0.0, 6.0], [200.0, 0.0], 0.0, [0.0, 6.0]) is Encounter.CLEAR
