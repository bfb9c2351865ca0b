"""The offshore crane's load (:mod:`marinesim.offshore.crane`) against closed forms: the pendulum's period, the
linear forced pendulum, energy, statics, quasi-static landing and the spring-mass estimate of snap loads.

The crane stands on the centreline, its tip 30 m above the waterline and 20 m forward of the pedestal at slew 0; a
10 t load hangs on a 40 mm wire (EA 1e8 N). With the vessel still, the body frame is the E frame.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import marinesim.offshore.crane as crane_module
from marinesim.constants import G
from marinesim.errors import ParameterError
from marinesim.offshore.crane import Crane, Lift, Load
from marinesim.pose import RotationKinematics

CHART = ((10.0, 60.0), (28.0, 30.0), (35.0, 15.0))
MASS = 10_000.0
EA = 1.0e8
TIP = np.array([20.0, 0.0, 30.0])


def make_crane(**changes) -> Crane:
    values = dict(pedestal_m=(0.0, 0.0, 20.0), boom_height_m=10.0, radius_m=20.0, hoist_speed_m_s=0.5,
                  slew_rate_deg_s=1.0, max_wire_m=60.0, load_chart=CHART)
    return Crane(**(values | changes))


def still(times: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The vessel at rest, her body frame on the E frame."""
    return np.array(points, dtype=float), np.zeros(np.shape(points))


def surging(x, x_dot):
    """The vessel translated along E x by ``x(t)`` (m), at ``x_dot(t)`` (m/s)."""
    def motion(times, points):
        shift = np.zeros(np.shape(points))
        velocity = np.zeros(np.shape(points))
        shift[:, 0], velocity[:, 0] = x(times), x_dot(times)
        return points + shift, velocity
    return motion


def heaving_deck(mean: float, amplitude: float, w: float):
    """A deck at ``mean + amplitude sin(w t)`` (m), its velocity and acceleration: the spot and the closed forms."""
    def spot(times):
        return mean + amplitude * np.sin(w * times), amplitude * w * np.cos(w * times)
    return (spot, lambda t: mean + amplitude * np.sin(w * t), lambda t: amplitude * w * np.cos(w * t),
            lambda t: -amplitude * w * w * np.sin(w * t))


def stretched(wire: float) -> float:
    """The length of a wire ``wire`` m long under the load's weight (m)."""
    return wire * (1.0 + MASS * G / EA)


def forced(t: np.ndarray, amplitude: float, w: float, w0: float) -> np.ndarray:
    """x'' + w0^2 x = w0^2 A sin(w t) with x(0) = 0 and x'(0) = A w (the load moving with the tip at the start)."""
    ratio = w0 ** 2 / (w0 ** 2 - w ** 2)
    return amplitude * ratio * np.sin(w * t) + amplitude * w * (1.0 - ratio) / w0 * np.sin(w0 * t)


def edges(times: np.ndarray, flags: np.ndarray) -> np.ndarray:
    """The times at which ``flags`` changes (the first time of the new value)."""
    return times[np.flatnonzero(np.diff(flags.astype(int))) + 1]


def test_small_swing_period_is_the_pendulum_with_the_stretched_wire():
    """A small free swing under a still tip has the period 2 pi sqrt(l / g), l the wire stretched by the weight: a
    wrong gravity, a force not along the wire, the stretch left out (5e-4 of the period) or a step that drifts the
    phase fail it; within 2e-4 (the amplitude's own correction, theta^2 / 16, is 2e-5)."""
    lift = Lift(make_crane(), Load(mass_kg=MASS), 20.0, still)
    lift.slew(0.0, 1.0)
    lift.slew(1.0, 0.0)  # the tip swept 1 deg (0.35 m), then still: the load swings about 1 deg
    t = np.arange(2.0, 80.0, 0.01)
    s = lift.sample(t)
    y = s["load_y_m"] - s["tip_y_m"]
    up = np.flatnonzero((y[:-1] < 0.0) & (y[1:] >= 0.0))
    crossings = t[up] - y[up] * (t[up + 1] - t[up]) / (y[up + 1] - y[up])
    period = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    expected = 2.0 * math.pi * math.sqrt(stretched(20.0) / G)
    assert len(crossings) >= 8
    assert period == pytest.approx(expected, rel=2e-4)  # the stretch alone is 5e-4


