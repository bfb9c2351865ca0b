"""The viewer window through pyglet's headless EGL mode: keys, recording, pause, help, redraws.

The walkthrough runs in a fresh Python process: moderngl finds pyglet's headless EGL context only
in a process that has made no other context (the rest of the suite makes many), so the test runs
this file as a script and reads its verdict (exit 0, 77 = no headless window here, else the error).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from conftest import DEFAULT
from marinesim.cli import main
from marinesim.gl import GraphicsError
from marinesim.render.controls import CHANGE_RAMP_S, HS_STEP, MAX_FRAME_S
from marinesim.scenario import load_scenario

NO_WINDOW = 77


@pytest.mark.slow
def test_an_operator_session_records_changes_the_sea_and_pauses(tmp_path):
    result = subprocess.run([sys.executable, __file__, str(tmp_path)], capture_output=True, text=True, timeout=600)
    if result.returncode == NO_WINDOW:
        pytest.skip(f"no headless pyglet window: {result.stdout.strip()}")
    assert result.returncode == 0, result.stderr[-3000:]


def walkthrough(tmp_path: Path) -> None:
    from marinesim.render.viewer import NoDisplay, Viewer

    scenario = load_scenario(DEFAULT)
    try:
        viewer = Viewer(scenario, size=(320, 180), headless=True)
    except (NoDisplay, GraphicsError) as error:  # no EGL here: nothing to test
        print(error)
        sys.exit(NO_WINDOW)
    controls, sim = viewer.controls, viewer.scene.sim
    controls.recordings = tmp_path
    try:
        controls.press("R")                               # record from t = 0
        for _ in range(30):
            viewer.tick(0.1)
        viewer.draw()
        controls.press("R")
        recorded = pd.read_csv(next(tmp_path.glob("*.csv")))
        assert main(["export", str(DEFAULT), "--out", str(tmp_path / "export.out"), "--duration", "3",
                     "--quiet"]) == 0
        exported = pd.read_csv(tmp_path / "export.out")
        assert list(recorded.columns) == list(exported.columns)
        assert len(recorded) == len(exported) == 31
        np.testing.assert_allclose(recorded.to_numpy(), exported.to_numpy(), rtol=1e-9, atol=1e-9)
        assert not list(tmp_path.glob(".*")), "the recording left its temporary file"

        hs = sim.sea.hs
        controls.press("BRACKETRIGHT")                    # waves up by 10 % over CHANGE_RAMP_S
        speed = sim.speed_m_s
        controls.press("UP")                              # waits for the sea change, then blends
        for _ in range(int(2.2 * CHANGE_RAMP_S / MAX_FRAME_S)):
            viewer.tick(5.0)                               # a stalled frame still advances only 0.1 s
        assert sim.time == pytest.approx(2.2 * CHANGE_RAMP_S + 3.0, abs=1e-6)
        assert sim.sea.hs == pytest.approx(HS_STEP * hs, rel=1e-9)
        assert sim.speed_m_s == pytest.approx(speed + 0.514444, rel=1e-4)

        controls.press("SPACE")
        before = sim.time
        viewer.tick(0.1)
        assert sim.time == before, "paused, the simulation must not move"
        controls.press("SPACE")

        for key in ("2", "H", "3", "W", "1"):
            controls.press(key)
            viewer.tick(0.05)
            viewer.draw()
            assert viewer.ctx.error == "GL_NO_ERROR"
        assert viewer.scene.camera_name == "orbit" and controls.show_help
    finally:
        viewer.close()


if __name__ == "__main__":
    walkthrough(Path(sys.argv[1]))
