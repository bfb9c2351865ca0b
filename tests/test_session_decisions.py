"""Decisions an objective asks of the trainee, judged from the exercise's journal (marinesim.session.decisions):
alarms acknowledged in time, and an order given before a criterion's expectation passes its limit."""

from __future__ import annotations

import pytest

from conftest import ROOT, VESSEL_SCENARIO, write
from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario
from marinesim.scenario.schema import Objective
from marinesim.session.decisions import judge
from marinesim.session.exercise import Exercise, run_exercise

ROLL = '\n[[criteria]]\nname = "roll"\nquantity = "roll_rms_deg"\nlimit = {limit}\nwindow_s = 20.0\n'
BUILDING = '''
[[events]]
at_s = 300.0
ramp_s = 60.0
sea = [{ type = "jonswap", hs_m = 12.0, tp_s = 10.0, from_deg = 200.0 }]
'''
ACKNOWLEDGE = Objective("acknowledge within 30 s", ("roll",), "acknowledge", 30.0)
ACT = Objective("act before the roll is expected to pass its limit", ("roll",), "act_before")


def _run(tmp_path, limit: float, drive=None, extra: str = "", duration: float = 120.0) -> Exercise:
    text = VESSEL_SCENARIO.replace("duration_s = 120.0", f"duration_s = {duration}")
    text = text.replace("spreading_s = 10.0\n", "") + ROLL.format(limit=limit)  # long-crested: right astern, no roll
    return run_exercise(load_scenario(write(tmp_path, text + extra)), drive=drive)


def _acknowledge_after(delay_s: float | None):
    """Run the exercise, acknowledging the first alarm ``delay_s`` after it is raised (None: never)."""
    def drive(exercise: Exercise) -> None:
        while not exercise.alarms and not exercise.complete():
            exercise.advance(1.0)
        if delay_s is not None and exercise.alarms:
            exercise.advance_to(exercise.alarms[0].raised_s + delay_s)
            exercise.act("acknowledge")
        exercise.run()
    return drive


@pytest.mark.parametrize("delay_s, verdict", [(5.0, "met"), (45.0, "not met"), (None, "not met")])
def test_an_alarm_is_acknowledged_in_time_or_not(tmp_path, delay_s, verdict):
    """A roll limit of 0.001 deg raises an alarm as soon as the window settles: acknowledged 5 s after, the decision
    is met; 45 s after, or never, it is not, and the words say how late."""
    exercise = _run(tmp_path, 0.001, _acknowledge_after(delay_s))
    judged = judge(exercise, ACKNOWLEDGE)
    assert exercise.alarms and judged.verdict == verdict, judged
    if delay_s == 45.0:
        assert "acknowledged after 45 s (within 30 s asked)" in judged.why
    if delay_s is None:
        assert "never acknowledged" in judged.why


def test_no_alarm_leaves_the_acknowledgement_unjudged(tmp_path):
    """A limit the roll never reaches raises no alarm: there was nothing to acknowledge, which is no pass."""
    judged = judge(_run(tmp_path, 90.0), ACKNOWLEDGE)
    assert judged == judged.__class__("not judged", "no alarm was raised")


@pytest.fixture(scope="module")
def limit_between(tmp_path_factory) -> float:
    """A roll limit between the expectation in the first sea and in the built one (1.8 times the first)."""
    exercise = _run(tmp_path_factory.mktemp("limit"), 90.0, extra=BUILDING, duration=420.0)
    before = exercise.expectations.window(0, 295.0).median
    after = exercise.expectations.window(0, 420.0).median
    assert after > 2.5 * before, "the sea change must raise the expected roll"
    return 1.8 * before


@pytest.mark.parametrize("order_at, course, verdict", [(30.0, 20.0, "met"), (400.0, 20.0, "not met"),
                                                     (None, None, "not met"), (30.0, 110.0, "not met")])
def test_an_order_that_keeps_the_expectation_within_the_limit(tmp_path, limit_between, order_at, course, verdict):
    """The long-crested sea from 200 deg builds from 300 s: on her course of 030 the roll's expectation over its 20 s
    window passes the limit within the ramp. Putting the sea right astern (course 020) at 30 s, time enough for the
    tanker to turn 10 deg, keeps it within and meets the decision; the same order at 400 s, or none, does not; nor
    does an order in time that brings the sea on the beam (course 110), which brings the passing on."""
    def drive(exercise: Exercise) -> None:
        if order_at is not None:
            exercise.advance_to(order_at)
            exercise.act("order", course_deg=course)
        exercise.run()
    exercise = _run(tmp_path, limit_between, drive, BUILDING, duration=420.0)
    judged = judge(exercise, ACT)
    assert judged.verdict == verdict, judged
    if verdict == "not met":
        assert "the expectation of roll passed its limit at" in judged.why


def test_a_decision_names_what_it_needs(tmp_path):
    """acknowledge needs within_s; act_before needs the criteria it is about; within_s goes with acknowledge only."""
    base = VESSEL_SCENARIO + ROLL.format(limit=1.0) + '\n[briefing]\ntext = "t"\nobjectives = [{o}]\n'
    for objective, key in (('{ text = "a", decision = "acknowledge" }', "within_s"),
                           ('{ text = "a", decision = "act_before" }', "criteria"),
                           ('{ text = "a", criteria = ["roll"], within_s = 10.0 }', "within_s")):
        with pytest.raises(ScenarioError, match=key):
            load_scenario(write(tmp_path, base.replace("{o}", objective)))



TRAFFIC = f'''
[[vessels]]
name = "coaster"
kind = "ship"
rao = "{ROOT / 'rao' / 'tanker' / 'tanker.4'}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
position_m = [3000.0, 3000.0]
speed_kn = 10.0
heading_deg = 270.0
manoeuvring = "tanker"
'''


def test_an_order_to_another_ship_is_not_the_trainees(tmp_path):
    """The instructor alters another ship (an order with ``vessel``) in a run stopped before the expectation could
    pass: that is no course or speed change of own-ship's, so the decision is not judged. Counted as hers, it would
    be met for what the instructor did."""
    def drive(exercise: Exercise) -> None:
        exercise.advance_to(30.0)
        exercise.act("order", vessel="coaster", course_deg=300.0)
        exercise.advance_to(60.0)
    exercise = _run(tmp_path, 90.0, drive, TRAFFIC)
    assert not exercise.complete()
    assert judge(exercise, ACT) == judge(exercise, ACT).__class__(
        "not judged", "the run stopped before the expectation passed the limit")