def test_tag_lines_damp_the_swing_at_their_ratio():
    """With the tag lines' damping ratio zeta the free swing decays as a damped oscillator's: successive peaks in
    the ratio exp(-2 pi zeta / sqrt(1 - zeta^2)) (the logarithmic decrement), and the period lengthens by
    1 / sqrt(1 - zeta^2). A damping against the load's absolute velocity, or scaled by the wrong frequency, fails it;
    within 1 % of the decrement."""
    zeta = 0.08
    lift = Lift(make_crane(), Load(mass_kg=MASS, swing_damping_ratio=zeta), 20.0, still)
    lift.slew(0.0, 1.0)
    lift.slew(1.0, 0.0)
    t = np.arange(2.0, 60.0, 0.005)
    s = lift.sample(t)
    y = s["load_y_m"] - s["tip_y_m"]
    peaks = np.flatnonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:]) & (y[1:-1] > 0.0)) + 1
    decrement = np.log(y[peaks[:-1]] / y[peaks[1:]])
    assert len(peaks) >= 4
    np.testing.assert_allclose(decrement, 2 * math.pi * zeta / math.sqrt(1 - zeta**2), rtol=1e-2)
    w0 = math.sqrt(G / stretched(20.0))
    period = np.diff(t[peaks]).mean()
    assert period == pytest.approx(2 * math.pi / (w0 * math.sqrt(1 - zeta**2)), rel=2e-3)


def test_forced_pendulum_follows_the_linear_solution():
    """A tip moved A sin(w t) along x swings the load as x'' + w0^2 x = w0^2 A sin(w t) (w0^2 = g / l), with the
    transient of its start; the fitted response at w has the ratio w0^2 / (w0^2 - w^2). A wrong coupling to the tip
    (its velocity or position), a phase error of the steps or of the start would show; within 0.1 % of the response
    (the swing is 1.3 deg: the linear theory's own error is some theta^2 / 16 = 3e-5)."""
    amplitude, w = 0.2, 0.4
    motion = surging(lambda t: amplitude * np.sin(w * t), lambda t: amplitude * w * np.cos(w * t))
    lift = Lift(make_crane(), Load(mass_kg=MASS), 20.0, motion)
    w0 = math.sqrt(G / stretched(20.0))
    t = np.arange(0.0, 60.0, 0.05)
    x = lift.sample(t)["load_x_m"] - TIP[0]
    ratio = w0 ** 2 / (w0 ** 2 - w ** 2)
    assert np.max(np.abs(x - forced(t, amplitude, w, w0))) < 1e-3 * amplitude * ratio
    basis = np.column_stack([np.sin(w * t), np.cos(w * t), np.sin(w0 * t), np.cos(w0 * t)])
    coefficients = np.linalg.lstsq(basis, x, rcond=None)[0]
    assert coefficients[0] / amplitude == pytest.approx(ratio, rel=1e-3)


