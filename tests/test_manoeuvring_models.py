"""The manoeuvring models against published tests and simulations, analytic limits and second methods.

KVLCC2 (MMG standard method, Yasukawa & Yoshimura 2015) at full scale, 15.5 kn, rudder 2.32 deg/s, against the
SIMMAN 2008 free-running model tests (MARIN, 7 m model, Fn 0.142) and the MMG simulation of Kim et al. (2021,
IJNAOE 13:466-477, Tables 7-8), which uses the same coefficients:

| manoeuvre | free-running tests | Kim et al. MMG |
|---|---|---|
| 35 deg to port: advance, tactical diameter (L) | 3.11, 3.08 | 3.06, 3.05 |
| 10/10 starboard first: overshoots (deg) | 8.2, 21.9 | 5.0, 14.0 |
| 10/10 port first | 9.5, 15.0 | 7.2, 9.1 |
| 20/20 starboard first, port first: first overshoot | 13.7, 15.1 | 10.4, 13.9 |

The MMG coefficients under-predict the tests' overshoots (Kim et al.'s CFD and system-based columns show the
same): the model is held to the published simulation of the same equations within 1 deg, and to the tests'
turning circle within 0.1 L.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.signal import lsim

from conftest import ROOT
from marinesim.constants import KNOT
from marinesim.manoeuvring.container import SonNomotoContainer
from marinesim.manoeuvring.ship import STEP_S
from marinesim.manoeuvring.state import Orders
from marinesim.manoeuvring.trials import turning_circle, zigzag
from marinesim.scenario.ship_file import load_ship

VESSELS = ROOT / "configs" / "vessels"


@pytest.fixture(scope="module")
def kvlcc2():
    file, ship = load_ship(VESSELS / "kvlcc2.toml")
    return ship, file.approach_speed_kn * KNOT


@pytest.fixture(scope="module")
def s175():
    file, ship = load_ship(VESSELS / "s175.toml")
    return ship, file.approach_speed_kn * KNOT


def test_kvlcc2_full_ahead_holds_the_approach_speed(kvlcc2):
    """Full ahead is the rpm of surge equilibrium at 15.5 kn with R'_0 0.022 (the model tests' self-propulsion
    point, 1.75 rps at full scale): a ship left at full ahead neither gains nor loses speed."""
    ship, speed = kvlcc2
    rps = ship.engine.telegraph["full ahead"]
    assert 60.0 * rps == pytest.approx(105.0, abs=0.1)
    state = replace(ship.steady(speed), n=rps)
    for _ in range(6000):  # 10 minutes
        state, _ = ship.step(state, Orders(rps=rps))
    assert state.u / KNOT == pytest.approx(15.5, abs=0.01)


def test_kvlcc2_turning_circle_against_the_free_running_tests(kvlcc2):
    """35 deg to port: advance and tactical diameter within 0.1 L of SIMMAN's model tests (3.11, 3.08 L) and of Kim
    et al.'s MMG (3.06, 3.05 L); a rudder moment taken with a non-dimensional lever arm (a bug of public code) would
    give some 4.2 L, a wake formula with misplaced brackets 2.4 L."""
    ship, speed = kvlcc2
    port = turning_circle(ship, speed, -1)
    assert port.advance_m / 320.0 == pytest.approx(3.11, abs=0.1)
    assert port.tactical_diameter_m / 320.0 == pytest.approx(3.08, abs=0.1)
    assert port.final_speed_kn / 15.5 == pytest.approx(0.38, abs=0.05)  # a VLCC keeps about 40 % in a hard turn


@pytest.mark.parametrize("angle, side, published", [(10.0, 1, (5.0, 14.0)), (10.0, -1, (7.2, 9.1)),
                                                    (20.0, 1, (10.4, None)), (20.0, -1, (13.9, None))])
def test_kvlcc2_zigzag_against_the_published_mmg_simulation(kvlcc2, angle, side, published):
    """Overshoots within 1 deg of Kim et al.'s MMG with the same coefficients; both below the free-running tests'
    (the coefficient set's known under-prediction), never above them."""
    ship, speed = kvlcc2
    z = zigzag(ship, speed, angle, side)
    tests = {(10.0, 1): (8.2, 21.9), (10.0, -1): (9.5, 15.0), (20.0, 1): (13.7, None), (20.0, -1): (15.1, None)}
    assert z.first_overshoot_deg == pytest.approx(published[0], abs=1.0)
    assert z.first_overshoot_deg < tests[angle, side][0]
    if published[1] is not None:
        assert z.second_overshoot_deg == pytest.approx(published[1], abs=1.0)


def test_container_ship_reproduces_the_mss_turning_circle():
    """MSS's container.m driven as its exTurnCircle (8 m/s, 80 rpm, the rudder at MSS's 10 deg limit to port): the
    steady turn of an independent transliteration of the same equations, R 695.15 m, 6.662 m/s, heel 5.04 deg
    outward (to starboard in a port turn), to 0.2 %. A sign slip in the coupled roll-sway-yaw inverse or the
    propeller race would move them by tens of per cent."""
    from marinesim.manoeuvring.actuators import Engine, SteeringGear
    from marinesim.manoeuvring.ship import Ship

    ship = Ship("S175", SonNomotoContainer(), SteeringGear(math.radians(10.0), math.radians(5.0)),
                Engine(160 / 60, 0.0, 4.2))
    state = replace(ship.steady(8.0), n=80 / 60)
    for k in range(7000):
        state, _ = ship.step(state, Orders(rudder=math.radians(-35.0 if k >= 1000 else 0.0), rps=80 / 60))
    assert state.speed / abs(state.r) == pytest.approx(695.15, rel=2e-3)
    assert state.speed == pytest.approx(6.662, rel=2e-3)
    assert math.degrees(state.phi) == pytest.approx(5.04, rel=5e-3)


def test_container_ship_heels_outward_as_the_centrifugal_estimate_says(s175):
    """In a steady turn a ship heels outward by about ``U^2 (KG - d/2) / (g R GM)`` (the centrifugal force at G
    against the lateral resistance at half draught): Son & Nomoto's S175 (KG 10.09 m, d 8.5 m, GM 0.3 m) at 15 kn
    with 10 deg of rudder heels outward within 35 % of it (the hull's lift acts above half draught). A 3-DOF model
    cannot heel at all."""
    ship, speed = s175
    state = ship.steady(speed)
    for _ in range(9000):
        state, _ = ship.step(state, Orders(rudder=math.radians(10.0), rps=state.n))
    radius = state.speed / state.r
    estimate = state.speed**2 * (10.09 - 8.5 / 2) / (9.81 * radius * 0.3)
    assert state.r > 0 and state.phi < 0  # a starboard turn, heeling to port: outward
    assert -state.phi == pytest.approx(estimate, rel=0.35)


@pytest.mark.parametrize("name", ["s175", "supply", "tanker", "kvlcc2"])
def test_small_rudder_turns_at_the_linearised_rate(name):
    """At 0.001 deg of rudder the steady rate of turn is K delta, K the model's own linearisation's static gain
    (for a course-stable ship: the course-unstable KVLCC2 and supply vessel have no linear steady turn, K < 0;
    the tanker is so nearly neutral, T 660 s, that her quadratic cross-flow drag shows from 0.01 deg)."""
    file, ship = load_ship(VESSELS / f"{name}.toml")
    speed = file.approach_speed_kn * KNOT
    k, t = ship.linear_yaw(speed)
    if k < 0:
        assert t < 0  # course-unstable: both negative
        return
    state = ship.steady(speed)
    for _ in range(round(12 * t / STEP_S)):
        state, _ = ship.step(state, Orders(rudder=math.radians(0.001), rps=state.n))
    assert state.r / math.radians(0.001) == pytest.approx(k, rel=0.01)


def test_a_small_zigzag_follows_the_linearised_model(s175):
    """A 1/1 zig-zag's rate of turn equals that of the model's linearisation (4 states: sway, yaw, roll) driven by
    the same rudder, within 2 % of its range; a first-order Nomoto fit to either gives the same K and T within 2 %.
    At 10/10 the nonlinear terms slow the turn: its fit's K is some 15 % less. (A first-order fit to a zig-zag is
    not the static K and the first-moment T: those describe the slow response, the zig-zag its own period.)"""
    ship, speed = s175
    a, b = ship.linear_system(speed)
    fits = []
    for angle in (1.0, 10.0):
        r = zigzag(ship, speed, angle).record
        t, rudder = r.time, np.radians(r.rudder)
        rate = np.gradient(np.radians(r.heading), t)
        out = lsim((a, b[:, None], np.eye(len(b))[1:2], np.zeros((1, 1))), rudder, t)[1]
        if angle == 1.0:
            assert np.abs(rate - out).max() < 0.02 * np.ptp(rate)
        fits.append([_nomoto_fit(t, rudder, rate), _nomoto_fit(t, rudder, out)])
    (small, small_linear), (large, _) = fits
    assert small == pytest.approx(small_linear, rel=0.02)
    assert large[0] < 0.9 * small[0]


def _nomoto_fit(t: np.ndarray, rudder: np.ndarray, rate: np.ndarray) -> tuple[float, float]:
    """Least-squares (K, T) of ``T dr/dt + r = K delta``."""
    (k, t_), *_ = np.linalg.lstsq(np.c_[rudder, -np.gradient(rate, t)], rate, rcond=None)
    return float(k), float(t_)


@pytest.mark.parametrize("name", ["s175", "supply", "tanker"])
def test_port_and_starboard_turns_mirror(name):
    """The container ship and the models from main particulars are symmetric: a hard-over turn to port is the
    starboard one mirrored (east and heading change of sign, north and speed the same) to rounding. (KVLCC2's is
    not: its propeller's flow straightening and wake differ with the drift's side, as measured.)"""
    file, ship = load_ship(VESSELS / f"{name}.toml")
    speed = file.approach_speed_kn * KNOT
    port, starboard = turning_circle(ship, speed, -1).record, turning_circle(ship, speed, 1).record
    assert np.allclose(port.north, starboard.north, atol=1e-6)
    assert np.allclose(port.east, -starboard.east, atol=1e-6)
    assert np.allclose(port.heading, -starboard.heading, atol=1e-9)


@pytest.mark.parametrize("name", ["s175", "supply", "tanker", "kvlcc2"])
def test_no_rudder_keeps_a_straight_course(name):
    """Calm water, rudder amidships, the engine at the approach: ten minutes later she is on the same heading with
    no sway or turn, exactly (the course-unstable models too: nothing disturbs them)."""
    file, ship = load_ship(VESSELS / f"{name}.toml")
    state = ship.steady(file.approach_speed_kn * KNOT, psi=math.radians(37.0))
    for _ in range(6000):
        state, _ = ship.step(state, Orders(rps=state.n))
    assert state.psi == math.radians(37.0) and state.v == 0.0 and state.r == 0.0


@pytest.mark.parametrize("name", ["s175", "supply", "tanker", "kvlcc2"])
def test_autopilot_brings_her_round_without_overshoot_at_its_rate_limit(name):
    """A 60 deg course change by autopilot: the heading comes within 0.5 deg of the new course in 6 minutes and
    stays there, goes past it by less than 1 deg (course-unstable ships too), and the rate of turn stays within
    the autopilot's limit but for 10 %, reaching 70 % of it at least (it turns her as fast as it may, not
    slower)."""
    file, ship = load_ship(VESSELS / f"{name}.toml")
    speed = file.approach_speed_kn * KNOT
    state = ship.steady(speed)
    course = math.radians(60.0)
    headings, rates = [], []
    for _ in range(6000):
        state, _ = ship.step(state, Orders(rps=state.n, autopilot=True, course=course))
        headings.append(math.degrees(state.psi))
        rates.append(math.degrees(state.r) * 60.0)
    limit = math.degrees(ship.autopilot.rate_limit) * 60.0
    assert max(headings) - 60.0 < 1.0
    assert np.abs(np.array(headings[3600:]) - 60.0).max() < 0.5
    assert 0.7 * limit < max(rates) < 1.1 * limit


def test_steering_gear_and_engine_follow_their_orders_at_their_rates(kvlcc2):
    """Hard over from midships takes 35 / 2.32 = 15.1 s; the propeller reaches 63 % of a new order in its time
    constant (20 s)."""
    ship, speed = kvlcc2
    state = ship.steady(speed)
    n0 = state.n
    for k in range(200):
        state, _ = ship.step(state, Orders(rudder=math.radians(35.0), rps=0.0))
        if k == 149:
            assert math.degrees(state.delta) == pytest.approx(2.32 * 15.0, abs=1e-9)
        if k == 199:
            assert state.n == pytest.approx(n0 * math.exp(-1.0), rel=1e-9)
    assert math.degrees(state.delta) == pytest.approx(35.0)


@pytest.mark.parametrize("name", ["s175", "kvlcc2", "supply"])
def test_stopped_in_a_turn_then_astern_she_stays_physical_and_steers_the_other_way(name):
    """Hard over, the engine stopped for twenty minutes (the propeller's rate reaches zero, not a vanishing one whose
    advance ratio overflows), then full astern: she stops and gathers sternway with every state finite, and going
    astern a starboard rudder swings her bow to port (the flow meets the rudder from aft)."""
    file, ship = load_ship(VESSELS / f"{name}.toml")
    state = ship.steady(file.approach_speed_kn * KNOT)
    for orders, seconds in ((Orders(rudder=math.radians(35.0), rps=state.n), 300),
                            (Orders(rudder=math.radians(35.0), rps=0.0), 1200),
                            (Orders(rudder=math.radians(20.0), rps=-ship.engine.max_astern_rps), 1500)):
        for _ in range(seconds * 10):
            state, _ = ship.step(state, orders)
            assert all(map(math.isfinite, (state.u, state.v, state.r, state.p, state.phi)))
        if orders.rps == 0.0:
            assert state.n == 0.0 and 0.0 < state.u < 1.0
    assert state.u < -1.0 and state.r < 0.0
