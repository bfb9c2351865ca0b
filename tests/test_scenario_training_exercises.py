"""The four shipped training exercises: each loads with its briefing and objectives, runs through
``assess`` and ``report`` (short, as CI can afford), and the heavy-weather transit rewards the right
call: the course change brings the roll back within its limit. Every shipped scenario, exercise or not,
draws its ship."""

from __future__ import annotations

import html
import json

import numpy as np
import pytest

from conftest import ROOT, offscreen
from marinesim.cli import main
from marinesim.criteria.monitor import Level
from marinesim.scenario import load_scenario
from marinesim.scenario.model import EnvironmentOptions
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation

TRAINING = sorted((ROOT / "configs" / "training").glob("*.toml"))


def test_four_exercises_ship():
    assert [p.stem for p in TRAINING] == ["crane_lift", "heavy_weather_transit", "helideck_landing",
                                          "offshore_loading"]


@pytest.mark.parametrize("path", TRAINING, ids=[p.stem for p in TRAINING])
def test_an_exercise_runs_through_assess_and_report(path, tmp_path, capsys):
    scenario = load_scenario(path)
    assert scenario.briefing is not None and scenario.briefing.objectives and scenario.events and scenario.criteria
    named = {c.label for c in scenario.criteria}
    for _, criteria in scenario.briefing.objectives:
        assert criteria and set(criteria) <= named, "every objective is judged by the exercise's criteria"
    assert main(["assess", str(path), "--duration", "240", "--json", "--quiet"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["duration_s"] == 240.0 and len(result["criteria"]) == len(scenario.criteria)
    assert main(["report", str(path), "--out", str(tmp_path / "r.html"), "--duration", "240", "--quiet"]) == 0
    page = (tmp_path / "r.html").read_text()
    assert html.escape(scenario.briefing.objectives[0][0]) in page and "<img class='plot'" in page


SHIPPED = sorted((ROOT / "configs").glob("*.toml")) + TRAINING


@pytest.mark.parametrize("path", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_shipped_scenario_shows_its_vessel(path):
    """The first frame with the vessel drawn against the same frame without it: the vessel must cover a
    visible part of the picture near its middle (the orbit camera looks at it), and its pixels carry the paint
    of its visual mesh (every shipped scenario names one), not the plain grey of a hydrodynamic hull. What would
    be wrong: a scenario that draws no ship, a mesh in the wrong frame (under the sea, off screen) or the visual
    mesh not loaded."""
    scenario = load_scenario(path)
    with offscreen(scenario) as view:
        view.go_to(0.0)
        with_vessel = view.frame(hud=False).astype(int)
        own, view.scene.sim.environment = view.scene.sim.environment, EnvironmentOptions()
        in_daylight = view.frame(hud=False).astype(int)  # the paint judged in clear daylight, not the scenario's haze
        view.scene.renderer.vessel.shown = False
        view.scene.sim.environment = own
        without = view.frame(hud=False).astype(int)
    vessel = np.abs(with_vessel - without).sum(axis=2) > 30
    height, width = vessel.shape
    rows, cols = np.nonzero(vessel)
    assert vessel.mean() > 0.005, f"the vessel covers {vessel.mean():.2%} of the frame"
    assert abs(cols.mean() / width - 0.5) < 0.15 and abs(rows.mean() / height - 0.5) < 0.2, "the vessel is off centre"
    assert scenario.vessel.visual is not None, "a shipped scenario draws a ship, not its hydrodynamic hull"
    pixels = in_daylight[vessel]
    chroma = pixels.max(axis=1) - pixels.min(axis=1)
    assert np.median(chroma) > 15, "the visual mesh's paint is missing (a grey hull reads about 3)"


@pytest.mark.slow
def test_the_course_change_is_the_right_call_in_heavy_weather():
    """Without a change the roll goes above 4 deg RMS as the sea builds; altering to 180 deg at 600 s
    keeps it within the limit (the briefing's objective is met)."""
    scenario = load_scenario(ROOT / "configs" / "training" / "heavy_weather_transit.toml")
    worst = {}
    for change in (False, True):
        with Simulation(scenario, wake=False) as simulation:
            exercise = Exercise(simulation)
            if change:
                exercise.advance_to(600.0)
                exercise.act("change", heading_deg=180.0, ramp_s=60.0)
            exercise.run()
        roll = exercise.assessment().criteria[0]
        worst[change] = (roll.value, roll.level)
    assert worst[False][1] is Level.EXCEEDED and worst[True][1] in (Level.OK, Level.CAUTION), worst
    assert worst[True][0] < 4.0 < worst[False][0]
