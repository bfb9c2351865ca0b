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
import threading
import tracemalloc
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from marinesim.cli import main
from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.gl import GraphicsError
from marinesim.render.camera import BridgeCamera
from marinesim.render.offscreen import Offscreen, render_video
from marinesim.render.renderer import RenderOptions
from marinesim.scenario import load_scenario
from marinesim.sea.cascades import cell_variances
from marinesim.sea.seastate import scaled_sea
from marinesim.session.assembly import Assembly
from marinesim.session.timeline import PREPARE_S, Simulation
from marinesim.pose import Pose

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ROOT / "configs" / "default.toml"
SIZE = (320, 180)


@pytest.fixture(scope="module")
def default():
    return load_scenario(DEFAULT)


@pytest.fixture(scope="module")
def underway(tmp_path_factory):
    """The default scenario with the tanker at 14 kn (Fn 0.145): a Kelvin wake worth drawing."""
    text = DEFAULT.read_text().replace("speed_kn = 4.0", "speed_kn = 14.0").replace('"../', f'"{ROOT.as_posix()}/')
    path = tmp_path_factory.mktemp("scenario") / "underway.toml"
    path.write_text(text)
    return load_scenario(path)


def offscreen(scenario, size=SIZE, **options) -> Offscreen:
    solver = "on" if options.get("solver") else "off"
    try:
        return Offscreen(scenario, size, solver=solver, options=RenderOptions(**options))
    except GraphicsError as error:
        pytest.skip(f"no EGL OpenGL 4.3 here: {error}")


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


def luminance(image: np.ndarray) -> np.ndarray:
    return image.astype(float) @ [0.2126, 0.7152, 0.0722]


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
    """Share of the water's pixels that foam brightens (the same frame with foam off is the reference)."""
    rough = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, hs_factor, 1.0, 0.0))
    with offscreen(rough) as view, offscreen(rough, foam=False) as plain:
        for v in (view, plain):
            v.go_to(20.0)
        row = int(horizon_row(view)) + 12
        brighter = luminance(view.frame(hud=False)[row:]) - luminance(plain.frame(hud=False)[row:])
    return float((brighter > 20.0).mean())


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


def test_live_changes_blend_smoothly_and_do_not_depend_on_the_frame_rate(default):
    """A course and sea change at t = 5 s: the same poses at 60 and at 7 frames/s; no jump in heave or heading."""
    def run(dt: float) -> Simulation:
        sim = Simulation(default, wake=False)
        while sim.time < 5.0 - 1e-9:
            sim.advance(min(dt, 5.0 - sim.time))
        sim.change(hs_factor=1.5, heading_deg=200.0, speed_kn=8.0, ramp_s=10.0)
        while sim.time < 30.0 - 1e-9:
            sim.advance(min(dt, 30.0 - sim.time))
        return sim
    fast, slow = run(1 / 60), run(1 / 7)
    times = np.arange(0.0, 30.0, 0.05)
    assert np.allclose(fast.frame(times)["heave_m"], slow.frame(times)["heave_m"], atol=1e-9)
    a, b = fast.pose(17.3), slow.pose(17.3)  # the change starts at 5.5 s, up to the rounding of summed frame times
    assert np.allclose([a.x, a.y, a.heading, *a.motion], [b.x, b.y, b.heading, *b.motion], rtol=0, atol=1e-9)
    heave = fast.frame(times)["heave_m"]
    assert np.abs(np.diff(heave)).max() < 0.1, "heave jumps during the blend"
    headings = np.unwrap([fast.pose(t).heading for t in times])
    assert np.abs(np.diff(headings)).max() < math.radians(1.0)
    assert math.degrees(headings[-1]) % 360 == pytest.approx(250.0, abs=1e-6)  # compass 200 = math 250
    assert fast.sea.hs == pytest.approx(1.5 * default.sea.hs, rel=1e-9)