def test_energy_is_conserved_without_damping():
    """Without damping and with the tip still, kinetic + potential + elastic energy stays constant through 100 s of a
    20 deg conical swing: a force not derived from the wire's energy, a wrong elastic law or a dissipating (or
    unstable) integrator would drift."""
    wire = 20.0
    l = stretched(wire)
    reach = l * math.sin(math.radians(22.0))  # moved in 2 s (the axial period 0.28 s): the wire stays taut

    def smooth(t, start, duration):
        s = np.clip((t - start) / duration, 0.0, 1.0)
        return s ** 3 * (10.0 - 15.0 * s + 6.0 * s * s), 30.0 * s * s * (1.0 - s) ** 2 / duration

    def motion(times, points):
        (x, vx), (y, vy) = smooth(times, 0.0, 2.0), smooth(times, 1.0, 2.0)
        shift = np.column_stack([reach * x, 0.4 * reach * y, np.zeros(times.shape)])
        return points + shift, np.column_stack([reach * vx, 0.4 * reach * vy, np.zeros(times.shape)])

    lift = Lift(make_crane(), Load(mass_kg=MASS, damping_ratio=0.0), wire, motion)
    s = lift.sample(np.arange(3.0, 103.0, 0.01))
    d = np.sqrt((s["load_x_m"] - s["tip_x_m"]) ** 2 + (s["load_y_m"] - s["tip_y_m"]) ** 2
                + (s["load_z_m"] - s["tip_z_m"]) ** 2)
    speed2 = s["load_vx_m_s"] ** 2 + s["load_vy_m_s"] ** 2 + s["load_vz_m_s"] ** 2
    energy = 0.5 * MASS * speed2 + MASS * G * s["load_z_m"] + 0.5 * EA / wire * np.maximum(d - wire, 0.0) ** 2
    swing = MASS * G * l * (1.0 - math.cos(math.radians(20.0)))
    assert np.max(np.degrees(np.arctan2(np.hypot(s["load_x_m"] - s["tip_x_m"], s["load_y_m"] - s["tip_y_m"]),
                                        s["tip_z_m"] - s["load_z_m"]))) > 18.0
    assert not s["slack"].any()
    assert (energy.max() - energy.min()) / swing < 1e-5


def test_static_tension_and_stretch_after_paying_out():
    """Paid out from 20 to 30 m and settled, the wire holds m g and is stretched m g L / EA with L the new length:
    a stiffness kept from the old length, a tension that is not EA/L times the stretch, or a load left oscillating
    would show; within 1e-5."""
    lift = Lift(make_crane(), Load(mass_kg=MASS), 20.0, still)
    lift.hoist(0.0, -0.5)
    lift.hoist(20.0, 0.0)
    s = lift.sample(np.array([0.0, 40.0, 42.5, 45.0]))
    d = np.sqrt((s["load_x_m"] - s["tip_x_m"]) ** 2 + (s["load_y_m"] - s["tip_y_m"]) ** 2
                + (s["load_z_m"] - s["tip_z_m"]) ** 2)
    assert s["wire_length_m"].tolist() == [20.0, 30.0, 30.0, 30.0]
    assert s["tension_kn"] * 1e3 == pytest.approx(np.full(4, MASS * G), rel=1e-5)
    assert d - s["wire_length_m"] == pytest.approx(MASS * G * s["wire_length_m"] / EA, rel=1e-5)


def test_slack_follows_the_heaving_deck():
    """A load landed on a deck heaving 0.5 m at 8 s, the wire paid out to hold it 0.3 m below the crest, is slack
    while the deck holds the load above the unstretched wire's end: quasi-statically, the deck's height less the
    contact's give m (g + a_deck) / k_c, plus the wire's damping stretch c v_deck / k_w while it unloads, above
    tip - L. The slack intervals' edges fall within two steps of that condition's roots, every cycle: a contact or
    slack logic that leaves the load hanging on a slack wire, lets the wire push, or lags would show."""
    spot, z_deck, v_deck, a_deck = heaving_deck(5.0, 0.5, 2.0 * math.pi / 8.0)
    end = 5.2  # the wire's unstretched end (m, E)
    wire = TIP[2] - end
    load = Load(mass_kg=MASS)
    lift = Lift(make_crane(), load, wire, still, spot)
    h = lift.step_s
    t = np.arange(0.0, 40.0, h)
    s = lift.sample(t)
    stiffness = EA / wire
    damping = 2.0 * load.damping_ratio * math.sqrt(stiffness * MASS)

    def margin(time):
        held = z_deck(time) - MASS * (G + a_deck(time)) / lift.contact_stiffness_n_m
        return held + max(v_deck(time), 0.0) * damping / stiffness - end

    grid = np.arange(0.0, 40.0, 0.01)
    values = np.array([margin(time) for time in grid])
    signs = np.flatnonzero(np.diff(np.sign(values)))
    expected = np.array([brentq(margin, grid[i], grid[i + 1]) for i in signs])
    found = edges(t, s["slack"])
    assert len(found) == len(expected) == 10
    assert np.max(np.abs(found - expected)) <= 2.0 * h
    assert np.all(s["landed"][s["slack"]])
    assert not np.any(s["slack"][(t > 1.0) & ~s["landed"]])


