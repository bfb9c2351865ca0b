"""Spray: the drops' flight, the bow impact that throws it (Ochi's threshold on the relative velocity at the stem),
spindrift from Beaufort 8, and the puffs on the picture."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from conftest import ROOT, luminance, offscreen
from marinesim.constants import G
from marinesim.render.spray import (DROP_TAU_S, SPRAY_ONSET, Bow, Puffs, Spray, flown, whitecap_fraction)
from marinesim.scenario import load_scenario
from marinesim.sea.seastate import scaled_sea
from marinesim.session.timeline import Simulation
from marinesim.vessel.response import Response

STEP = 1.0 / 30.0


@pytest.fixture(scope="module")
def heavy():
    """The S175 at 18 kn into a head sea of Hs 3.4 m (wind sea and swell)."""
    return load_scenario(ROOT / "configs" / "s175_heavy_weather.toml")


def spray_of(scenario) -> tuple[Simulation, Spray]:
    sim = Simulation(scenario, wake=False)
    return sim, Spray(sim, Bow.of(scenario.vessel.hull, scenario.vessel.hull.vertices))


def test_drops_fly_as_gravity_and_the_drag_towards_the_wind_make_them():
    """The closed-form step equals a numerical integration of dv/dt = -g z + (w - v) / tau, and a drop ends up
    drifting with the wind and falling at its terminal speed (1 mm: 4.0 m/s, Gunn & Kinzer). A sign slip in
    the drag or gravity, or a step that depends on its length, fails it."""
    wind = np.array([-12.0, 5.0, 0.0])
    position, velocity = np.array([[1.0, 2.0, 3.0]]), np.array([[8.0, 0.0, 11.0]])
    tau = np.array([DROP_TAU_S])

    def rates(_, state):
        return np.r_[state[3:], -G * np.array([0.0, 0.0, 1.0]) + (wind - state[3:]) / tau[0]]

    numeric = solve_ivp(rates, (0.0, 1.7), np.r_[position[0], velocity[0]], rtol=1e-10, atol=1e-10).y[:, -1]
    one, v_one = flown(position, velocity, tau, wind, 1.7)
    many, v_many = position, velocity
    for _ in range(17):
        many, v_many = flown(many, v_many, tau, wind, 0.1)
    np.testing.assert_allclose(one[0], numeric[:3], atol=1e-8)
    np.testing.assert_allclose(v_one[0], numeric[3:], atol=1e-8)
    np.testing.assert_allclose(many, one, atol=1e-9)
    _, late = flown(position, velocity, tau, wind, 30.0)
    np.testing.assert_allclose(late[0], [-12.0, 5.0, -8.06], atol=1e-6)   # 3 mm drops: 8.06 m/s
    assert flown(position, velocity, np.array([4.0 / G]), wind, 30.0)[1][0, 2] == pytest.approx(-4.0)


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
    height, rising = spray.at_stem(0.0, STEP, 6000)[:, :2].T
    wet = (height > -spray.bow.draft_m) & (height < spray.bow.freeboard_m)
    fast = np.flatnonzero(wet & (rising > SPRAY_ONSET * v_th))
    assert fast.size > 0
    born_at = []
    for k in range(1, 6000, 3):
        before = len(spray.puffs)
        sim.advance_to(k * STEP)
        spray.update(np.zeros(3))
        if len(spray.puffs) > before:
            born_at.append(k)
            fresh = spray.puffs.where(spray.puffs.age < 3.5 * STEP)
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


def test_the_same_run_throws_the_same_spray_whatever_the_frame_rate(heavy):
    """Ten seconds around a bow impact stepped at 30 and at 24 frames a second end with the same puffs in the same
    places: births keep to the run's clock and flights are exact."""
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
    height, rising = spray.at_stem(0.0, STEP, 6000)[:, :2].T
    rising[(height < -spray.bow.draft_m) | (height > spray.bow.freeboard_m)] = 0.0
    impact = float(np.argmax(rising)) * STEP
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
