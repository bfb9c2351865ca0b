"""The viewer on Mesa's software OpenGL through EGL: real shaders, real frames, real files.

Every render here goes through the same Session the window uses. Images are small (a software
renderer draws them) but the statements are about what a user would see: sky above the
horizon, the vessel where its pose puts it, more foam in a rougher sea, a wake behind a moving
ship, a bridge view that rolls with the ship, a video with the frames it should have.
"""

from __future__ import annotations

import dataclasses
import math
import re

import numpy as np
import pandas as pd
import pytest

from conftest import DEFAULT, RENDER_SIZE as SIZE, ROOT, luminance, offscreen, run_lengths
from marinesim.cli import main
from marinesim.pose import Pose
from marinesim.render.camera import BridgeCamera
from marinesim.render.offscreen import Offscreen, render_video
from marinesim.scenario import load_scenario
from marinesim.sea.seastate import scaled_sea


def horizon_row(view: Offscreen) -> float:
    """Pixel row of the horizon in the middle column: a point 15 km out along the view, at z = 0."""
    eye = view.scene.camera.eye(view.scene.sim.pose())
    ahead = np.array([eye.forward[0], eye.forward[1], 0.0])
    far = eye.position * [1, 1, 0] + 15_000.0 * ahead / np.linalg.norm(ahead)
    return float(eye.project(far[None, :], view.size)[0, 1])


def projected_box(view: Offscreen, mesh) -> tuple[float, float, float, float]:
    """Pixel columns and rows (x0, y0, x1, y1) spanned by ``mesh``'s body-frame bounding box in the current pose."""
    scene = view.scene
    pose = scene.sim.pose()
    projected = scene.camera.eye(pose).project(pose.world(mesh.bounds()), view.size)[:, :2]
    return (*projected.min(axis=0), *projected.max(axis=0))


def test_every_shader_compiles_and_frames_render_at_two_sizes_and_after_a_resize(underway):
    """Sky, ocean (with wake and solver compositing), vessel, foam, HUD and solver passes all
    compile, and a frame draws without a GL error at 320x180, at 480x270 and back again."""
    with offscreen(underway, solver=True, solver_size=64) as view:
        view.go_to(2.0)
        frames = []
        for size in (SIZE, (480, 270), SIZE):
            view.resize(size)
            frames.append(view.frame())
            assert view.ctx.error == "GL_NO_ERROR"
        assert view.solver_on
        assert [f.shape for f in frames] == [(180, 320, 3), (270, 480, 3), (180, 320, 3)]
        assert np.array_equal(frames[0], frames[2]), "the same frame after a resize must be the same picture"
        assert frames[1].std() > 10.0, "a frame of one colour: nothing was drawn"


def test_sky_above_the_horizon_water_below_and_the_vessel_where_its_pose_puts_it(default):
    with offscreen(default) as view, offscreen(default, vessel=False) as bare:
        for v in (view, bare):
            v.go_to(30.0)
        image, without = view.frame(hud=False), bare.frame(hud=False)
        row = horizon_row(view)
        assert 5 < row < SIZE[1] - 20, f"the default orbit camera should see the horizon, got row {row:.1f}"
        sky, water = image[: int(row) - 3], image[int(row) + 12:]
        # sky: bright and blue; water: darker than the sky and blue-green, not grey or black
        assert luminance(sky).mean() > 150.0
        assert luminance(water).mean() < 0.75 * luminance(sky).mean()
        assert water[..., 2].mean() > water[..., 0].mean() + 20.0, "water should be bluer than it is red"
        assert sky[..., 2].mean() > sky[..., 0].mean(), "the sky should be bluer than it is red"

        x0, y0, x1, y1 = projected_box(view, view.scene.renderer.mesh)
        changed = np.abs(image.astype(int) - without.astype(int)).max(axis=-1) > 25
        rows, cols = np.nonzero(changed)
        inside = (cols >= x0 - 1) & (cols <= x1 + 1) & (rows >= y0 - 1) & (rows <= y1 + 1)
        assert changed.sum() > 100, "the vessel covers almost no pixels"
        assert inside.mean() > 0.99, "vessel pixels outside its projected bounding box: the pose or camera is wrong"
        assert changed.sum() > 0.15 * (x1 - x0) * (y1 - y0), "the vessel fills too little of its bounding box"