def test_snap_after_slack_matches_the_spring_mass_estimate():
    """When the falling deck gives the load back to the wire, the load leaves the deck where k_w (tip - L - z_deck)
    = m (g + a_deck), moving at the deck's velocity (shared by the springs in series), and swings on the wire alone:
    peak tension m g + sqrt((m a)^2 + k_w m v^2), above m g (the snap). Undamped, within 0.2 %: a wire whose
    stiffness, mass coupling or re-tensioning were wrong would show."""
    spot, z_deck, v_deck, a_deck = heaving_deck(5.0, 0.5, 2.0 * math.pi / 8.0)
    end = 5.2
    wire = TIP[2] - end
    lift = Lift(make_crane(), Load(mass_kg=MASS, damping_ratio=0.0), wire, still, spot)
    h, k_c, k_w = lift.step_s, lift.contact_stiffness_n_m, EA / wire
    leave = brentq(lambda time: k_w * (end - z_deck(time)) - MASS * (G + a_deck(time)), 2.5, 4.0)
    t = np.arange(0.0, leave + 0.5, h)
    s = lift.sample(t)
    v = k_c * v_deck(leave) / (k_c + k_w)
    peak = MASS * G + math.sqrt((MASS * a_deck(leave)) ** 2 + k_w * MASS * v * v)
    assert abs(edges(t, s["landed"])[-1] - leave) <= 2.0 * h
    first = (t > leave) & (t < leave + math.pi * math.sqrt(MASS / k_w))  # the first half swing on the wire
    assert s["tension_kn"][first].max() * 1e3 == pytest.approx(peak, rel=2e-3)
    assert peak > 1.5 * MASS * G


def test_lift_off_from_a_heaving_deck():
    """Resting on a falling deck with the wire slack, the load hoisted at v_h lifts off where the shortening wire
    holds m (g + a_deck), at the springs' shared velocity, and then peaks at m g + sqrt((m a)^2 + k_w m (v_h - v)^2):
    the dynamic amplification of a lift-off. Undamped, within 0.2 %, and the load clear of the deck after: a wire
    stiffness not EA over the length now paid out, or a deck that holds on, would show."""
    spot, z_deck, v_deck, a_deck = heaving_deck(5.0, 0.5, 2.0 * math.pi / 8.0)
    lift = Lift(make_crane(), Load(mass_kg=MASS, damping_ratio=0.0), 23.0, still, spot)
    lift.hoist(0.0, -0.5)
    lift.hoist(6.0, 0.0)  # 26 m out: the load on the deck, the wire slack even at the trough
    lift.hoist(10.0, 0.5)
    h, k_c = lift.step_s, lift.contact_stiffness_n_m

    def wire(time):
        return 26.0 - 0.5 * (time - 10.0)

    def hold(time):
        return EA / wire(time) * (TIP[2] - wire(time) - z_deck(time)) - MASS * (G + a_deck(time))

    off = brentq(hold, 11.0, 13.0)
    t = np.arange(8.0, off + 1.0, h)
    s = lift.sample(t)
    k_w = EA / wire(off)
    v = (k_w * 0.5 + k_c * v_deck(off)) / (k_w + k_c)
    peak = MASS * G + math.sqrt((MASS * a_deck(off)) ** 2 + k_w * MASS * (0.5 - v) ** 2)
    assert v_deck(off) < -0.3  # the deck falling: a hard lift-off
    assert s["landed"][t < 11.0].all() and s["slack"][t < 11.0].all()
    assert abs(edges(t, s["landed"])[-1] - off) <= 2.0 * h
    first = (t > off) & (t < off + math.pi * math.sqrt(MASS / k_w))  # the first half swing on the wire
    assert s["tension_kn"][first].max() * 1e3 == pytest.approx(peak, rel=2e-3)
    assert s["load_above_spot_m"][t > off + 0.05].min() > 0.0


