"""The helicopter as drawn (marinesim/render/aircraft.py): an S-92's dimensions, faces that the renderer's back-face
culling keeps, lights where an aircraft carries them, and its silhouette drawn on a real OpenGL context."""

from __future__ import annotations

import math

import moderngl
import numpy as np
import pytest

from conftest import ray_hits
from marinesim.pose import Pose
from marinesim.render.aircraft import (FUSELAGE_LENGTH_M, HEIGHT_M, OVERALL_LENGTH_M, ROTOR_DIAMETER_M, ROTOR_GREY,
                                       TAIL_ROTOR_DIAMETER_M, TYRE, helicopter_lights, helicopter_mesh,
                                       helicopter_parts)
from marinesim.render.camera import Eye
from marinesim.render.daylight import light_at
from marinesim.render.layers.base import View
from marinesim.render.layers.vessel import VesselLayer
from marinesim.render.nav_lights import GREEN, RED, WHITE, luminous_intensity_cd, sector_weight
from marinesim.scenario.model import EnvironmentOptions


@pytest.fixture(scope="module")
def mesh():
    return helicopter_mesh()


def painted(mesh, rgb) -> np.ndarray:
    """The corners (k, 3) of the triangles painted ``rgb`` (0..255)."""
    corners = mesh.positions.reshape(-1, 3, 3)
    colour = mesh.colours.reshape(-1, 3, 3)[:, 0]
    return corners[np.all(np.isclose(colour, np.asarray(rgb) / 255.0), axis=1)].reshape(-1, 3)


def test_the_bounds_are_an_s92s_within_ten_percent(mesh):
    """Nose to tail 17.32 m, 4.71 m high to the rotor head, the main rotor 17.17 m across (the blades' tips from the
    mast) and the tail rotor 3.35 m, 20.85 m long with the rotors turning (the main rotor's disc ahead to the tail
    rotor's astern), all within 10 %; the origin at the wheels' bottom, midway between the nose and main wheels. A
    rotor drawn by its radius for its diameter, feet for metres or the origin at the mast would fail."""
    lo, hi = mesh.positions.min(axis=0), mesh.positions.max(axis=0)
    assert hi[0] - lo[0] == pytest.approx(FUSELAGE_LENGTH_M, rel=0.1)
    assert hi[2] == pytest.approx(HEIGHT_M, rel=0.1) and lo[2] == 0.0
    grey = painted(mesh, ROTOR_GREY)
    head = grey[grey[:, 2] > HEIGHT_M - 0.05]
    mast = head[:, :2].mean(axis=0)
    blades = grey[grey[:, 2] > 4.4]  # above the tail rotor
    reach = np.hypot(*(blades[:, :2] - mast).T).max()
    assert 2.0 * reach == pytest.approx(ROTOR_DIAMETER_M, rel=0.1)
    tail = grey[grey[:, 0] < lo[0] + TAIL_ROTOR_DIAMETER_M + 1.0]
    hub = tail[:, [0, 2]].min(axis=0) + np.ptp(tail[:, [0, 2]], axis=0) / 2.0
    tail_reach = np.hypot(tail[:, 0] - hub[0], tail[:, 2] - hub[1]).max()
    assert 2.0 * tail_reach == pytest.approx(TAIL_ROTOR_DIAMETER_M, rel=0.1)
    assert (mast[0] + reach) - (hub[0] - tail_reach) == pytest.approx(OVERALL_LENGTH_M, rel=0.1)
    ground = painted(mesh, TYRE)
    ground = ground[ground[:, 2] < 1e-6]
    assert (ground[:, 0].min() + ground[:, 0].max()) / 2.0 == pytest.approx(0.0, abs=0.05)
    assert ground[:, 1].min() == pytest.approx(-ground[:, 1].max(), abs=1e-9)


def test_every_part_is_closed_and_faces_outwards(mesh):
    """Each part encloses a positive signed volume (its faces wound counter-clockwise seen from outside), and rays
    from every side meet a face turned towards them first: with back faces culled, an inward face would let the eye
    see through the fuselage."""
    assert all(part.volume() > 0.0 for part in helicopter_parts())
    triangles = mesh.positions.reshape(-1, 3, 3)
    normals = mesh.normals.reshape(-1, 3, 3)[:, 0]
    spans = (np.linspace(-13.5, 4.5, 25), np.linspace(-6.0, 6.0, 17), np.linspace(0.05, 4.7, 11))
    met = 0
    for axis in range(3):
        u, v = [k for k in range(3) if k != axis]
        for sign in (1.0, -1.0):
            direction = np.zeros(3)
            direction[axis] = -sign
            for a in spans[u] + 0.0137:
                for b in spans[v] + 0.0071:
                    origin = np.zeros(3)
                    origin[[axis, u, v]] = (40.0 * sign, a, b)
                    _, faces = ray_hits(triangles, origin, direction)
                    if len(faces):
                        met += 1
                        assert normals[faces[0]] @ direction < 0.0, (origin, direction)
    assert met > 300


