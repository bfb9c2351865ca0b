"""Spray: the drops' flight, the bow impact that throws it (Ochi's threshold on the relative velocity at the stem),
spindrift from Beaufort 8, and the puffs on the picture."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

from conftest import ROOT, luminance, offscreen
from marinesim.constants import G
from marinesim.session.spray import (DROP_TERMINAL_M_S, SPINDRIFT_TERMINAL_M_S, SPRAY_ONSET, STEP_S, Bow, Puffs, Spray,
                                     flown, jet_speed, whitecap_fraction)
from marinesim.scenario import load_scenario
from marinesim.sea.seastate import scaled_sea
from marinesim.session.timeline import Simulation
from marinesim.vessel.response import Response


@pytest.fixture(scope="module")
def heavy():
    """The S175 at 18 kn into a head sea of Hs 3.4 m (wind sea and swell)."""
    return load_scenario(ROOT / "configs" / "s175_heavy_weather.toml")


def spray_of(scenario) -> tuple[Simulation, Spray]:
    sim = Simulation(scenario, wake=False)
    return sim, Spray(sim, Bow.of(scenario.vessel.hull, scenario.vessel.hull.vertices))


def stepped(position: np.ndarray, velocity: np.ndarray, terminal: float, wind: np.ndarray, h: float, steps: int
            ) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity (steps + 1, 3) of one drop flown ``steps`` times ``h`` s, as the spray steps it."""
    positions, velocities = [np.asarray(position, float)], [np.asarray(velocity, float)]
    for _ in range(steps):
        x, v = flown(positions[-1][None, :], velocities[-1][None, :], np.array([terminal]), wind, h)
        positions.append(x[0])
        velocities.append(v[0])
    return np.array(positions), np.array(velocities)


def test_drops_fly_as_gravity_and_quadratic_drag_against_the_wind_make_them():
    """Stepped on the spray's clock, a 3 mm drop thrown across a 13 m/s wind follows a tight numerical integration
    of dv/dt = -g z - g |v - w| (v - w) / v_t^2 to a few millimetres over 1.7 s, half the step quarters the error
    (second order: a wrong sign or a missing term would leave an error that does not shrink so), and it ends up
    drifting with the wind and falling at its terminal speed (Gunn & Kinzer: 8.06 m/s)."""
    wind = np.array([-12.0, 5.0, 0.0])
    position, velocity = np.array([1.0, 2.0, 3.0]), np.array([8.0, 0.0, 11.0])

    def rates(_, state):
        u = state[3:] - wind
        return np.r_[state[3:], -G * np.array([0.0, 0.0, 1.0]) - G * np.linalg.norm(u) * u / DROP_TERMINAL_M_S ** 2]

    numeric = solve_ivp(rates, (0.0, 1.7), np.r_[position, velocity], method="DOP853", rtol=1e-11, atol=1e-11)
    errors = []
    for h, steps in ((STEP_S, 51), (STEP_S / 2.0, 102)):
        x, v = stepped(position, velocity, DROP_TERMINAL_M_S, wind, h, steps)
        errors.append((np.linalg.norm(x[-1] - numeric.y[:3, -1]), np.linalg.norm(v[-1] - numeric.y[3:, -1])))
    assert errors[0][0] < 0.005 and errors[0][1] < 0.005, errors   # mm on a puff 1.5 m wide
    np.testing.assert_allclose(np.array(errors[1]) / np.array(errors[0]), 0.25, atol=0.05)
    _, late = flown(position[None, :], velocity[None, :], np.array([DROP_TERMINAL_M_S]), wind, 30.0)
    np.testing.assert_allclose(late[0], wind - [0.0, 0.0, DROP_TERMINAL_M_S], rtol=0.01)


