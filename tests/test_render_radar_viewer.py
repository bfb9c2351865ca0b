"""The radar picture in the viewer: key 5 shows and hides it in a pyglet window (headless EGL, pyglet's own key
events), key 6 steps its range, the scene hands the HUD the traffic where the scenario puts it (own ship's track,
each body's place and velocity relative to her, the auto range), and a headless render draws it too.

The window's walkthrough runs in a fresh Python process, as tests/test_render_viewer.py's does (moderngl finds
pyglet's headless EGL context only in a process that has made no other context): the test runs this file as a
script and reads its verdict (exit 0, 77 = no headless window here, else the error).
"""

from __future__ import annotations

import inspect
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT, VESSEL_SCENARIO, offscreen, write
from marinesim.constants import KNOT
from marinesim.gl import GraphicsError
from marinesim.constants import NAUTICAL_MILE as NM
from marinesim.scenario import load_scenario

NO_WINDOW = 77
SIZE = (640, 360)
TANKER = ROOT / "rao" / "tanker" / "tanker.4"
OWN_KN, SHIP_KN = 5.0, 8.0
MARK, SHIP = (400.0, 300.0), (-3000.0, 1000.0)
SCENARIO = f"""
[ocean]
resolution = 64
tiles = 2

[[sea]]
type = "jonswap"
hs_m = 2.0
tp_s = 9.0
from_deg = 200.0

[vessel]
rao = "{TANKER}"
speed_kn = {OWN_KN}
heading_deg = 0.0

[run]
duration_s = 120.0
dt_s = 0.1
seed = 5

[[vessels]]
name = "mark"
kind = "buoy"
position_m = [{MARK[0]}, {MARK[1]}]

[[vessels]]
name = "tanker"
kind = "ship"
rao = "{TANKER}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
position_m = [{SHIP[0]}, {SHIP[1]}]
speed_kn = {SHIP_KN}
heading_deg = 90.0
"""
"""Own ship heading north at 5 kn from the origin; a buoy 400 m east and 300 m north of her start; a tanker 3 km
west and 1 km north steaming east at 8 kn."""


