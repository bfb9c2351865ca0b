"""The helicopter's approach to a moving helideck (marinesim.offshore.helicopter), checked against the profile's own
numbers worked out by hand: the glide path's angle and closing speed, the hover point square to the wind, the
go-around's climb and track, and the deck's height at touchdown."""

from __future__ import annotations

import math

import numpy as np
import pytest

from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.offshore.helicopter import PHASES, HelicopterApproach

WIND_FROM = 240.0
DECK_HEIGHT = 25.0
HOVER = 30.0 * 0.3048
SHIP_SPEED = 10.0 * KNOT


def bearing_vector(compass_deg: float) -> np.ndarray:
    """Unit vector (east, north) towards a compass bearing."""
    return np.array([math.sin(math.radians(compass_deg)), math.cos(math.radians(compass_deg))])


def compass_of(v: np.ndarray) -> np.ndarray:
    """Compass bearing (deg) of horizontal vectors (n, 2)."""
    return np.degrees(np.arctan2(v[:, 0], v[:, 1])) % 360.0


def ship(speed: float = SHIP_SPEED, course: float = 200.0, turn_deg_s: float = 0.0):
    """A deck at (300, -150, 25) m at t = 0 on a straight course (compass deg) at ``speed`` (m/s), its heading
    ``course`` turning at ``turn_deg_s``, heaving 1.5 m at a 9 s period about its mean height."""
    direction = bearing_vector(course)

    def deck(t):
        t = np.asarray(t, float)
        east, north = 300.0 + speed * t * direction[0], -150.0 + speed * t * direction[1]
        return np.c_[east, north, np.full(len(t), DECK_HEIGHT)], course + turn_deg_s * t

    def deck_z(t):
        return DECK_HEIGHT + 1.5 * np.sin(2.0 * math.pi * np.asarray(t, float) / 9.0 + 0.4)

    return deck, deck_z


def approach(speed: float = SHIP_SPEED, turn_deg_s: float = 0.0, **profile) -> HelicopterApproach:
    deck, deck_z = ship(speed, turn_deg_s=turn_deg_s)
    return HelicopterApproach(deck, deck_z, WIND_FROM, **profile)


def relative(heli: HelicopterApproach, t: np.ndarray) -> tuple[np.ndarray, dict]:
    """The helicopter's position relative to the deck's mean centre (n, 3) and its samples."""
    s = heli.sample(t)
    centre, _ = heli.deck(t)
    return np.c_[s["x"], s["y"], s["z"]] - centre, s


def arrival_s(speed_kn: float = 60.0, range_nm: float = 0.75, deceleration: float = 0.5) -> float:
    """When the approach reaches the hover: steady to the braking distance v^2 / 2a, then 2 d / v to stop."""
    v = speed_kn * KNOT
    braking = v * v / (2.0 * deceleration)
    return (range_nm * 1852.0 - braking) / v + 2.0 * braking / v


@pytest.mark.parametrize("speed", [0.0, SHIP_SPEED])
def test_the_approach_flies_the_glide_angle_at_the_closing_speed_from_downwind(speed):
    """On the steady segment the closing speed over the deck is 60 kn and the path descends at 6 deg; the whole
    approach lies on that path (height over the hover = tan 6 deg x distance to go), starts 0.75 nm downwind of the
    hover point, tracks into the wind (240 deg) within 0.01 deg and heads 240 deg, whether the ship lies stopped or
    steams at 10 kn across the wind. A wrong sign of the wind (towards, not from) would track 060; degrees taken for
    radians or the speed in m/s taken as kn would miss the figures by far more than the tolerances."""
    heli = approach(speed)
    steady = np.arange(0.0, 13.0, 0.5)
    rel, s = relative(heli, steady)
    velocity = np.diff(rel, axis=0) / 0.5
    horizontal = np.hypot(velocity[:, 0], velocity[:, 1])
    assert horizontal == pytest.approx(60.0 * KNOT, rel=1e-9)
    assert np.degrees(np.arctan2(-velocity[:, 2], horizontal)) == pytest.approx(6.0, abs=1e-9)
    assert compass_of(velocity[:, :2]) == pytest.approx(WIND_FROM, abs=0.01)
    assert np.all(s["heading_deg"] == WIND_FROM) and np.all(s["phase"] == "approach")
    hover_point = 20.0 * bearing_vector(WIND_FROM - 90.0)  # left of the track: the deck is on the right
    whole = np.linspace(0.0, arrival_s(), 200)
    rel, _ = relative(heli, whole)
    to_go = np.hypot(*(rel[:, :2] - hover_point).T)
    assert rel[:, 2] - HOVER == pytest.approx(math.tan(math.radians(6.0)) * to_go, abs=1e-9)
    assert to_go[0] == pytest.approx(0.75 * 1852.0, rel=1e-12)
    assert compass_of((rel[:1, :2] - hover_point)) == pytest.approx((WIND_FROM + 180.0) % 360.0, abs=1e-9)