@pytest.mark.parametrize("terminal", [DROP_TERMINAL_M_S, SPINDRIFT_TERMINAL_M_S])
def test_a_drop_let_go_in_still_air_falls_and_one_thrown_up_rises_as_quadratic_drag_says(terminal):
    """1-D closed forms of quadratic drag: from rest a drop falls at v_t tanh(g t / v_t) and reaches its
    terminal speed (within 1 %); thrown straight up at 20 m/s it slows as v_t tan(atan(20 / v_t) - g t / v_t) to
    its apex. Linear drag would approach v_t as 1 - exp(-g t / v_t), 17 % slower at t = v_t / g; no drag
    would never level off; a drag that does not balance gravity at v_t would settle elsewhere."""
    still = np.zeros(3)
    steps = int(5.0 * terminal / G / STEP_S)
    _, fall = stepped(np.zeros(3), np.zeros(3), terminal, still, STEP_S, steps)
    t = STEP_S * np.arange(steps + 1)
    np.testing.assert_allclose(fall[:, :2], 0.0, atol=1e-12)
    np.testing.assert_allclose(-fall[:, 2], terminal * np.tanh(G * t / terminal), atol=0.01 * terminal)
    assert -fall[-1, 2] == pytest.approx(terminal, rel=0.01)
    _, settled = flown(np.zeros((1, 3)), np.zeros((1, 3)), np.array([terminal]), still, 30.0)
    assert -settled[0, 2] == pytest.approx(terminal, rel=0.01)

    apex_s = terminal / G * np.arctan(20.0 / terminal)
    steps = int(apex_s / STEP_S)
    _, rise = stepped(np.zeros(3), np.array([0.0, 0.0, 20.0]), terminal, still, STEP_S, steps)
    t = STEP_S * np.arange(steps + 1)
    np.testing.assert_allclose(rise[:, 2], terminal * np.tan(np.arctan(20.0 / terminal) - G * t / terminal),
                               atol=0.01 * 20.0)


def test_a_drop_thrown_sideways_slows_as_quadratic_drag_alone_would_at_first():
    """A 3 mm drop thrown horizontally at 20 m/s in still air: without gravity quadratic drag slows it as
    u0 / (1 + k u0 t), k = g / v_t^2, and it goes ln(1 + k u0 t) / k. Gravity's fall only adds drag, so that is
    an upper bound, and as the fall is at most g t, the horizontal speed is within a factor
    exp(-k g^2 t^3 / (6 u)) below it: 0.16 % at 0.2 s. Linear drag (26 % faster at 0.2 s) fails it."""
    k, u0 = G / DROP_TERMINAL_M_S ** 2, 20.0
    x, v = stepped(np.zeros(3), np.array([u0, 0.0, 0.0]), DROP_TERMINAL_M_S, np.zeros(3), STEP_S, 6)
    t = STEP_S * np.arange(7)
    alone = u0 / (1.0 + k * u0 * t)
    assert np.all(v[:, 0] <= alone * (1.0 + 1e-12)) and np.all(x[:, 0] <= np.log1p(k * u0 * t) / k + 1e-12)
    assert np.all(v[:, 0] >= alone * np.exp(-k * G ** 2 * t ** 3 / (6.0 * v[:, 0])))
    assert v[-1, 0] == pytest.approx(u0 / (1.0 + k * u0 * 0.2), rel=0.002)


def test_the_jet_leaves_the_flare_at_twice_the_spray_roots_speed(heavy):
    """Wagner's condition for a wedge y = |x| tan(beta) entering at V, integral_0^(pi/2) y(c sin a) da =
    (pi / 2) V t, solved numerically for the wetted half-width c(t), gives the spray root's speed dc/dt; the
    jet leaves at twice it relative to the body (Zhao & Faltinsen 1993). The puffs a bow impact throws leave the
    stem's velocity at that speed for flares of 20-40 deg: at the root's speed they would fly half as fast."""
    def half_width(beta, v, t):
        def wagner(c):
            return quad(lambda a: c * np.sin(a) * np.tan(beta), 0.0, 0.5 * np.pi)[0] - 0.5 * np.pi * v * t
        return brentq(wagner, 1e-9, 1e3)

    for beta in np.radians([10.0, 20.0, 30.0, 40.0]):
        root = (half_width(beta, 3.0, 0.02) - half_width(beta, 3.0, 0.01)) / 0.01
        assert jet_speed(3.0, beta) == pytest.approx(2.0 * root, rel=1e-8)

    sim, spray = spray_of(heavy)
    sim.advance_to(50.0)
    rising = 2.0 * spray.threshold_m_s()
    spray._bow_spray(sim.time, np.array([0.0, rising, 0.0, 0.0]), np.random.default_rng(3))
    thrown = spray._stepped
    assert len(thrown) > 50
    relative = np.linalg.norm(thrown.velocity - np.r_[sim.velocity(), 0.0], axis=1)
    low, high = jet_speed(rising, np.radians(40.0)), jet_speed(rising, np.radians(20.0))
    assert np.all(relative >= low * (1.0 - 1e-9)) and np.all(relative <= high * (1.0 + 1e-9))
    assert relative.min() < 1.1 * low and relative.max() > 0.9 * high   # the flares' whole range
    sim.close()