def test_changes_asked_for_during_a_blend_add_up(default):
    """Two presses of 'waves up' and 'speed up' while a change blends: x1.21 and +2 kn, not x1.1 and +1."""
    sim = Simulation(default, wake=False)
    speed_kn = default.vessel.speed_kn
    for _ in range(2):
        sim.change(hs_factor=1.1, ramp_s=5.0)
        sim.change(speed_kn=sim.speed_m_s / KNOT + 1.0, ramp_s=5.0)
    assert sim.speed_m_s / KNOT == pytest.approx(speed_kn + 2.0)   # the waiting changes already count
    sim.advance(30.0)
    assert sim.sea.hs == pytest.approx(1.21 * default.sea.hs, rel=1e-9)
    assert sim.legs[-1].track.speed / KNOT == pytest.approx(speed_kn + 2.0)
    assert len(sim.legs) == 5, "each change should have started in turn"


def test_a_sea_change_is_prepared_off_the_frame_thread_and_starts_at_a_fixed_time(default, monkeypatch):
    """The costly part of a sea change (every cell's variance, 0.1-0.2 s at 4 x 256^2) runs on the
    change's worker while frames go on; on the frame thread it would stall the picture at each key
    press. The change starts PREPARE_S after it was asked for, however fast the worker was."""
    threads = []

    def variances(*args):
        threads.append(threading.current_thread().name)
        return cell_variances(*args)

    monkeypatch.setattr("marinesim.sea.ocean.cell_variances", variances)
    sim = Simulation(default, wake=False)
    sim.advance(1.0)
    threads.clear()
    sim.change(hs_factor=1.3, ramp_s=4.0)
    assert sim.sea.hs == pytest.approx(1.3 * default.sea.hs)  # the HUD shows what was asked for at once
    assert len(sim.legs) == 1
    while len(sim.legs) == 1:
        sim.advance(1 / 60)
    assert sim.legs[-1].start == pytest.approx(1.0 + PREPARE_S, abs=1e-12)
    assert threads and all(name.startswith("sea-change") for name in threads), threads
    sim.advance(10.0)
    assert sim.ocean.components(sim.time).variance == pytest.approx(1.3**2 * Assembly(default).ocean.components().variance,
                                                                    rel=1e-9)
    sim.close()


def test_a_sea_change_the_ocean_cannot_carry_is_refused_when_asked(underway, tmp_path):
    """A regular wave's period change needs a tile the ocean does not have: the refusal must come
    from change() (the viewer shows it), not half a second later from the frame loop."""
    text = underway.path.read_text() + '\n[[sea]]\ntype = "regular"\nheight_m = 1.0\nperiod_s = 8.0\nfrom_deg = 90.0\n'
    path = tmp_path / "regular.toml"
    path.write_text(text)
    sim = Simulation(load_scenario(path), wake=False)
    with pytest.raises(ParameterError, match="cannot carry a regular wave of 8.4 s"):
        sim.change(tp_factor=1.05, ramp_s=5.0)
    sim.advance(1.0)  # nothing was left waiting
    assert len(sim.legs) == 1 and sim.sea.tp == pytest.approx(load_scenario(path).sea.tp)
    sim.change(hs_factor=1.1, ramp_s=5.0)  # heights can change
    sim.advance(6.0)
    assert len(sim.legs) == 2


def test_bad_change_arguments_are_refused_when_asked(default):
    """A sea change starts PREPARE_S later; its ramp time must still be refused by change(),
    where the viewer shows the message, and not by a later frame, which would lose the change."""
    sim = Simulation(default, wake=False)
    for ramp_s in (0.0, -1.0, math.nan):
        with pytest.raises(ParameterError, match="ramp time"):
            sim.change(hs_factor=1.2, ramp_s=ramp_s)
    sim.advance(2.0)
    assert len(sim.legs) == 1 and sim.sea.hs == pytest.approx(default.sea.hs)
    sim.change(speed_kn=6.0, ramp_s=0.0)  # a speed change may be instant
    assert sim.speed_m_s / KNOT == pytest.approx(6.0) and len(sim.legs) == 2