def test_refusals_one_line_each():
    """Over the chart's SWL, outside its radii, a wire reaching below the sea floor, a wire too stiff for the step,
    bad numbers and orders: each refused in one line naming what is wrong (else the lift goes on with nonsense)."""
    with pytest.raises(ParameterError, match=r"^load 45\.0 t exceeds the crane's safe working load 30\.0 t at "
                                             r"radius 28\.0 m$"):
        Lift(make_crane(radius_m=28.0), Load(mass_kg=45_000.0), 20.0, still)
    with pytest.raises(ParameterError, match=r"^crane radius_m 40 m is outside its load chart \(10\.\.35 m\)$"):
        make_crane(radius_m=40.0).check(Load(mass_kg=1000.0))
    with pytest.raises(ParameterError, match=r"^crane max_wire_m 60 m reaches below the sea floor: the tip is 30 m "
                                             r"above the water in 25 m of water \(55 m\)$"):
        Lift(make_crane(), Load(mass_kg=MASS), 20.0, still, depth_m=25.0)
    Lift(make_crane(), Load(mass_kg=MASS), 20.0, still, depth_m=30.0)
    too_short = r"^crane min_wire_m 0\.5 m is too short .*; give at least 1\.\d+ m, or a softer wire$"
    with pytest.raises(ParameterError, match=too_short):
        Lift(make_crane(), Load(mass_kg=500.0), 20.0, still)
    light = Lift(make_crane(min_wire_m=2.0), Load(mass_kg=500.0), 20.0, still)
    assert light.step_s >= crane_module.MIN_STEP_S
    with pytest.raises(ParameterError, match=r"^wire_m 5 m puts the load"):
        Lift(make_crane(), Load(mass_kg=MASS), 5.0, still, lambda t: (np.full(t.shape, 26.0), np.zeros(t.shape)))
    for build in (lambda: Load(mass_kg=math.nan), lambda: Load(mass_kg=MASS, wire_ea_n=-1.0),
                  lambda: make_crane(hoist_speed_m_s=-0.5), lambda: make_crane(load_chart=((30.0, 5.0), (10.0, 9.0))),
                  lambda: Lift(make_crane(), Load(mass_kg=MASS), 61.0, still)):
        with pytest.raises(ParameterError) as refused:
            build()
        assert "\n" not in str(refused.value)
    lift = Lift(make_crane(), Load(mass_kg=MASS), 20.0, still)
    with pytest.raises(ParameterError, match="order time"):
        lift.hoist(-1.0, 0.2)
    with pytest.raises(ParameterError, match="hoist speed_m_s"):
        lift.hoist(1.0, math.inf)


def rolling_and_yawing(times, points):
    """A vessel sailing east at 2 m/s, rolling 3 deg at 12 s and yawing 2 deg at 20 s (R = Rz(yaw) Rx(roll))."""
    roll, roll_rate = math.radians(3.0) * np.sin(0.52 * times), math.radians(3.0) * 0.52 * np.cos(0.52 * times)
    yaw, yaw_rate = math.radians(2.0) * np.sin(0.31 * times), math.radians(2.0) * 0.31 * np.cos(0.31 * times)
    cr, sr, cy, sy = np.cos(roll), np.sin(roll), np.cos(yaw), np.sin(yaw)
    x, y, z = points.T
    ry, rz = cr * y - sr * z, sr * y + cr * z  # Rx(roll) p
    ry_dot, rz_dot = roll_rate * (-sr * y - cr * z), roll_rate * (cr * y - sr * z)
    positions = np.column_stack([2.0 * times + cy * x - sy * ry, sy * x + cy * ry, rz])
    velocities = np.column_stack([2.0 - yaw_rate * (sy * x + cy * ry) - sy * ry_dot,
                                  yaw_rate * (cy * x - sy * ry) + cy * ry_dot, rz_dot])
    return positions, velocities