def test_the_relative_motion_at_the_stem_is_the_exported_one_and_rises_at_its_derivative(heavy):
    """The water's height over the stem is the export's relative motion of a point at the stem (with the sign
    turned: the water over the point), the stem's height and vertical velocity are the export's, and its rising
    speed is that height's time derivative, at the encounter
    frequency: taken at the waves' own frequency it would be about half as fast in this head sea."""
    sim, spray = spray_of(heavy)
    height, rising, stem_z, stem_vz = spray.at_stem(120.0, 0.002, 1500).T
    times = 120.0 + 0.002 * np.arange(1500)
    response = sim.assembly.response  # she runs straight: the scenario's track
    exported = Response(response.rao, response.components, response.track, {"stem": tuple(spray.bow.stem)})
    frame = exported.frame(times)
    relative = frame["stem_relative_m"]
    assert np.abs(height + relative).max() < 0.01 * np.ptp(relative)   # the export turns the pitch exactly
    assert np.abs(stem_z - frame["stem_z_m"]).max() < 0.01 * np.ptp(frame["stem_z_m"])
    assert np.abs(stem_vz - frame["stem_vz_m_s"]).max() < 0.01 * np.ptp(frame["stem_vz_m_s"])
    derivative = np.gradient(height, times)
    assert np.abs(derivative - rising)[5:-5].max() < 0.01 * np.abs(rising).max()
    sim.close()


def test_the_bow_throws_spray_when_the_sea_rises_against_it_past_the_onset_and_only_then(heavy):
    """Over 200 s the puffs are born only in the steps where the water rises at the stem faster than half
    Ochi's threshold, near the stem and upwards; a sea a fifth as high throws none."""
    sim, spray = spray_of(heavy)
    v_th = spray.threshold_m_s()
    assert v_th == pytest.approx(0.093 * np.sqrt(G * spray.bow.length_m))
    assert 170.0 < spray.bow.length_m < 180.0   # the S175's waterline
    height, rising = spray.at_stem(0.0, STEP_S, 6000)[:, :2].T
    wet = (height > -spray.bow.draft_m) & (height < spray.bow.freeboard_m)
    fast = np.flatnonzero(wet & (rising > SPRAY_ONSET * v_th))
    assert fast.size > 0
    born_at = []
    for k in range(1, 6000, 3):
        before = len(spray.puffs)
        sim.advance_to(k * STEP_S)
        spray.update(np.zeros(3))
        if len(spray.puffs) > before:
            born_at.append(k)
            fresh = spray.puffs.where(spray.puffs.age < 3.5 * STEP_S)
            stem = sim.pose().world(spray.bow.stem[None, :])[0]
            assert np.all(np.hypot(*(fresh.position[:, :2] - stem[:2]).T) < spray.bow.reach_m + 15.0)
            assert np.all(fresh.velocity[:, 2] > 0.0)
    assert born_at
    near = np.min(np.abs(np.array(born_at)[:, None] - fast[None, :]), axis=1)
    assert np.all(near <= 3)   # every birth within a step of a fast rise
    sim.close()

    calm = dataclasses.replace(heavy, sea=scaled_sea(heavy.sea, 0.2, 1.0, 0.0))
    sim, spray = spray_of(calm)
    for t in np.arange(1.0, 200.0, 4.0):
        sim.advance_to(t)
        spray.update(np.zeros(3))
        assert len(spray.puffs.where(spray.puffs.kind == 0)) == 0
    sim.close()


def test_spindrift_blows_off_the_crests_from_beaufort_8_and_not_below(heavy):
    """No spindrift at 15 m/s; at 25 m/s puffs leave crests around the ship and drift downwind, as many as the
    whitecap cover makes; the same run gives the same puffs."""
    sim, spray = spray_of(heavy)
    sim.advance_to(60.0)
    spray.update(np.array([15.0, 0.0, 0.0]))
    assert len(spray.puffs.where(spray.puffs.kind == 1)) == 0
    sim.close()

    counts, runs = [], []
    for _ in range(2):
        sim, spray = spray_of(heavy)
        sim.advance_to(60.0)
        spray.update(np.array([0.0, -25.0, 0.0]))
        drift = spray.puffs.where(spray.puffs.kind == 1)
        counts.append(len(drift))
        runs.append(drift.position.copy())
        sim.close()
    np.testing.assert_array_equal(runs[0], runs[1])
    assert whitecap_fraction(25.0) == pytest.approx(3.84e-6 * 25.0 ** 3.41)
    assert counts[0] > 100
    assert np.mean(drift.velocity[:, 1]) < -10.0 and abs(np.mean(drift.velocity[:, 0])) < 2.0
    sim, spray = spray_of(heavy)
    sim.advance_to(60.0)
    spray.update(np.array([0.0, -21.0, 0.0]))
    fewer = len(spray.puffs.where(spray.puffs.kind == 1))
    sim.close()
    assert fewer / counts[0] == pytest.approx(whitecap_fraction(21.0) / whitecap_fraction(25.0), rel=0.25)