def foam_fraction(scenario, hs_factor: float) -> float:
    """Share of the water's pixels that foam brightens (the same frame with foam off is the reference): the sea's own
    whitecaps, without a ship (whose wash and collar of foam are no whitecaps)."""
    rough = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, hs_factor, 1.0, 0.0), vessel=None)
    with offscreen(rough) as view, offscreen(rough, foam=False) as plain:
        for v in (view, plain):
            v.go_to(20.0)
        row = int(horizon_row(view)) + 12
        brighter = luminance(view.frame(hud=False)[row:]) - luminance(plain.frame(hud=False)[row:])
    return float((brighter > 20.0).mean())


@pytest.mark.slow
def test_foam_covers_more_of_the_sea_as_hs_rises(default):
    """Whitecaps grow with wave steepness: Hs x0.5 almost none, x2 several times more than x1.

    And the default wind sea (Hs 3.5 m, Tp 9 s) has about the whitecap cover observed for the
    wind that raises it. Fully developed (Pierson-Moskowitz, wp = 0.877 g / U19.5) it needs
    U19.5 = 12.3 m/s, U10 = U19.5 / 1.075 = 11.5 m/s, where Monahan & O'Muircheartaigh (1980)
    give W = 3.84e-6 U10^3.41 = 1.6 %. Within a factor of two: foam thresholds off by 0.1 in J
    move the cover by more than that."""
    calm, design, storm = (foam_fraction(default, f) for f in (0.5, 1.0, 2.0))
    assert calm < design < storm
    assert calm < 0.002, f"a 1.9 m sea should be almost free of whitecaps, got {calm:.2%}"
    assert storm > 3.0 * design and storm > 0.01, (calm, design, storm)
    u10 = 0.877 * 9.81 / (2.0 * math.pi / 9.0) / 1.075
    monahan = 3.84e-6 * u10**3.41
    assert 0.5 * monahan < design < 2.0 * monahan, f"whitecap cover {design:.2%}, Monahan's law {monahan:.2%}"