def busy_lift(**kwargs) -> Lift:
    spot, *_ = heaving_deck(9.0, 0.4, 2.0 * math.pi / 7.0)
    return Lift(make_crane(), Load(mass_kg=MASS), 20.0, rolling_and_yawing, spot, **kwargs)


def bits(sample: dict[str, np.ndarray], at=slice(None)) -> dict[str, bytes]:
    return {key: np.ascontiguousarray(value[at]).tobytes() for key, value in sample.items()}


def test_same_orders_same_bits_whatever_was_asked():
    """The lift at a time is a function of the orders alone: times asked in another order, an order given after a
    sample (it changes nothing before its time, only after), orders given in another sequence, and blocks dropped
    and stepped again, all give the same bits. A state that depended on what was asked before would differ."""
    t = np.arange(0.0, 30.0, 0.037)
    lift = busy_lift()
    lift.hoist(3.0, -0.5)
    lift.slew(5.0, 1.0)
    before = lift.sample(t)
    assert before["landed"].any() and before["slack"].any()  # the deck reached: contact and slack both run
    order = np.random.default_rng(7).permutation(t.size)
    assert bits(lift.sample(t[order])) == bits(before, order)
    lift.hoist(20.0001, 0.4)
    after = lift.sample(t)
    early = t <= 20.0001
    assert bits(after, early) == bits(before, early)
    assert not np.array_equal(after["load_z_m"][~early], before["load_z_m"][~early])
    other = busy_lift()
    other.hoist(20.0001, 0.4)
    other.slew(5.0, 1.0)
    other.hoist(3.0, -0.5)
    assert bits(other.sample(t[::-1])) == bits(after, slice(None, None, -1))


def test_old_blocks_are_stepped_again_to_the_same_bits(monkeypatch):
    """With two blocks held, a minute of lift drops the first blocks; asked again they are stepped from their first
    state to the same bits (a recomputation that started elsewhere, or held everything, would show)."""
    monkeypatch.setattr(crane_module, "BLOCKS_KEPT", 2)
    lift = busy_lift()
    lift.slew(1.0, -1.0)
    early = np.arange(0.0, 6.0, 0.01)
    first = lift.sample(early)
    lift.sample(np.array([60.0]))
    assert len(lift._blocks) <= 2 and 0 not in lift._blocks
    assert bits(lift.sample(early)) == bits(first)


def test_hoist_follows_the_ordered_speed_within_the_crane_s():
    """The wire pays out at the crane's hoist speed when more is asked, stops at max_wire_m, hoists at the speed
    ordered, and the load follows it: hanging m g L / EA below the wire's end when settled, rising at the hoisting
    speed with the same stretch (the wire's damping sees no stretching). A wire rate that ignored the clip or the
    stop, a hoisting taken for stretching, or a load that did not follow, would show."""
    lift = Lift(make_crane(max_wire_m=30.0), Load(mass_kg=MASS), 20.0, still)
    lift.hoist(2.0, -5.0)
    lift.hoist(40.0, 0.3)
    t = np.arange(0.0, 56.0, 0.25)
    s = lift.sample(t)
    expected = np.where(t < 40.0, np.minimum(20.0 + 0.5 * np.maximum(t - 2.0, 0.0), 30.0), 30.0 - 0.3 * (t - 40.0))
    assert s["wire_length_m"] == pytest.approx(expected, abs=1e-12)
    settled = (t > 32.0) & (t < 40.0)
    assert s["load_z_m"][settled] == pytest.approx(TIP[2] - stretched(30.0), abs=1e-4)
    hoisting = t > 52.0
    assert s["load_vz_m_s"][hoisting] == pytest.approx(0.3, abs=1e-3)
    d = s["tip_z_m"] - s["load_z_m"]
    assert d[hoisting] - s["wire_length_m"][hoisting] == pytest.approx(
        MASS * G * s["wire_length_m"][hoisting] / EA, rel=1e-3)  # the wire shortening, not stretching


