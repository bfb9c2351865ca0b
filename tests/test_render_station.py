"""What a DP operator sees in the viewer: the footprint plot, the offset chart and the thrusters' use, on the
shipped supply vessel on DP (configs/supply_dp.toml) after her first bow tunnel was lost at 10 minutes."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from conftest import ROOT
from marinesim.scenario import load_scenario


def test_the_panels_show_the_footprint_plot_and_each_thrusters_use_with_the_lost_one_crossed_out():
    """At 11 minutes with the panels on (1280 x 720): the DP line names her offset against the 5 m footprint and
    each thruster's use, the lost bow tunnel as X; the footprint plot sits at the right (its circle green: she is
    inside) and leaves the middle of the picture, the vessel's, free; a fifth strip chart gives the offset.
    What would be wrong if not: a DP operator without the position plot, or a lost thruster shown as idle."""
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.renderer import RenderOptions

    scenario = load_scenario(ROOT / "configs" / "supply_dp.toml")
    with Offscreen(scenario, (1280, 720), solver="off", options=RenderOptions(reproducible=True, hud="panels",
                                                                              wake=False)) as view:
        view.go_to(660.0)
        lines = view.scene.hud_lines()
        footprint = view.scene.footprint()
        charts = [chart.title for chart in view.scene.charts()]
        with_hud = view.frame(hud=True).astype(int)
        bare = view.frame(hud=False).astype(int)
    dp = next(line for line in lines if line.startswith("DP  offset"))
    assert "/ 5 m" in dp and "thrust % X " in dp, dp
    assert charts[-1] == "offset"
    assert footprint is not None and footprint.radius == 5.0 and footprint.east.size > 100
    assert np.hypot(footprint.east, footprint.north).max() < 5.0
    hud = np.abs(with_hud - bare).sum(axis=2) > 30
    green = (with_hud[..., 1] > 180) & (with_hud[..., 0] < 150) & (with_hud[..., 2] < 160) & hud
    right = green[:, 1280 - 300:]
    assert right[:360].sum() > 150, "the footprint's green circle at the top right"
    assert hud[260:460, 440:840].mean() < 0.02, "the middle, where the vessel is, stays free"


NO_WINDOW = 77


@pytest.mark.slow
def test_the_instructor_fails_a_thruster_and_the_reference_with_keys_and_the_replay_holds_them(tmp_path):
    """The viewer (pyglet's headless EGL window, real key events) on configs/supply_dp.toml: L loses the first
    working thruster, Q sets the position reference drifting, RIGHT turns the DP's heading 5 deg, UP UP V move her
    set point 2 m ahead and 1 m to starboard; the session log holds them as orders, and its replay has the same faults and the same record to the last digit. What would be
    wrong if not: an instructor who cannot fail the DP live, or a log that does not bring back what happened."""
    result = subprocess.run([sys.executable, __file__, str(tmp_path)], capture_output=True, text=True, timeout=600)
    if result.returncode == NO_WINDOW:
        pytest.skip(f"no headless pyglet window: {result.stdout.strip()}")
    assert result.returncode == 0, result.stderr[-3000:]


def walkthrough(tmp_path: Path) -> None:
    from marinesim.gl import GraphicsError
    from marinesim.render.viewer import NoDisplay, Viewer
    from marinesim.session.replay import replay_session

    scenario = load_scenario(ROOT / "configs" / "supply_dp.toml")
    try:
        viewer = Viewer(scenario, size=(320, 180), headless=True)
    except (NoDisplay, GraphicsError) as error:
        print(error)
        sys.exit(NO_WINDOW)
    import pyglet

    key = pyglet.window.key
    viewer.log_path = tmp_path / "session.jsonl"

    def press(symbol: int, text: str | None) -> None:
        viewer.window.dispatch_event("on_key_press", symbol, 0)
        if text is not None:
            viewer.window.dispatch_event("on_text", text)
        viewer.window.dispatch_event("on_key_release", symbol, 0)
        viewer.window.dispatch_events()

    try:
        for _ in range(20):
            viewer.tick(0.1)
        press(key.L, "l")
        press(key.Q, "q")
        press(key.RIGHT, None)
        for symbol, text in ((key.UP, None), (key.UP, None), (key.V, "v")):
            press(symbol, text)
        for _ in range(30):
            viewer.tick(0.1)
        viewer.draw()
        sim = viewer.scene.sim
        faults = sim.voyage.orders.faults
        assert faults == {"thruster:bow tunnel 1", "reference drift"}, faults
        assert math.isclose(math.degrees(sim.voyage.orders.course), 35.0), sim.voyage.orders.course
        heading = math.radians(35.0)  # two metres ahead and one to starboard of her new heading
        assert math.isclose(sim.voyage.orders.north, 2.0 * math.cos(heading) - math.sin(heading), abs_tol=1e-5)
        assert math.isclose(sim.voyage.orders.east, 2.0 * math.sin(heading) + math.cos(heading), abs_tol=1e-5)
        record = sim.frame(np.arange(0.0, 5.0, 0.1))
    finally:
        viewer.close()
    again = replay_session(tmp_path / "session.jsonl")
    assert again.sim.voyage.orders.faults == faults
    replayed = again.sim.frame(np.arange(0.0, 5.0, 0.1))
    for column, values in record.items():
        np.testing.assert_array_equal(replayed[column], values, err_msg=column)


if __name__ == "__main__":
    walkthrough(Path(sys.argv[1]))