def sea_plane_points(eye, size: tuple[int, int], rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Where the rays through pixel centres meet the mean sea surface z = 0 (m, E frame)."""
    width, height = size
    ndc = np.c_[(cols + 0.5) / width * 2 - 1, 1 - (rows + 0.5) / height * 2, np.ones(len(rows)), np.ones(len(rows))]
    far = ndc @ np.linalg.inv(eye.view_projection(width / height)).T
    direction = far[:, :3] / far[:, 3:] - eye.position
    return eye.position + direction * (-eye.position[2] / direction[:, 2])[:, None]


def test_the_wake_shows_behind_the_moving_vessel_and_not_ahead_of_it(underway):
    """Kelvin waves trail the ship: every pixel the wake changes looks at water behind the bow
    (within the sea's own heave of the surface) and inside the wake's grid."""
    with offscreen(underway, SIZE) as view, offscreen(underway, SIZE, wake=False) as plain:
        for v in (view, plain):
            v.go_to(10.0)
        changed = np.abs(view.frame(hud=False).astype(int) - plain.frame(hud=False).astype(int)).max(axis=-1) > 12
        scene = view.scene
        wake = scene.sim.wakes()[0][0]
        pose = scene.sim.pose()
        eye = scene.camera.eye(pose)
    assert changed.mean() > 0.02, "the wake changed almost nothing in the picture"
    rows, cols = np.nonzero(changed)
    on_sea = sea_plane_points(eye, SIZE, rows, cols)
    ahead = np.array([math.cos(pose.heading), math.sin(pose.heading)])
    along = (on_sea[:, :2] - [pose.x, pose.y]) @ ahead
    hull = scene.renderer.mesh
    bow = hull.positions[:, 0].max()
    assert np.mean(along < bow + 30.0) > 0.98, "wake drawn ahead of the bow: the vessel-frame mapping is wrong"
    assert np.mean(along > wake.x[0] - 30.0) > 0.98, "wake drawn beyond the end of its grid"


def streak_foam(scenario, wind_m_s: float) -> np.ndarray:
    """Where foam brightens the calmed sea (Hs x 0.3: no whitecaps) seen from 150 m straight down, 2 km from the
    ship, the wind ``wind_m_s`` blowing up the picture: a (rows, cols) bool mask."""
    calm = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, 0.3, 1.0, 0.0),
                               environment=scenario.environment.changed(wind_speed_m_s=wind_m_s))
    frames = []
    for foam in (True, False):
        with offscreen(calm, (320, 320), foam=foam) as view:
            view.scene.camera_name = "free"
            free = view.scene.cameras["free"]
            wind = view.scene.renderer.view(free.eye(view.scene.sim.pose()), (320, 320)).light.wind
            free.position, free.yaw_deg, free.pitch_deg = (2000.0, 2000.0, 150.0), math.degrees(
                math.atan2(wind[1], wind[0])), -89.9
            view.go_to(10.0)
            frames.append(luminance(view.frame(hud=False)))
    return frames[0] - frames[1] > 20.0


def test_a_rising_wind_lays_more_foam_in_streaks_along_it(default):
    """Beaufort 6 (10 m/s) blows no streaks; from 7 on foam lies in streaks along the wind (runs along it several
    times longer than across), and a storm (22 m/s, Beaufort 9) covers more of the sea with them than a near gale
    (16 m/s): a storm is not drawn as a moderate swell."""
    cover = {wind: streak_foam(default, wind) for wind in (10.0, 16.0, 22.0)}
    assert cover[10.0].mean() < 0.002
    assert 0.02 < cover[16.0].mean() < cover[22.0].mean()
    for wind in (16.0, 22.0):
        along, across = run_lengths(cover[wind].T), run_lengths(cover[wind])  # the wind blows up the picture
        assert along > 3.0 * across, (wind, along, across)


def overhead_brightening(scenario, speed_kn: float):
    """From 900 m over the track a ship length astern, the Kelvin wake off and the sea calmed to a third (no
    whitecaps): how much foam brightens each pixel (luminance), and the sea point (vessel frame) under each."""
    calm = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, 0.3, 1.0, 0.0),
                               vessel=dataclasses.replace(scenario.vessel, speed_m_s=speed_kn * 0.514444))
    size = (480, 360)
    frames = []
    for foam in (True, False):
        with offscreen(calm, size, wake=False, foam=foam) as view:
            view.scene.camera_name = "free"
            view.go_to(60.0)
            pose = view.scene.sim.pose()
            hull = view.scene.sim.vessel.hull.vertices
            back = float(np.ptp(hull[:, 0]))
            free = view.scene.cameras["free"]
            free.position = (pose.x - back * math.cos(pose.heading), pose.y - back * math.sin(pose.heading), 900.0)
            free.yaw_deg, free.pitch_deg = math.degrees(pose.heading), -89.9
            frames.append(luminance(view.frame(hud=False)))
            eye = view.scene.camera.eye(pose)
    rows, cols = np.indices(size[::-1]).reshape(2, -1)
    sea = sea_plane_points(eye, size, rows, cols)[:, :2] - [pose.x, pose.y]
    c, s = math.cos(pose.heading), math.sin(pose.heading)
    vessel = np.c_[sea @ [c, s], sea @ [-s, c]]
    return (frames[0] - frames[1]).ravel(), vessel, hull


def test_the_wash_astern_is_a_foam_band_that_spreads_and_fades_and_foam_meets_the_hull(underway):
    """A ship making way leaves a white band astern as wide as her beam that widens (as a self-propelled wake,
    x^1/5) and fades as its water ages; none ahead of the bow or far abeam; a collar of foam against her sides;
    at rest no wash. A wash ahead of the bow, or one that grew astern, would tell a trainee the wrong course."""
    brighter, v, hull = overhead_brightening(underway, 14.0)
    stern, bow = hull[:, 0].min(), hull[:, 0].max()
    length, half_beam = bow - stern, 0.5 * float(np.ptp(hull[:, 1]))

    def mean_in(x0, x1, y0, y1, field=brighter):
        inside = (v[:, 0] > x0) & (v[:, 0] < x1) & (np.abs(v[:, 1]) > y0) & (np.abs(v[:, 1]) < y1)
        assert inside.sum() > 30, (x0, x1, y0, y1)
        return float(field[inside].mean())

    near, far = (stern - 0.25 * length, stern - 0.1 * length), (stern - 1.9 * length, stern - 1.75 * length)
    centre_near, centre_far = mean_in(*near, 0.0, 0.3 * half_beam), mean_in(*far, 0.0, 0.3 * half_beam)
    assert centre_near > 40.0, "no white wash just astern"
    assert centre_far < 0.6 * centre_near, "the wash does not fade astern"
    edge = (1.3 * half_beam, 1.6 * half_beam)
    assert mean_in(*far, *edge) / centre_far > 2.0 * mean_in(*near, *edge) / centre_near, "the wash does not spread"
    assert abs(mean_in(bow + 30.0, bow + 300.0, 0.0, 2.0 * half_beam)) < 2.0, "foam ahead of the bow"
    assert abs(mean_in(stern, stern + 0.5 * length, 4.0 * half_beam, 8.0 * half_beam)) < 2.0, "foam far abeam"
    sides = (stern + 0.3 * length, bow - 0.3 * length)
    assert mean_in(*sides, half_beam + 0.5, half_beam + 4.0) > 5.0 * max(mean_in(*sides, half_beam + 15.0,
                                                                               half_beam + 30.0), 1.0)
    at_rest, v, _ = overhead_brightening(underway, 0.0)
    assert mean_in(*near, 0.0, 0.3 * half_beam, field=at_rest) < 0.1 * centre_near, "a wash behind a ship at rest"


def test_the_bridge_camera_rolls_and_pitches_with_the_ship():
    """The eye is the bridge point carried by the pose; its up vector tilts by exactly the roll and pitch."""
    camera = BridgeCamera((-105.0, 0.0, 32.0), look_pitch_deg=0.0)
    level = camera.eye(Pose(10.0, 20.0, 0.3))
    roll, pitch = math.radians(5.0), math.radians(2.0)
    rolled = camera.eye(Pose(10.0, 20.0, 0.3, (0, 0, 0, roll, 0, 0)))
    pitched = camera.eye(Pose(10.0, 20.0, 0.3, (0, 0, 0, 0, pitch, 0)))
    assert math.degrees(math.acos(rolled.up @ level.up)) == pytest.approx(5.0, abs=1e-9)
    starboard = np.cross(level.forward, level.up)
    assert rolled.up @ starboard > 0, "positive roll (starboard down, CONVENTIONS) tilts the mast to starboard"
    # pitch bow down raises a point 105 m aft by 105 sin(2 deg) = 3.66 m, and the view dips by 2 deg
    rise = 105.0 * math.sin(pitch) + 32.0 * (math.cos(pitch) - 1.0)
    assert pitched.position[2] - level.position[2] == pytest.approx(rise, abs=1e-9)
    assert math.degrees(math.asin(-pitched.forward[2])) == pytest.approx(2.0, abs=1e-9)


def test_a_ten_second_video_has_its_frames_and_its_csv_equals_marinesim_export(default, tmp_path):
    import imageio_ffmpeg

    out = tmp_path / "run.mp4"
    result = render_video(default, out, seconds=10.0, size=(160, 90), fps=10.0, solver="off")
    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(out))
    assert (result.frames, frames) == (100, 100)
    assert seconds == pytest.approx(10.0)
    assert not list(tmp_path.glob(".*part*")), "a temporary file was left behind"
    assert main(["export", str(DEFAULT), "--out", str(tmp_path / "export.csv"), "--duration", "10", "--quiet"]) == 0
    pd.testing.assert_frame_equal(pd.read_csv(result.motions), pd.read_csv(tmp_path / "export.csv"))


@pytest.fixture(scope="module")
def barge(tmp_path_factory):
    """The default sea with the box barge as the hull (no bridge point, so no deckhouse of its own): plain,
    with hulls/barge_visual.glb (deckhouse and mast, in cm, y up) as its visual mesh, and that mesh alone."""
    text = (re.sub(r"visual_mesh = .*\n", "", DEFAULT.read_text()).replace("tanker.gdf", "box_barge.stl")
            .replace("bridge = [-105.0, 0.0, 32.0]\n", "")
            .replace('"../', f'"{ROOT.as_posix()}/'))
    visual = text.replace("[vessel]\n", f'[vessel]\nvisual_mesh = "{ROOT.as_posix()}/hulls/barge_visual.glb"\n'
                          'visual_mesh_units = "cm"\nvisual_mesh_axes = "x,-z,y"\n'
                          'visual_mesh_offset_m = [-50.0, 0.0, -5.0]\n')
    folder = tmp_path_factory.mktemp("barge")
    (folder / "plain.toml").write_text(text)
    (folder / "visual.toml").write_text(visual)
    (folder / "visual_only.toml").write_text(re.sub(r"hull = .*\n", "", visual))
    return tuple(load_scenario(folder / f"{name}.toml") for name in ("plain", "visual", "visual_only"))


def test_the_visual_mesh_is_drawn_in_its_pose_instead_of_the_hull(barge):
    """With a visual mesh, the vessel on screen is the model with its deckhouse, not the bare barge: the
    picture changes, every changed pixel lies inside the visual mesh's bounding box carried by the 6-DOF pose,
    the vessel hides more of the sea (the deckhouse stands 12 m above the deck), and the water still stops at
    the hydrodynamic hull."""
    plain, visual, _ = barge
    with offscreen(plain) as hull_view, offscreen(visual) as view, offscreen(visual, vessel=False) as bare:
        for v in (hull_view, view, bare):
            v.go_to(30.0)
        image, hull_image, without = (v.frame(hud=False).astype(int) for v in (view, hull_view, bare))
        renderer = view.scene.renderer
        assert renderer.mesh.positions[:, 2].max() == pytest.approx(25.0, abs=1e-4), "not the visual mesh drawn"
        assert renderer.hull_mask.cells is not None, "the hull mask (no water inside the waterplane) comes from the hull"
        x0, y0, x1, y1 = projected_box(view, renderer.mesh)
    for changed in (np.abs(image - hull_image).max(axis=-1) > 25, np.abs(image - without).max(axis=-1) > 25):
        rows, cols = np.nonzero(changed)
        inside = (cols >= x0 - 1) & (cols <= x1 + 1) & (rows >= y0 - 1) & (rows <= y1 + 1)
        assert changed.sum() > 100, "the visual mesh changed almost no pixels"
        assert inside.mean() > 0.99, "vessel pixels outside the visual mesh's projected box: pose or offset wrong"
    covered, covered_by_hull = ((np.abs(i - without).max(axis=-1) > 25).sum() for i in (image, hull_image))
    assert covered > 1.3 * covered_by_hull, "the deckhouse hides no more sea than the bare barge: not drawn"


def test_a_visual_mesh_without_a_hull_is_drawn_and_the_sea_runs_under_it(barge):
    """A visual mesh alone is drawn in its pose (no hull: no wake, no solver, no hull mask), inside its box."""
    *_, visual_only = barge
    assert visual_only.vessel.hull is None
    with offscreen(visual_only) as view, offscreen(visual_only, vessel=False) as bare:
        for v in (view, bare):
            v.go_to(30.0)
        changed = np.abs(view.frame(hud=False).astype(int) - bare.frame(hud=False).astype(int)).max(axis=-1) > 25
        renderer = view.scene.renderer
        assert renderer.hull_mask.cells is None and view.scene.sim.solver is None and not view.scene.sim.wakes()
        x0, y0, x1, y1 = projected_box(view, renderer.mesh)
    rows, cols = np.nonzero(changed)
    assert changed.sum() > 100, "the visual mesh covers almost no pixels"
    assert np.mean((cols >= x0 - 1) & (cols <= x1 + 1) & (rows >= y0 - 1) & (rows <= y1 + 1)) > 0.99