def changed(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Pixels (h, w) where two frames differ by more than a rounding."""
    return (np.abs(a.astype(int) - b.astype(int)) > 8).any(axis=2)


def panel_mask(rect: tuple[int, int, int]) -> np.ndarray:
    """The radar panel's pixels (h, w) of a :data:`SIZE` frame, ``rect`` from ``Hud.radar_rect``."""
    x, y, side = rect
    mask = np.zeros(SIZE[::-1], bool)
    mask[y:y + side, x:x + side] = True
    return mask


def test_key_5_shows_and_hides_the_radar_in_the_window(tmp_path):
    result = subprocess.run([sys.executable, __file__, str(tmp_path)], capture_output=True, text=True, timeout=600)
    if result.returncode == NO_WINDOW:
        pytest.skip(f"no headless pyglet window: {result.stdout.strip()}")
    assert result.returncode == 0, result.stderr[-3000:]


def walkthrough(tmp_path: Path) -> None:
    """With other vessels the radar is up from the start; 35 s on, the radar the HUD is handed has own ship on
    heading 000 at 5 kn with her track 5 kn astern of her every 10 s, the buoy and the tanker where their positions
    less hers put them (a sign or frame slip, a stale cache, the absolute positions instead of relative ones would
    move them), and the 0.75 nm scale holding the buoy 452 m off. Key 5 hides it: the pixels that change are those
    of its panel, nearly all of them, and nothing else; key 5 again brings the same frame back. Key 6 twice: the
    1.5 nm scale."""
    from marinesim.render.hud import Hud
    from marinesim.render.viewer import NoDisplay, Viewer

    scenario = load_scenario(write(tmp_path, SCENARIO))
    try:
        viewer = Viewer(scenario, size=SIZE, headless=True)
    except (NoDisplay, GraphicsError) as error:
        print(error)
        sys.exit(NO_WINDOW)
    import pyglet

    key = pyglet.window.key
    handed = []
    draw = Hud.draw

    def spy(self, *args, **kwargs):
        handed.append(inspect.signature(draw).bind(self, *args, **kwargs).arguments.get("radar"))
        return draw(self, *args, **kwargs)

    Hud.draw = spy

    def press(symbol: int, text: str) -> None:
        viewer.window.dispatch_event("on_key_press", symbol, 0)
        viewer.window.dispatch_event("on_text", text)
        viewer.window.dispatch_event("on_key_release", symbol, 0)
        viewer.window.dispatch_events()

    target = viewer.ctx.framebuffer(color_attachments=[viewer.ctx.renderbuffer(SIZE)],
                                    depth_attachment=viewer.ctx.depth_renderbuffer(SIZE))

    def frame() -> np.ndarray:
        """The window's scene drawn as the window draws it, into a framebuffer that can be read (a headless
        window's own cannot), (h, w, 3), top row first."""
        target.use()
        viewer.scene.draw(SIZE)
        data = target.read(components=3, alignment=1)
        assert viewer.ctx.error == "GL_NO_ERROR"
        return np.frombuffer(data, np.uint8).reshape(SIZE[1], SIZE[0], 3)[::-1].copy()

    try:
        scene = viewer.scene
        assert scene.radar_shown
        t = 35.0
        scene.step(t)
        assert scene.sim.time == t
        shown = frame()
        radar = handed[-1]
        own, ship = OWN_KN * KNOT, SHIP_KN * KNOT
        assert radar.heading_deg == pytest.approx(0.0, abs=1e-9)
        np.testing.assert_allclose(radar.velocity, [0.0, own], atol=1e-9)
        np.testing.assert_allclose(radar.track, [[0.0, -own * (t - s)] for s in (0.0, 10.0, 20.0, 30.0, t)],
                                   atol=1e-6)
        mark, tanker = radar.contacts
        assert (mark.name, tanker.name) == ("mark", "tanker")
        np.testing.assert_allclose(mark.position, [MARK[0], MARK[1] - own * t], atol=1e-6)
        np.testing.assert_allclose(mark.velocity, [0.0, 0.0], atol=1e-12)
        np.testing.assert_allclose(tanker.position, [SHIP[0] + ship * t, SHIP[1] - own * t], atol=1e-6)
        np.testing.assert_allclose(tanker.velocity, [ship, 0.0], atol=1e-9)
        assert tanker.heading_deg == pytest.approx(90.0, abs=1e-9)
        assert radar.range_m == 0.75 * NM

        rect = scene.hud.radar_rect(SIZE)
        press(key._5, "5")
        assert not scene.radar_shown
        hidden = frame()
        assert handed[-1] is None
        diff = changed(shown, hidden)
        panel = panel_mask(rect)
        assert not diff[~panel].any(), "hiding the radar changed pixels outside its panel"
        assert diff[panel].mean() > 0.9
        press(key._5, "5")
        assert scene.radar_shown and np.array_equal(frame(), shown)

        press(key._6, "6")
        press(key._6, "6")
        frame()
        assert handed[-1].range_m == 1.5 * NM and viewer.controls.message == "radar range 1.5 nm"
    finally:
        Hud.draw = draw
        viewer.ctx.screen.use()  # never release the bound framebuffer
        target.release()
        viewer.close()


def test_a_headless_render_draws_the_radar_with_other_vessels(tmp_path):
    """``marinesim render``'s frames (Offscreen, HUD on) show the radar where the scenario has other vessels, in the
    HUD's radar panel and nowhere else, and none without them, as the window does: a render that left it out would
    leave the traffic off the video."""
    view = offscreen(load_scenario(write(tmp_path, SCENARIO)), SIZE, hud="strip", wake=False, spray=False,
                     reproducible=True)
    with view:
        view.go_to(5.0)
        assert view.scene.radar_shown
        shown = view.frame()
        rect = view.scene.hud.radar_rect(SIZE)
        view.scene.radar_shown = False
        diff = changed(shown, view.frame())
    panel = panel_mask(rect)
    assert not diff[~panel].any() and diff[panel].mean() > 0.9
    plain = load_scenario(write(tmp_path, VESSEL_SCENARIO, "plain.toml"))
    with offscreen(plain, SIZE, hud="strip", wake=False, spray=False, vessel=False) as view:
        assert not view.scene.radar_shown and view.scene.radar() is None


if __name__ == "__main__":
    walkthrough(Path(sys.argv[1]))