def test_the_hover_is_held_alongside_while_the_deck_is_red_as_the_ship_steams_at_10_kn():
    """Arrived (75.9 s after the start: 14.1 s steady, then 61.7 s slowing at 0.5 m/s^2) and not permitted, or
    permitted and then held before arrival, the helicopter stays 20 m square to the wind, on the left of its track, and
    30 ft over the deck's mean height, within a centimetre for five minutes while the ship makes 10 kn and heaves."""
    assert approach().arrival_s == pytest.approx(arrival_s(), rel=1e-12)
    t = np.linspace(arrival_s(), arrival_s() + 300.0, 301)
    expected = np.r_[20.0 * bearing_vector(WIND_FROM - 90.0), HOVER]
    never = approach()
    held = approach()
    held.permit(10.0)
    held.hold(60.0)
    for heli in (never, held):
        rel, s = relative(heli, t)
        assert np.abs(rel - expected).max() < 0.01
        assert set(s["phase"]) == {"hover"}


def test_it_lands_only_after_the_permit_and_touches_down_at_the_decks_height():
    """Permitted 50 s after arriving, the helicopter hovers until then, crosses in 12 s and settles in 10 s; it
    touches down at the deck's actual (heaving) height at that moment, with the deck's heave rate (no jump in
    velocity), and then rides the deck: at its centre and height, turning with it (0.2 deg/s here)."""
    heli = approach(turn_deg_s=0.2)
    permit = arrival_s() + 50.0
    heli.permit(permit)
    touchdown = permit + 22.0
    deck, deck_z = ship(turn_deg_s=0.2)
    s = heli.sample(np.array([permit - 1e-6, permit, permit + 11.99, permit + 12.01, touchdown - 1e-6, touchdown]))
    assert list(s["phase"]) == ["hover", "crossing", "crossing", "landing", "landing", "on_deck"]
    assert s["z"][-1] == deck_z(np.array([touchdown]))[0] and s["height_above_deck_m"][-1] == 0.0
    dt = 1e-3
    edge = heli.sample(np.array([touchdown - 2 * dt, touchdown - dt, touchdown + dt, touchdown + 2 * dt]))["z"]
    heave_rate = 1.5 * 2.0 * math.pi / 9.0 * math.cos(2.0 * math.pi * touchdown / 9.0 + 0.4)
    assert (edge[1] - edge[0]) / dt == pytest.approx(heave_rate, abs=0.01)
    assert (edge[3] - edge[2]) / dt == pytest.approx(heave_rate, abs=0.01)
    later = np.linspace(touchdown, touchdown + 120.0, 50)
    s = heli.sample(later)
    centre, heading = deck(later)
    assert np.all(s["phase"] == "on_deck")
    assert np.array_equal(s["x"], centre[:, 0]) and np.array_equal(s["y"], centre[:, 1])
    assert np.array_equal(s["z"], deck_z(later))
    assert s["heading_deg"] == pytest.approx((WIND_FROM + 0.2 * (later - touchdown)) % 360.0, abs=1e-9)
    before = heli.sample(np.linspace(0.0, permit - 1e-6, 400))["phase"]
    assert set(before) == {"approach", "hover"}


def test_position_and_velocity_are_continuous_through_every_phase_and_into_the_wave_off():
    """At each change of phase (the end of the steady glide, the hover, the crossing, the settling, touchdown, and a
    wave-off ordered during the crossing by a RED deck) the velocity just before and just after agree within what the
    largest acceleration (about 3 m/s^2) makes of a millisecond: a jump in position or velocity would show."""
    heli = approach(turn_deg_s=0.1)
    permit = arrival_s() + 5.0
    heli.permit(permit)
    v = 60.0 * KNOT
    steady_end = (0.75 * 1852.0 - v * v / 1.0) / v
    boundaries = [steady_end, arrival_s(), permit, permit + 12.0]
    red = permit + 16.0
    heli.hold(red)
    dt = 1e-3
    for t0 in boundaries + [red]:
        rel = heli.sample(np.array([t0 - dt, t0, t0 + dt]))
        p = np.c_[rel["x"], rel["y"], rel["z"]]
        assert np.abs((p[2] - p[1]) - (p[1] - p[0])).max() / dt < 0.01, t0
    assert heli.sample(np.array([red - 1e-6, red]))["phase"].tolist() == ["landing", "wave_off"]


def test_the_wave_off_climbs_away_ahead_and_to_the_side():
    """Waved off from the hover while the ship steams into the wind at 10 kn: after the collective's 4 s the climb is
    1000 ft/min (5.08 m/s), after 20 s the ground track is the wind's turned 30 deg away from the deck (210 deg) at
    60 kn and the heading follows it; the height never falls and the distance to the deck grows throughout."""
    deck, deck_z = ship(course=WIND_FROM)
    heli = HelicopterApproach(deck, deck_z, WIND_FROM)
    wave = arrival_s() + 30.0
    heli.permit(wave + 5.0)   # too late: the wave-off comes first
    heli.wave_off(wave)
    t = np.arange(wave, wave + 60.0, 0.25)
    s = heli.sample(t)
    assert np.all(s["phase"] == "wave_off")
    z = s["z"]
    assert np.all(np.diff(z) >= 0.0) and z[-1] - z[0] > 200.0
    climb = np.diff(z[t >= wave + 4.0]) / 0.25
    assert climb == pytest.approx(1000.0 * 0.3048 / 60.0, rel=1e-9)
    late = t >= wave + 20.0
    velocity = np.diff(np.c_[s["x"], s["y"]][late], axis=0) / 0.25
    assert np.hypot(*velocity.T) == pytest.approx(60.0 * KNOT, rel=1e-9)
    assert compass_of(velocity) == pytest.approx(WIND_FROM - 30.0, abs=1e-6)
    assert s["heading_deg"][late] == pytest.approx(WIND_FROM - 30.0, abs=1e-9)
    centre, _ = deck(t)
    distance = np.hypot(s["x"] - centre[:, 0], s["y"] - centre[:, 1])
    assert distance[0] == pytest.approx(20.0, abs=1e-6) and np.all(np.diff(distance) > 0.0)


