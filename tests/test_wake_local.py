"""The local flow about a moving hull (the double-body flow at zero Froude number): the water it raises ahead of
the stem and lowers along the shoulders, checked against a direct sum of its sources and drawn with the waves."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from conftest import ROOT, offscreen, ray_hits
from marinesim.constants import G, KNOT
from marinesim.hull import load_hull
from marinesim.render.camera import FAR_M, NEAR_M
from marinesim.render.wake_look import wake_appearance
from marinesim.scenario import load_scenario
from marinesim.sea.seastate import scaled_sea
from marinesim.wake.compute import WakeGrid, compute_wake
from marinesim.wake.local import local_flow, sources

SPEED = 18.0 * KNOT


@pytest.fixture(scope="module")
def s175():
    hull = load_hull(ROOT / "hulls" / "s175_hull.stl")
    surface = hull.wetted()
    return hull, surface, local_flow(surface, SPEED)


def test_the_fft_sum_is_the_direct_sum_of_the_sources_and_their_images(s175):
    """At 60 grid points around the S175 (outside her waterplane, up to 40 m off), the layered FFT's velocity is
    the direct sum of the same sources and their images above the still water, (u, v) = m (x - x_j, y - y_j) /
    (2 pi r^3), to 1 % of the largest: a wrong factor, depth or image, or periodic copies of the hull, fail it."""
    _, surface, flow = s175
    points, n_x_ds = sources(surface, flow.cell_m)
    depth = np.maximum(-points[:, 2], flow.cell_m)
    strength = SPEED * n_x_ds
    half_beam = float(np.abs(surface.corners[:, 1]).max())
    bow, stern = float(surface.corners[:, 0].max()), float(surface.corners[:, 0].min())
    rng = np.random.default_rng(7)
    fft, direct = [], []
    for _ in range(60):
        i = int(round((rng.uniform(stern - 40.0, bow + 40.0) - flow.x0) / flow.cell_m))
        j = int(round((rng.choice((-1.0, 1.0)) * rng.uniform(half_beam + 2.0, half_beam + 40.0) - flow.y0)
                      / flow.cell_m))
        x, y = flow.x0 + i * flow.cell_m, flow.y0 + j * flow.cell_m
        d = np.c_[x - points[:, 0], y - points[:, 1]]
        r3 = (d[:, 0] ** 2 + d[:, 1] ** 2 + depth**2) ** 1.5
        direct.append((strength / (2.0 * math.pi * r3)) @ d)
        fft.append((flow.u[j, i], flow.v[j, i]))
    fft, direct = np.array(fft), np.array(direct)
    assert np.abs(fft - direct).max() < 0.01 * np.abs(direct).max()


def test_the_bow_raises_the_water_ahead_of_it_and_the_shoulders_lower_it(s175):
    """At 18 kn: the water stands over half a metre high just ahead of the stem, falls off ahead of it (under
    15 % of that 20 m out), lies lowest beside midships (the ship's own trough) and rises again at the stern."""
    _, surface, flow = s175
    x, y = flow.axes()
    bow, stern = float(surface.corners[:, 0].max()), float(surface.corners[:, 0].min())
    centre = flow.elevation[np.argmin(np.abs(y))]

    def ahead(m: float) -> float:
        return float(centre[np.argmin(np.abs(x - (bow + m)))])

    assert 0.5 < ahead(1.0) < 0.5 * SPEED**2 / (2.0 * G)   # well under the stagnation head
    assert ahead(1.0) > ahead(5.0) > ahead(20.0) > ahead(60.0) > 0.0
    assert ahead(20.0) < 0.15 * ahead(1.0)
    beside = flow.elevation[np.argmin(np.abs(y - float(np.abs(surface.corners[:, 1]).max()) - 2.0))]
    middle = float(beside[np.argmin(np.abs(x - 0.5 * (bow + stern)))])
    assert middle < -0.2 and middle == pytest.approx(beside[(x > stern) & (x < bow)].min(), abs=0.1)
    assert float(centre[np.argmin(np.abs(x - (stern - 2.0)))]) > 0.3


def test_the_drawn_wake_carries_the_bow_wave_ahead_of_the_stem(s175):
    """The wake the renderer draws raises the water ahead of the stem (the waves alone are still there: they start
    at the bow), and the local flow falls to the still level at the grid's front edge, not in a step."""
    hull, surface, flow = s175
    wake = compute_wake(hull, SPEED, WakeGrid(nx=512, ny=256))
    bow = float(surface.corners[:, 0].max())
    row = int(np.argmin(np.abs(wake.y)))
    just_ahead = int(np.argmin(np.abs(wake.x - (bow + 2.0))))
    drawn = wake_appearance(wake)[..., 0]
    assert wake.elevation[row, just_ahead] == 0.0
    assert drawn[row, just_ahead] > 0.5
    assert drawn[row, just_ahead] == pytest.approx(flow.sample(wake.x[just_ahead:just_ahead + 1],
                                                               wake.y[row:row + 1])[0, 0], rel=0.05)
    assert np.abs(wake.local[:, -1]).max() == 0.0 and np.abs(wake.local[:, -2]).max() < 0.05 * drawn.max()


def water_in_front(view, body_point: np.ndarray, eye_offset: np.ndarray) -> bool:
    """Whether, from ``eye_offset`` (m, vessel frame) off ``body_point`` on the hull's plating, something (the
    water) stands in front of that point: the depth buffer's distance there is shorter than the point's."""
    scene = view.scene
    pose = scene.sim.pose()
    target = pose.world(body_point[None, :])[0]
    rotation = pose.matrix()[:3, :3]
    eye_at = target + rotation @ eye_offset
    scene.camera_name = "free"
    free = scene.cameras["free"]
    look = target - eye_at
    free.position = tuple(eye_at)
    free.yaw_deg = math.degrees(math.atan2(look[1], look[0]))
    free.pitch_deg = math.degrees(math.atan2(look[2], math.hypot(look[0], look[1])))
    view.frame(hud=False)
    width, height = view.size
    depth = np.frombuffer(view._fbo.read(components=1, attachment=-1, dtype="f4"), np.float32)
    depth = depth.reshape(height, width)[::-1]
    col, row, distance = scene.camera.eye(pose).project(target[None, :], view.size)[0]
    near, far = NEAR_M, FAR_M
    z = 2.0 * float(depth[int(row), int(col)]) - 1.0
    seen = 2.0 * near * far / (far + near - z * (far - near))
    return seen < distance - 1.0


def test_the_picture_shows_the_water_raised_against_the_stem_and_lowered_amidships():
    """The S175 at 18 kn in a flat calm, seen from 30 m abeam: 0.4 m above the still waterline, the plating 2 m
    aft of the stem is under the bow wave and the plating amidships is bare (the ship's trough)."""
    scenario = load_scenario(ROOT / "configs" / "s175_head_seas.toml")
    calm = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, 0.01, 1.0, 0.0),
                               vessel=dataclasses.replace(scenario.vessel, speed_m_s=SPEED))
    hull = calm.vessel.hull.wetted()
    bow = float(hull.corners[:, 0].max())
    with offscreen(calm, (640, 360)) as view:
        view.go_to(5.0)
        mesh = view.scene.renderer.mesh.positions.reshape(-1, 3, 3)
        for x, covered in ((bow - 2.0, True), (0.0, False)):
            distances, _ = ray_hits(mesh, (x, -60.0, 0.35), (0.0, 1.0, 0.0))
            plating = np.array([x, -60.0 + distances[0], 0.35])
            assert water_in_front(view, plating, np.array([0.0, -30.0, 3.0])) == covered, x