def test_the_lights_are_an_aircrafts():
    """Red to port and green to starboard, each from ahead to 110 deg on its side, white astern over 140 deg (14 CFR
    29.1387), all round red beacons; the intensities 40, 20 and 150 cd the rules ask (29.1391, 29.1393, 29.1401),
    recovered through COLREG Annex I's range formula; the port light seen from port shows and from starboard does
    not; every light within 0.25 m of the drawn skin along an axis."""
    lights = {light.name: light for light in helicopter_lights()}
    port, starboard, tail = lights["port position"], lights["starboard position"], lights["tail position"]
    assert port.colour == RED and port.position[1] > 1.5 and starboard.colour == GREEN and starboard.position[1] < -1.5
    assert tail.colour == WHITE and (tail.sector_deg[1] - tail.sector_deg[0]) % 360.0 == 140.0
    assert sector_weight(port, np.array([5.0, 100.0, -5.0, 150.0])).tolist() == [1.0, 1.0, 0.0, 0.0]
    assert sector_weight(starboard, np.array([-5.0, -100.0, 5.0])).tolist() == [1.0, 1.0, 0.0]
    for name, cd in (("port position", 40.0), ("tail position", 20.0), ("anti-collision upper", 150.0)):
        assert luminous_intensity_cd(lights[name].range_nm) == pytest.approx(cd, rel=1e-9)
    beacons = [light for light in lights.values() if light.name.startswith("anti-collision")]
    assert len(beacons) == 2 and all(b.colour == RED and b.sector_deg == (0.0, 360.0) for b in beacons)
    assert lights["landing"].position[0] > 0.0 and lights["landing"].position[2] < 1.0
    triangles = helicopter_mesh().positions.reshape(-1, 3, 3)
    for light in lights.values():
        nearest = min(ray_hits(triangles, light.position, direction)[0].min(initial=math.inf)
                      for direction in np.r_[np.eye(3), -np.eye(3)])
        assert nearest < 0.25, light.name


def test_the_side_view_silhouette_is_as_long_for_its_height_as_the_type(gl_context, mesh):
    """Drawn at 320 x 240 through the vessel pass from 150 m abeam to starboard, the silhouette's length over its
    height in pixels is what the mesh's corners projected by the same camera on the CPU give (within 3 %), and the
    S-92's 17.8 m over 4.71 m within 10 %: a mesh drawn inside out (culled away), squashed or with a missing part
    would not match."""
    size = (320, 240)
    lo, hi = mesh.positions.min(axis=0), mesh.positions.max(axis=0)
    centre = (lo + hi) / 2.0
    eye = Eye(centre + np.array([0.0, -150.0, 0.0]), np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0]), 8.5)
    view = View(eye, eye.view_projection(size[0] / size[1]), light_at(EnvironmentOptions()))
    layer = VesselLayer(gl_context, mesh)
    target = gl_context.simple_framebuffer(size)
    try:
        target.use()
        target.clear(0.0, 0.0, 0.0, 1.0)
        gl_context.enable(moderngl.DEPTH_TEST)
        layer.draw(view, Pose())
        image = np.frombuffer(target.read(components=3), np.uint8).reshape(size[1], size[0], 3)
    finally:
        layer.release()
        target.release()
    rows, cols = np.nonzero(image.max(axis=2) > 2)
    length_px, height_px = np.ptp(cols) + 1, np.ptp(rows) + 1
    projected = eye.project(mesh.positions, size)
    expected = np.ptp(projected[:, 0]) / np.ptp(projected[:, 1])
    assert 150 < length_px < 260
    assert length_px / height_px == pytest.approx(expected, rel=0.03)
    assert length_px / height_px == pytest.approx((hi[0] - lo[0]) / HEIGHT_M, rel=0.03)
    assert length_px / height_px == pytest.approx(FUSELAGE_LENGTH_M / HEIGHT_M, rel=0.1)
    assert math.isclose(np.ptp(projected[:, 0]), length_px, abs_tol=3.0)
