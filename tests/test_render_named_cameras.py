"""Named cameras on board (``[[cameras]]``): each shipped exercise's role camera shows what it names in its first
frame, key 4 goes through them, ``--camera NAME`` starts on one, and a bad camera is refused in one line."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO as SCENARIO, cli, write
from marinesim.errors import ScenarioError
from marinesim.render.controls import Controls
from marinesim.render.offscreen import Offscreen
from marinesim.render.renderer import RenderOptions
from marinesim.scenario import load_scenario

TRAINING = ROOT / "configs" / "training"
SIZE = (200, 112)
ROLES = [("crane_lift", "crane cab", "load"), ("crossing_situation", "starboard wing", "tanker"),
         ("heavy_weather_transit", "bridge wing", "target"), ("helideck_landing", "helideck officer", "helideck"),
         ("offshore_loading", "loading master", "target"), ("offshore_loading", "FPSO stern", "bow")]
"""Each exercise's role cameras and what each must show: its target, a point on own-ship, the crane's load, or
another vessel."""
CAMERA = """
[[cameras]]
name = "deck"
position_m = [0.0, 10.0, 25.0]
target = "bow"
"""


def _view(scenario, camera: str, vessel: bool = True, size: tuple[int, int] = SIZE) -> Offscreen:
    from marinesim.gl import GraphicsError

    options = RenderOptions(hud="off", reproducible=True, vessel=vessel, spray=False, wake=False)
    try:
        return Offscreen(scenario, size, camera, "off", options)
    except GraphicsError as error:
        pytest.skip(f"no EGL OpenGL 4.3 here: {error}")


def _shown(view, camera, what: str) -> np.ndarray:
    """Where ``what`` is in the E frame (m): the camera's target, a point on board, the crane's load (the middle of
    the container) or another vessel (her bridge front's height above her reference point)."""
    sim = view.scene.sim
    pose = sim.pose()
    if what == "target":
        return pose.world(np.array([camera.target]))[0]
    if what == "load":
        row = sim.lift.sample(np.array([sim.time]))
        return np.array([row["load_x_m"][0], row["load_y_m"][0], row["load_z_m"][0] + 1.3])
    if what in sim.vessel.points:
        return pose.world(np.array([sim.vessel.points[what]]))[0]
    index = [body.other.name for body in sim.bodies].index(what)
    return sim.other_poses()[index].world(np.array([[0.0, 0.0, 12.0]]))[0]


@pytest.mark.parametrize("exercise, name, what", ROLES, ids=[f"{e}-{n}" for e, n, _ in ROLES])
def test_each_role_camera_shows_what_it_names(exercise, name, what):
    """In the first frame from the exercise's role camera what it is there to watch (its target, the crane's load, the
    helideck, the other vessel) is in the picture, and the depth image at its pixel is its distance (within 15 %):
    nothing stands between, and it is what is seen (with the vessels left out that pixel is far beyond). A camera
    looking past its deck, from inside the hull or at a stack of containers would show the trainee nothing of the
    job."""
    scenario = load_scenario(TRAINING / f"{exercise}.toml")
    camera, = (c for c in scenario.cameras if c.name == name)
    size = SIZE if what != "tanker" else (4 * SIZE[0], 4 * SIZE[1])  # she is 4 nm off: a few pixels at 200
    distances = []
    for vessel in (True, False):
        view = _view(scenario, camera.name, vessel, size)
        with view:
            view.go_to(0.0)
            view.frame(hud=False)
            depth = view.depth_m()
            pose = view.scene.camera_pose()
            (x, y, w), = view.scene.camera.eye(pose).project(_shown(view, camera, what)[None], size)
            if what == "target":
                assert abs(x - size[0] / 2) < 1.0 and abs(y - size[1] / 2) < 1.0
            assert w > 0 and 2 <= x < size[0] - 2 and 2 <= y < size[1] - 2, (exercise, x, y)
            row, col = int(y), int(x)
            distances.append(float(np.median(depth[row - 1:row + 2, col - 1:col + 2])))
    seen, beyond = distances
    assert seen == pytest.approx(w, rel=0.15), f"{exercise}: the pixel shows something {seen:.1f} m off, not " \
                                               f"{what} {w:.1f} m off"
    assert beyond > 1.2 * w


def test_key_4_goes_through_the_named_cameras_and_the_command_line_starts_on_one(tmp_path, gl_context):
    """Key 4 looks through the scenario's named cameras in turn (and says so where there are none); --camera NAME
    starts a render on one, and an unknown name is one line listing the cameras there are."""
    scenario = load_scenario(write(tmp_path, SCENARIO + CAMERA + CAMERA.replace('"deck"', '"mast"')))
    assert [(c.name, round(c.look_yaw_deg, 6)) for c in scenario.cameras] == [("deck", round(
        math.degrees(math.atan2(-10.0, 120.0)), 6))] * 1 + [("mast", round(math.degrees(math.atan2(-10.0, 120.0)), 6))]
    view = Offscreen(scenario, SIZE, "orbit", "off", RenderOptions(hud="off", spray=False, wake=False))
    with view:
        controls = Controls(view.scene, recordings=tmp_path)
        seen = []
        for _ in range(3):
            controls.press("_4")
            seen.append(view.scene.camera_name)
        assert seen == ["deck", "mast", "deck"]
        controls.press("_1")
        assert view.scene.camera_name == "orbit"
    plain = load_scenario(write(tmp_path, SCENARIO, "plain.toml"))
    with Offscreen(plain, SIZE, "orbit", "off", RenderOptions(hud="off", spray=False, wake=False)) as view:
        controls = Controls(view.scene, recordings=tmp_path)
        controls.press("_4")
        assert view.scene.camera_name == "orbit" and "no named cameras" in controls.message
    path = write(tmp_path, SCENARIO + CAMERA, "deck.toml")
    assert cli("render", str(path), "--screenshot", str(tmp_path / "deck.png"), "--camera", "deck", "--size",
               "160x90").returncode == 0
    refused = cli("render", str(path), "--screenshot", str(tmp_path / "no.png"), "--camera", "crow's nest")
    assert refused.returncode == 2 and "unknown camera \"crow's nest\" (known: orbit, bridge, free, deck)" in \
        refused.stderr and len(refused.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("change, message", [
    (('target = "bow"', 'target = "crane_tip"'), r"cameras\[0\].target: 'crane_tip' is not one of \[vessel.points\] "
                                                 r"\(bridge, bow\)"),
    (('name = "deck"', 'name = "deck"\nbody = "fpso"'), r"cameras\[0\].body: .*'ownship'"),
    (('name = "deck"', 'name = "bridge"'), r"cameras\[0\].name: 'bridge' is the viewer's own camera"),
    (('target = "bow"', 'target = "bow"\nlook_azimuth_deg = 30.0'), r"cameras\[0\].target: give a target or the look "
                                                                    r"angles, not both"),
    (('position_m = [0.0, 10.0, 25.0]', 'position_m = [0.0, 10.0]'), r"cameras\[0\].position_m: expected \[x, y, z\]"),
    (('target = "bow"', 'target = "bow"\nfov_deg = 170.0'), r"cameras\[0\].fov_deg: must be in 5..120 deg"),
])
def test_a_bad_camera_is_refused_in_one_line(tmp_path, change, message):
    """A camera on something that is not there, named as the viewer's own, or looking two ways at once: one line
    naming the key, before anything runs."""
    with pytest.raises(ScenarioError, match=message):
        load_scenario(write(tmp_path, SCENARIO + CAMERA.replace(*change)))


def test_two_cameras_of_one_name_are_refused(tmp_path):
    """The key would never reach the second one, and --camera could not say which."""
    with pytest.raises(ScenarioError, match=r"cameras\[1\].name: 'deck' names an earlier camera too"):
        load_scenario(write(tmp_path, SCENARIO + CAMERA + CAMERA))
    scenario = load_scenario(write(tmp_path, SCENARIO + CAMERA, "one.toml"))
    assert replace(scenario, cameras=()).cameras == ()


def test_the_hawser_is_drawn_from_her_bow_chock_to_the_fpsos_stern():
    """Offshore loading, from the FPSO's stern: the hawser's far end is made fast on the FPSO (her stern chock,
    125 m abaft her origin, 25 m up) and rides on her; the rope's mid-span, hanging ``w s^2 / (8 T)`` below the
    chord, is what the pixel there shows (its depth the distance to it, 15 %), and with the vessels left out that
    pixel is far beyond. A hawser drawn from the wrong side of her bow, to a point the FPSO has moved away from, or
    not at all would show the deck crew a line that is not where the physics has it."""
    scenario = load_scenario(TRAINING / "offshore_loading.toml")
    size = (4 * SIZE[0], 4 * SIZE[1])
    distances = []
    for vessel in (True, False):
        view = _view(scenario, "FPSO stern", vessel, size)
        with view:
            view.go_to(0.0)
            view.frame(hud=False)
            depth = view.depth_m()
            renderer, sim = view.scene.renderer, view.scene.sim
            if vessel:
                (index, layer, fast), = renderer.hawsers
                assert fast is not None and fast[0] == 0, "made fast on the FPSO"
                np.testing.assert_allclose(fast[1], [-125.0, 0.0, 25.0], atol=0.05)
            line = sim.voyage.ship.moorings.lines[0]
            x, y, z = line.fairlead
            fairlead = sim.pose().world(np.array([[x, -y, z]]))[0]
            far = sim.other_poses()[0].world(np.array([[-125.0, 0.0, 25.0]]))[0]
            tension = sim.voyage.ship.line_tensions(sim.voyage.state(0.0), frozenset())[0]
            span = float(np.linalg.norm(far - fairlead))
            middle = 0.5 * (fairlead + far) - [0.0, 0.0, line.weight_n_m * span**2 / (8.0 * tension)]
            pose = view.scene.camera_pose()
            (px, py, w), = view.scene.camera.eye(pose).project(middle[None], size)
            assert w > 0 and 2 <= px < size[0] - 2 and 2 <= py < size[1] - 2, (px, py)
            distances.append(float(np.median(depth[int(py) - 1:int(py) + 2, int(px) - 1:int(px) + 2])))
    seen, beyond = distances
    assert seen == pytest.approx(w, rel=0.15), f"the pixel shows something {seen:.1f} m off, not the hawser {w:.1f} m"
    assert beyond > 1.2 * w
