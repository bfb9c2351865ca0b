"""Named cameras on other bodies (``[[cameras]] body = NAME``): the eye moves with that body's pose, so a camera on a
buoy or on a ship sailing beside own ship, looking at her, sees her hull at the distance a ray cast from that pose
finds; a camera on an unknown body, or aiming at one of own ship's points from another body, is refused in one
line."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT, offscreen, ray_hits, write
from marinesim.constants import KNOT
from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario

TANKER = ROOT / "rao" / "tanker" / "tanker.4"
SIZE = (200, 112)
OWN_KN = 6.0
BUOY, BUOY_HEADING_DEG, BUOY_EYE = (0.0, -300.0), 30.0, (0.0, 0.0, 8.0)
AIM_Z = 3.0
"""The cameras aim at own ship's track point 3 m above the water (her port or starboard side is in the way)."""


def _buoy_target() -> list[float]:
    """Own ship's start, 3 m up, in the buoy's body frame (x along its heading, y to port): the E offset turned by
    minus the buoy's heading as a math angle."""
    heading = math.radians(90.0 - BUOY_HEADING_DEG)
    east, north = -BUOY[0], -BUOY[1]
    return [east * math.cos(heading) + north * math.sin(heading), -east * math.sin(heading) + north * math.cos(heading),
            AIM_Z]


SCENARIO = f"""
[ocean]
resolution = 64
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 1.5
tp_s = 9.0
from_deg = 200.0

[vessel]
rao = "{TANKER}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
speed_kn = {OWN_KN}
heading_deg = 90.0

[vessel.points]
bow = [120.0, 0.0, 12.0]

[run]
duration_s = 60.0
dt_s = 0.1
seed = 7

[[vessels]]
name = "mark"
kind = "buoy"
position_m = [{BUOY[0]}, {BUOY[1]}]
heading_deg = {BUOY_HEADING_DEG}

[[vessels]]
name = "sister"
kind = "ship"
rao = "{TANKER}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
position_m = [0.0, 300.0]
speed_kn = {OWN_KN}
heading_deg = 90.0

[[cameras]]
name = "buoy watch"
body = "mark"
position_m = [{BUOY_EYE[0]}, {BUOY_EYE[1]}, {BUOY_EYE[2]}]
target = {_buoy_target()}
fov_deg = 10.0

[[cameras]]
name = "sister's bridge"
body = "sister"
position_m = [0.0, 0.0, 15.0]
target = [0.0, -300.0, {AIM_Z}]
fov_deg = 10.0
"""
"""Own ship (the WAMIT tanker, drawn from her hull) heading east at 6 kn from the origin; a buoy 300 m south of her
start heading 030; her sister 300 m north on a parallel course at her speed. The buoy's camera 8 m up looks at own
ship's start, the sister's from 15 m over her midship looks square to starboard: at own ship, abeam of her all the
way."""


@pytest.fixture(scope="module")
def scenario(tmp_path_factory):
    return load_scenario(write(tmp_path_factory.mktemp("body_cameras"), SCENARIO))


@pytest.mark.parametrize("camera, index, t", [("buoy watch", 0, 0.0), ("sister's bridge", 1, 20.0)])
def test_a_camera_on_another_body_sees_own_ship_where_its_pose_puts_her(scenario, camera, index, t):
    """At ``t`` the depth at the centre of the picture from a camera on the buoy (heaving, its frame turned 030) or on
    the sister (sailing, rolling and pitching in the sea) is the distance along the line from the eye to the target,
    both placed by that body's pose, to own ship's drawn hull in her pose (a ray cast against the mesh's triangles),
    within 5 cm of about 280 m. A camera left on own ship's frame, a body frame turned the wrong way or a pose of
    another time would look elsewhere: at the sea or the sky, hundreds of metres off."""
    view = offscreen(scenario, SIZE, hud="off", wake=False, spray=False, foam=False, reproducible=True)
    with view:
        view.scene.camera_name = camera
        view.go_to(t)
        view.frame(hud=False)
        depth = view.depth_m()
        sim = view.scene.sim
        body = sim.other_poses()[index]
        named = scenario.cameras[index]
        eye, target = body.world(np.array([named.point, named.target]))
        own = sim.pose().world(view.scene.renderer.mesh.positions).reshape(-1, 3, 3)
    assert sim.time == t and sim.bodies[index].other.name == named.body
    hits, _ = ray_hits(own, eye, target - eye)
    assert hits.size, "the line of sight misses own ship"
    seen = float(np.median(depth[SIZE[1] // 2 - 1:SIZE[1] // 2 + 1, SIZE[0] // 2 - 1:SIZE[0] // 2 + 1]))
    assert 250.0 < hits[0] < 300.0
    assert seen == pytest.approx(hits[0], abs=0.05), f"{camera}: the centre is {seen:.2f} m off, own ship's hull " \
                                                    f"{hits[0]:.2f} m"
    if index == 1:  # the sister has sailed as far as own ship: still abeam
        assert body.x == pytest.approx(OWN_KN * KNOT * t, abs=1e-6) and sim.pose().x == pytest.approx(body.x, abs=1e-6)


@pytest.mark.parametrize("change, message", [
    (('body = "mark"', 'body = "fpso2"'),
     r"cameras\[0\].body: 'fpso2' is not 'ownship' or one of \[\[vessels\]\] \(mark, sister\)$"),
    ((f'target = {_buoy_target()}', 'target = "bow"'),
     r"cameras\[0\].target: 'bow': a point's name is own-ship's; on 'mark' give \[x, y, z\] in its frame or the "
     r"look angles$"),
])
def test_a_camera_on_an_unknown_body_or_aiming_at_a_point_name_there_is_refused(tmp_path, change, message):
    """A camera on a body the scenario lacks, or aiming from another body at one of own ship's points by name (the
    names are her [vessel.points], in her frame): one line naming the key, before anything runs."""
    with pytest.raises(ScenarioError, match=message) as refused:
        load_scenario(write(tmp_path, SCENARIO.replace(*change)))
    assert "\n" not in str(refused.value)


def test_look_angles_on_another_body_are_taken(tmp_path):
    """Look angles instead of a target on another body: the camera is built on that body, looking along them
    (the azimuth positive to starboard, so the body frame's yaw is its negative)."""
    text = SCENARIO.replace(f'target = {_buoy_target()}', "look_azimuth_deg = 40.0\nlook_elevation_deg = -2.0")
    camera = load_scenario(write(tmp_path, text)).cameras[0]
    assert (camera.body, camera.look_yaw_deg, camera.look_pitch_deg, camera.target) == ("mark", -40.0, -2.0, None)