def test_a_red_deck_during_the_crossing_is_a_wave_off_and_a_wave_off_on_deck_changes_nothing():
    """The status lights' red once the crossing has begun sends the helicopter round (CAP 437: do not land); a
    wave-off ordered after touchdown leaves it on deck."""
    heli = approach()
    heli.permit(0.0)
    heli.hold(arrival_s() + 3.0)
    assert heli.plan() == (pytest.approx(arrival_s()), pytest.approx(arrival_s() + 3.0))
    landed = approach()
    landed.permit(0.0)
    landed.wave_off(arrival_s() + 40.0)
    t = np.linspace(arrival_s() + 22.0, arrival_s() + 80.0, 30)
    assert set(landed.sample(t)["phase"]) == {"on_deck"}


def decided() -> HelicopterApproach:
    heli = approach(turn_deg_s=0.05)
    heli.permit(20.0)
    heli.hold(50.0)
    heli.permit(arrival_s() + 30.0)
    heli.wave_off(arrival_s() + 48.0)
    return heli


def test_the_state_is_a_function_of_the_decisions_alone():
    """Same decisions, same bits: sampled in order, shuffled, one time at a time, or by a second helicopter given
    the same decisions; and a decision at t leaves everything before t as it was (for each kind of decision)."""
    t = np.linspace(-20.0, arrival_s() + 120.0, 701)
    heli = decided()
    whole = heli.sample(t)
    order = np.random.default_rng(5).permutation(len(t))
    shuffled = heli.sample(t[order])
    one_by_one = [heli.sample(t[i:i + 1]) for i in range(0, len(t), 37)]
    again = decided().sample(t)
    for key in whole:
        assert np.array_equal(shuffled[key], whole[key][order])
        assert np.array_equal(again[key], whole[key])
        assert np.array_equal(np.concatenate([s[key] for s in one_by_one]), whole[key][::37])
    for kind in ("permit", "hold", "wave_off"):
        for at in (30.0, arrival_s() + 10.0, arrival_s() + 35.0):
            later = decided()
            getattr(later, kind)(at)
            before = t < at
            after = later.sample(t[before])
            for key in whole:
                assert np.array_equal(after[key], whole[key][before]), (kind, at, key)
    assert PHASES.index("approach") < PHASES.index("hover") < PHASES.index("on_deck")


@pytest.mark.parametrize("key, value, words", [
    ("approach_speed_kn", -60.0, "approach_speed_kn must be > 0"),
    ("glide_angle_deg", 1.9, "glide_angle_deg must be in 2..15 deg"),
    ("glide_angle_deg", 15.1, "glide_angle_deg must be in 2..15 deg"),
    ("start_range_nm", 0.4, "start_range_nm must be > 0.514 nm"),
    ("hover_height_ft", math.nan, "hover_height_ft must be a finite number"),
    ("crossing_s", -1.0, "crossing_s must be > 0"),
    ("settling_s", math.inf, "settling_s must be a finite number"),
    ("deck_side", "up", "deck_side must be 'left' or 'right'"),
])
def test_a_bad_profile_is_refused_in_one_line_naming_the_key(key, value, words):
    """Each bad value is refused at construction in one line that names the key and what it must be (a negative
    speed would fly the approach backwards; 0.4 nm is inside the 0.514 nm needed to slow from 60 kn)."""
    with pytest.raises(ParameterError) as error:
        approach(**{key: value})
    assert words in str(error.value) and "\n" not in str(error.value)


def test_non_finite_wind_times_and_deck_are_refused_in_one_line():
    """A wind direction, decision time or sample time that is not finite, and a deck giving NaN, are refused naming
    what was wrong."""
    deck, deck_z = ship()
    for call, words in ((lambda: HelicopterApproach(deck, deck_z, math.nan), "wind_from_deg must be a finite"),
                        (lambda: approach().permit(math.nan), "permit time must be a finite"),
                        (lambda: approach().sample(np.array([0.0, math.inf])), "times must be a 1-D array of finite"),
                        (lambda: HelicopterApproach(deck, lambda t: np.full(len(t), math.nan), WIND_FROM).sample(
                            np.array([1.0])), "deck_z(times) must give (1,) finite heights")):
        with pytest.raises(ParameterError) as error:
            call()
        assert words in str(error.value) and "\n" not in str(error.value)
