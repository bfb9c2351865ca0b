"""Draft marks: numerals every 0.2 m of draft at the stem, amidships and the stern, read off the picture."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from conftest import ROOT, luminance, offscreen, ray_hits
from marinesim.render.draft_marks import ADVANCE_M, GLYPH_WIDTH_M, NUMERAL_M, STROKE_M, draft_marks, reading
from marinesim.render.vessel_mesh import visual_mesh
from marinesim.scenario import load_scenario
from marinesim.sea.seastate import scaled_sea

SEGMENT_CENTRES = {  # (x, z) over the numeral's width and height: the seven-segment digit's strokes
    "top": (0.5, 1.0 - 0.09), "top right": (0.87, 0.75), "bottom right": (0.87, 0.25), "bottom": (0.5, 0.09),
    "bottom left": (0.13, 0.25), "top left": (0.13, 0.75), "middle": (0.5, 0.5)}
DIGITS = {"0": "top,top right,bottom right,bottom,bottom left,top left", "1": "top right,bottom right",
          "2": "top,top right,middle,bottom left,bottom",
          "4": "top left,middle,top right,bottom right", "6": "top,top left,middle,bottom left,bottom,bottom right",
          "8": "top,top right,bottom right,bottom,bottom left,top left,middle",
          "9": "top,top right,bottom right,bottom,top left,middle"}


@pytest.fixture(scope="module")
def s175():
    """The S175 (design draft 9.5 m; its bare hull and its visual mesh) stopped in a calm sea."""
    scenario = load_scenario(ROOT / "configs" / "s175_head_seas.toml")
    return dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, 0.01, 1.0, 0.0),
                               vessel=dataclasses.replace(scenario.vessel, speed_m_s=0.0))


def test_readings_and_where_the_marks_stand(s175):
    """Whole metres read "<n>M", the rest their decimetre; the keel is the S175's baseline at every station, so the
    calm waterline (z = -0.05 m in her body frame) reads her design draft, 9.5 m; the forward and aft marks stand
    near the waterline's ends and go up to 1.5 times the draft (14.3 m: under the deck edge, 15.4 m)."""
    assert [reading(d) for d in (9.0, 9.2, 9.4, 9.6, 9.8, 10.0, 12.0)] == ["9M", "2", "4", "6", "8", "10M", "12M"]
    mesh = visual_mesh(s175.vessel.visual)
    marks = draft_marks(s175.vessel.hull, mesh.positions)
    for keel in marks.keel_z:
        assert -0.05 - keel == pytest.approx(9.5, abs=0.01)
    forward, midship, aft = marks.stations_x
    assert 80.0 < forward < 86.0 and -95.0 < aft < -85.0 and midship == pytest.approx((forward + aft) / 2)
    for keel, top in zip(marks.keel_z, marks.top_z):
        assert top - keel == pytest.approx(1.5 * 9.55)


def read_numerals(view, station: int, side: float) -> list[tuple[str, str]]:
    """(expected, read) for every numeral at ``station`` on ``side`` (-1 starboard, +1 port) that stands wholly
    above the water in a view from 4 m off the plating: each stroke sampled where the marks' rules put it."""
    scene = view.scene
    marks, mesh = scene.renderer.vessel.marks, scene.renderer.mesh
    x_station = marks["u_marks_x"][station]
    keel = marks["u_marks_keel"][station]
    pose = scene.sim.pose()
    triangles = mesh.positions.reshape(-1, 3, 3)

    def surface(x: float, z: float) -> np.ndarray:
        distances, _ = ray_hits(triangles, (x, 60.0 * side, z), (0.0, -side, 0.0))
        return np.array([x, 60.0 * side - side * distances[0], z])

    target = pose.world(surface(x_station, 0.6)[None, :])[0]
    outward = np.array([-math.sin(pose.heading), math.cos(pose.heading), 0.0]) * side
    scene.camera_name = "free"
    free = scene.cameras["free"]
    free.position = tuple(target + 4.0 * outward)
    free.yaw_deg, free.pitch_deg = math.degrees(math.atan2(-outward[1], -outward[0])), 0.0
    image = luminance(view.frame(hud=False))
    eye = scene.camera.eye(pose)

    def brightness(x: float, z: float) -> float:
        col, row = eye.project(pose.world(surface(x, z)[None, :]), view.size)[0, :2]
        return float(image[int(row), int(col)])

    found = []
    run = -side   # the text runs forward (+x) on the starboard side, aft on the port side
    for k in range(int((-keel) / 0.2) + 1, int((1.8 - keel) / 0.2)):
        draft = 0.2 * k
        z = keel + draft
        text = reading(round(draft, 1))
        width = (len(text) - 1) * ADVANCE_M + GLYPH_WIDTH_M
        paint = brightness(x_station, z + 0.15)          # the gap between two numerals
        read = ""
        for i, char in enumerate(text):
            left = -0.5 * width + i * ADVANCE_M
            def lit(u: float, v: float) -> bool:
                return brightness(x_station + run * (left + u * GLYPH_WIDTH_M), z + v * NUMERAL_M) > paint + 15.0
            if char == "M":
                read += "M" if lit(0.13, 0.5) and lit(0.87, 0.5) and not lit(0.5, 0.09) else "?"
                continue
            strokes = {name for name, (u, v) in SEGMENT_CENTRES.items() if lit(u, v)}
            read += next((d for d, names in DIGITS.items() if set(names.split(",")) == strokes), "?")
        found.append((text, read))
    return found


def test_the_marks_read_the_drafts_above_the_water_at_the_bow_on_both_sides_and_amidships(s175):
    """From 4 m off the plating at the forward marks (port and starboard) and the midship ones, every numeral between
    the waterline and 1.8 m above it reads what its draft says (9.6, 9.8, 10M, ... 11M): numbers misplaced by a
    step, mirrored on one side or drawn at the wrong height fail it."""
    assert STROKE_M * 192.0 > 3.0   # a stroke is over three pixels at 4 m in a 720-line frame
    with offscreen(s175, (1280, 720)) as view:
        view.go_to(5.0)
        for station, side in ((0, -1.0), (0, 1.0), (1, -1.0)):
            found = read_numerals(view, station, side)
            assert len(found) >= 8
            assert [read for _, read in found] == [expected for expected, _ in found], (station, side, found)