def test_a_long_session_of_changes_keeps_memory_flat_and_the_past_exact(default):
    """Twenty sea and speed changes, as an instructor makes in a training session: memory stays
    flat (each change used to keep its sea's amplitude grid and the ship's response to it, 10 MB
    at the default 4 x 256^2), and motions at times of the first change, whose states were since
    dropped, come back to the same bits."""
    sim = Simulation(default, wake=False)
    sim.advance(2.0)
    sim.change(hs_factor=1.2, speed_kn=6.0, ramp_s=1.0)  # starts at 2.5 s (PREPARE_S), settled at 3.5 s
    sim.advance(2.0)
    times = np.array([3.0, 3.75])  # blending into the first change, then settled in it
    past = sim.frame(times)
    tracemalloc.start()
    held = []
    for i in range(20):
        sim.advance(2.5)
        sim.change(hs_factor=0.9 if i % 2 else 1.1, speed_kn=5.0 + i % 3, ramp_s=2.0)
        held.append(tracemalloc.get_traced_memory()[0] / 2**20)
    tracemalloc.stop()
    assert held[-1] - held[4] < 5.0  # MB over 15 changes; kept, they were about 150
    again = sim.frame(times)
    for column, values in past.items():
        np.testing.assert_array_equal(again[column], values, err_msg=column)
    assert sim.sea.hs == pytest.approx(1.2 * 1.1**10 * 0.9**10 * default.sea.hs, rel=1e-9)


def test_render_command_refuses_bad_sizes_and_writes_a_screenshot(tmp_path, capsys):
    assert main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "a.png"), "--size", "321x180"]) == 2
    assert "--size" in capsys.readouterr().err
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.avi")]) == 2
    assert main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "a.png"), "--time", "-1"]) == 2
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.mp4"), "--seconds", "0"]) == 2
    assert "--seconds" in capsys.readouterr().err
    assert main(["render", str(DEFAULT), "--out", str(tmp_path / "a.mp4"), "--fps", "0"]) == 2
    assert "--fps" in capsys.readouterr().err
    both = ["--out", str(tmp_path / "a.mp4"), "--screenshot", str(tmp_path / "a.png")]
    assert main(["render", str(DEFAULT), *both]) == 2
    assert not list(tmp_path.iterdir()), "a refused command wrote something"
    try:
        code = main(["render", str(DEFAULT), "--screenshot", str(tmp_path / "shot.png"), "--size", "160x90",
                     "--time", "5", "--camera", "bridge"])
    except GraphicsError as error:
        pytest.skip(str(error))
    from PIL import Image

    assert code == 0
    assert Image.open(tmp_path / "shot.png").size == (160, 90)


@pytest.fixture(scope="module")
def barge(tmp_path_factory):
    """The default sea with the box barge as the hull (no bridge point, so no deckhouse of its own): plain,
    with hulls/barge_visual.glb (deckhouse and mast, in cm, y up) as its visual mesh, and that mesh alone."""
    text = (DEFAULT.read_text().replace("tanker.gdf", "box_barge.stl").replace("bridge = [-105.0, 0.0, 32.0]\n", "")
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
        assert renderer._mask is not None, "the hull mask (no water inside the waterplane) comes from the hull"
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
        assert renderer._mask is None and view.scene.sim.solver is None and not view.scene.sim.wakes()
        x0, y0, x1, y1 = projected_box(view, renderer.mesh)
    rows, cols = np.nonzero(changed)
    assert changed.sum() > 100, "the visual mesh covers almost no pixels"
    assert np.mean((cols >= x0 - 1) & (cols <= x1 + 1) & (rows >= y0 - 1) & (rows <= y1 + 1)) > 0.99