def test_left_to_itself_the_spray_feels_the_runs_wind_and_its_changes(heavy):
    """Asked for its puffs with no wind given (as the renderer asks), the spray feels the run's wind at 10 m: a
    25 m/s northerly carries the spindrift south, and once the wind has eased to 15 m/s (below Beaufort 8) none is
    in flight. What would be wrong: a spray that feels no wind (no spindrift, puffs that rise and fall where they
    left), the wind's bearing taken as where it blows to (puffs carried north), or the scenario's wind kept after a
    change of weather."""
    northerly = dataclasses.replace(heavy, environment=heavy.environment.model_copy(
        update={"wind_speed_m_s": 25.0, "wind_from_deg": 0.0}))
    sim, spray = spray_of(northerly)
    sim.advance_to(60.0)
    puffs = spray.update()
    drift = puffs.where(puffs.kind == 1)
    assert len(drift) > 100
    assert np.mean(drift.velocity[:, 1]) < -10.0 and abs(np.mean(drift.velocity[:, 0])) < 2.0
    sim.change_weather(wind_speed_m_s=15.0)
    for t in np.arange(60.5, 70.0, 0.5):   # frames two a second: the spray moved on through the change
        sim.advance_to(float(t))
        spray.update()
    sim.close()
    assert len(spray.puffs.where(spray.puffs.kind == 1)) == 0


def test_the_same_run_throws_the_same_spray_whatever_the_frame_rate(heavy):
    """Ten seconds around a bow impact stepped at 30 and at 24 frames a second end with the same puffs in the same
    places: births and flights keep to the run's clock."""
    ends = []
    for rate in (30.0, 24.0):
        sim, spray = spray_of(heavy)
        sim.advance_to(100.0)
        spray.update(np.array([0.0, -25.0, 0.0]))
        for t in np.arange(1, int(10 * rate) + 1) / rate + 100.0:
            sim.advance_to(float(t))
            spray.update(np.array([0.0, -25.0, 0.0]))
        ends.append(spray.puffs)
        sim.close()
    assert len(ends[0]) == len(ends[1]) > 50 and np.any(ends[0].kind == 0)
    np.testing.assert_allclose(ends[0].position, ends[1].position, atol=1e-6)


def test_spindrift_follows_a_change_of_sea(heavy):
    """After the sea's heights are doubled, the crests spindrift leaves are the new sea's (twice as high): a spray
    that kept the old sea's would shed from crests half the height."""
    sim, spray = spray_of(heavy)
    sim.advance_to(10.0)
    spray.update(np.array([0.0, -25.0, 0.0]))
    before = spray._crests()[1]
    sim.change(hs_factor=2.0)
    sim.advance_to(10.2)
    spray.update(np.array([0.0, -25.0, 0.0]))
    sim.advance_to(30.0)
    spray.update(np.array([0.0, -25.0, 0.0]))
    assert spray._crests()[1] == pytest.approx(2.0 * before, rel=1e-6)
    sim.close()


def test_a_bow_impact_shows_white_spray_at_the_bow_and_nowhere_else(heavy):
    """The frame just after the hardest bow impact of the first 200 s, with the puffs and without: the spray
    brightens the picture around the bow only."""
    sim, spray = spray_of(heavy)
    height, rising = spray.at_stem(0.0, STEP_S, 6000)[:, :2].T
    rising[(height < -spray.bow.draft_m) | (height > spray.bow.freeboard_m)] = 0.0
    impact = float(np.argmax(rising)) * STEP_S
    assert rising.max() > spray.threshold_m_s()
    sim.close()
    with offscreen(heavy, (480, 270)) as view:
        orbit = view.scene.cameras["orbit"]
        orbit.azimuth_deg, orbit.elevation_deg, orbit.distance_m = 125.0, 12.0, 200.0
        view.go_to(impact + 0.5)
        puffs = view.scene.renderer.spray.puffs
        assert len(puffs) > 50
        with_spray = luminance(view.frame(hud=False))
        view.scene.renderer.spray.puffs = Puffs.none()
        without = luminance(view.frame(hud=False))
        eye = view.scene.camera.eye(view.scene.sim.pose())
        stem = view.scene.sim.pose().world(view.scene.renderer.spray.bow.stem[None, :])
        col, row = eye.project(stem, (480, 270))[0][:2]
    brighter = with_spray - without > 10.0
    assert brighter.sum() > 30
    rows, cols = np.nonzero(brighter)
    assert np.all(np.hypot(rows - row, cols - col) < 60)