def test_slew_moves_the_tip_round_the_pedestal():
    """Slewing at the crane's rate (more asked) turns the tip round the pedestal at its radius, clockwise for a
    negative rate, and the load goes round with it, swinging no more than the two kinks of the tip's path excite
    (2 v / w0): a wrong sense of slew, a radius not kept, or a load left behind would show."""
    lift = Lift(make_crane(slew_deg=30.0), Load(mass_kg=MASS), 20.0, still)
    lift.slew(1.0, -4.0)
    lift.slew(31.0, 0.0)
    t = np.arange(0.0, 45.0, 0.125)
    s = lift.sample(t)
    angle = np.radians(30.0 - np.clip(t - 1.0, 0.0, 30.0))
    assert s["slew_deg"] == pytest.approx(np.degrees(angle), abs=1e-9)
    assert s["tip_x_m"] == pytest.approx(20.0 * np.cos(angle), abs=1e-9)
    assert s["tip_y_m"] == pytest.approx(20.0 * np.sin(angle), abs=1e-9)
    assert s["tip_z_m"] == pytest.approx(np.full(t.size, 30.0), abs=1e-12)
    offset = np.hypot(s["load_x_m"] - s["tip_x_m"], s["load_y_m"] - s["tip_y_m"])
    v, w0 = 20.0 * math.radians(1.0), math.sqrt(G / stretched(20.0))
    assert offset.max() <= 2.0 * v / w0
    assert offset.max() > 0.9 * v / w0


def test_tip_velocity_while_slewing_on_a_moving_vessel():
    """The tip's velocity (the vessel's at the tip, plus the slew turned into E) is the time derivative of its
    position, on a vessel sailing, rolling and yawing while the crane slews: a slew velocity left out or turned
    the wrong way would show."""
    lift = busy_lift()
    lift.slew(1.0, 1.0)
    t = np.array([2.3, 4.71, 7.9])
    delta = 1e-4
    ahead, behind, now = lift.sample(t + delta), lift.sample(t - delta), lift.sample(t)
    for axis in "xyz":
        derivative = (ahead[f"tip_{axis}_m"] - behind[f"tip_{axis}_m"]) / (2.0 * delta)
        assert now[f"tip_v{axis}_m_s"] == pytest.approx(derivative, abs=1e-6)


def test_roll_swings_the_load_as_the_tip_s_lateral_motion_forces_it():
    """A vessel rolling 1 deg at 12 s moves the tip 30 m above the roll axis sideways by -30 sin(roll): the load
    answers as the linear forced pendulum driven by that motion (the vessel's rotation from marinesim.pose). A wrong
    sense of roll or lever arm would show; within 0.2 % (sin(roll) ~ roll is good to 5e-5, the tip's heave
    30 (1 - cos(roll)) is 5 mm)."""
    amplitude, w = math.radians(1.0), 2.0 * math.pi / 12.0

    def rolling(times, points):
        assert np.all(points == points[0])  # no slewing: one body point
        zeros = np.zeros((times.size, 3))
        angles, rates, accelerations = zeros.copy(), zeros.copy(), zeros.copy()
        angles[:, 0] = amplitude * np.sin(w * times)
        rates[:, 0] = amplitude * w * np.cos(w * times)
        accelerations[:, 0] = -amplitude * w * w * np.sin(w * times)
        positions, velocities, _ = RotationKinematics(angles, rates, accelerations).points(points[:1], zeros, zeros,
                                                                                           zeros)
        return positions[:, 0], velocities[:, 0]

    lift = Lift(make_crane(), Load(mass_kg=MASS), 10.0, rolling)
    w0 = math.sqrt(G / stretched(10.0))
    t = np.arange(0.0, 40.0, 0.05)
    y = lift.sample(t)["load_y_m"]
    lateral = -TIP[2] * amplitude
    assert np.max(np.abs(y - forced(t, lateral, w, w0))) < 2e-3 * abs(lateral) * w0 ** 2 / (w0 ** 2 - w ** 2)
