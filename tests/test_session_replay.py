"""Alarms, live actions, the session log and its replay: a session whose actions fall at arbitrary frame
times replays to the same bytes, and an alarm is raised in the first frame its running value is above
the limit, then held until acknowledged."""

from __future__ import annotations

import filecmp
import json

import numpy as np
import pytest

from conftest import cli, write
from marinesim.scenario import load_scenario
from marinesim.session.exercise import Exercise
from marinesim.session.log import read_log, write_log
from marinesim.session.recorder import Recorder
from marinesim.session.timeline import Simulation
from test_session_exercise import CONDITIONAL


SESSION = CONDITIONAL.format(threshold=0.17).replace("limit = 0.5", "limit = {limit}")
"""400 s of the vessel scenario: a bridge-acceleration criterion (120 s window; its values run from
0.11 to 0.19 m/s^2) whose value above 0.17 fires a slow-down event, and a message at 200 s."""


def _values(scenario) -> tuple[list[float], list[float | None]]:
    """(evaluation times, the criterion's values) of ``scenario`` run in blocks, as ``assess`` runs it."""
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation)
    exercise.run()
    simulation.close()
    return exercise.evaluated_s, [v[0] for v in exercise.values], exercise


def test_an_alarm_is_raised_in_the_first_frame_above_the_limit_and_held_until_acknowledged(tmp_path):
    """The limit is set between the criterion's smallest and largest settled values, so the run crosses
    it; the live run (frames of 0.01-0.7 s) raises the alarm in the frame whose clock first passes the
    evaluation where ``assess`` first sees the value above the limit, and not a frame earlier."""
    times, values, _ = _values(load_scenario(write(tmp_path, SESSION.format(limit=0.5))))
    settled = np.array([v for v in values if v is not None])
    limit = float(np.round(np.median(settled), 4))
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=limit)))
    *_, reference = _values(scenario)
    first = reference.assessment().criteria[0].first_exceeded_s
    assert first is not None and reference.alarms[0].raised_s == first

    simulation = Simulation(scenario, wake=False)
    live = Exercise(simulation)
    rng = np.random.default_rng(3)
    before = 0.0
    while not live.alarms:
        before = simulation.time
        live.advance(rng.uniform(0.01, 0.7))
    assert before < first <= simulation.time, "the alarm must show in the frame that passes its evaluation"
    alarm = live.alarms[0]
    assert alarm.raised_s == first and alarm.value > limit and alarm.name == "bridge acceleration"
    assert live.unacknowledged() == [alarm]
    live.advance(4.3)
    live.act("acknowledge")
    assert live.unacknowledged() == [] and alarm.acknowledged_s == simulation.time
    kinds = [(e["kind"], e.get("criterion")) for e in live.journal]
    assert ("alarm", "bridge acceleration") in kinds
    acknowledged = next(e for e in live.journal if e["kind"] == "acknowledged")
    assert acknowledged["criteria"] == ["bridge acceleration"]
    assert acknowledged["delays_s"] == [pytest.approx(simulation.time - first)]
    simulation.close()


def _live_session(scenario, tmp_path, seed: int):
    """A session as the viewer runs it: random frames, the recorder from t = 0, and the instructor's and
    the trainee's actions at whatever frame time they fall on; returns (the exercise, the recording)."""
    simulation = Simulation(scenario, wake=False)
    exercise = Exercise(simulation)
    recorder = Recorder(exercise, tmp_path / "live.csv")
    plan = [(37.0, "change", {"hs_factor": 1.1, "ramp_s": 10.0}),
            (61.0, "message", {"text": "stand by the helideck"}),
            (80.0, "trigger", {"index": 1}),                      # the 200 s message, brought forward
            (95.0, "change", {"speed_kn": 4.0, "ramp_s": 10.0}),
            (130.0, "acknowledge", {}),
            (151.0, "change", {"heading_deg": 250.0, "ramp_s": 20.0}),
            (170.0, "change", {"turn_waves_deg": 15.0, "tp_factor": 1.05, "ramp_s": 10.0})]
    rng = np.random.default_rng(seed)
    while simulation.time < 220.0:
        exercise.advance(rng.uniform(0.01, 0.7))
        recorder.catch_up()
        while plan and simulation.time >= plan[0][0]:
            _, action, fields = plan.pop(0)
            exercise.note("key", key="X")
            exercise.act(action, **fields)
    recorder.stop()
    exercise.note("end")
    simulation.close()
    return exercise, tmp_path / "live.csv"


@pytest.mark.parametrize("seed", [1, 2])
def test_a_session_replays_to_the_same_bytes(tmp_path, seed):
    """``marinesim replay LOG --export`` writes the bytes the live recorder wrote, and its journal holds the
    same events, alarms, acknowledgements and actions at the same times: the timeline depends on the
    actions and their times only, not on how the frames fell."""
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=0.15)))
    exercise, recording = _live_session(scenario, tmp_path, seed)
    log = write_log(tmp_path / "session.jsonl", exercise)
    assert read_log(log).end_s == exercise.sim.time
    early = next(h for h in exercise.happened if h.index == 1)
    assert early.early and early.time_s < 200.0 and exercise.alarms

    result = cli("replay", str(log), "--export", str(tmp_path / "replay.csv"), "--quiet")
    assert result.returncode == 0, result.stderr
    assert filecmp.cmp(recording, tmp_path / "replay.csv", shallow=False), "the replay's motions differ"
    live_side, replay_side = (json.loads((tmp_path / f"{n}.csv.json").read_text()) for n in ("live", "replay"))
    assert {k: v for k, v in live_side.items() if k != "file"} == {k: v for k, v in replay_side.items() if k != "file"}
    assert live_side["actions"] and live_side["events"]
    assert "verdict" in result.stdout


def test_a_session_log_is_json_lines_with_a_sidecar(tmp_path):
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=0.15)))
    exercise, _ = _live_session(scenario, tmp_path, 4)
    log = write_log(tmp_path / "session.jsonl", exercise)
    lines = log.read_text().splitlines()
    assert json.loads(lines[0])["format"] == "marinesim session log"
    entries = [json.loads(line) for line in lines[1:]]
    assert [e["t"] for e in entries] == sorted(e["t"] for e in entries)
    assert {"event", "action", "key", "alarm", "acknowledged", "end"} <= {e["kind"] for e in entries}
    sidecar = json.loads((tmp_path / "session.jsonl.json").read_text())
    import hashlib
    assert sidecar["data_sha256"] == hashlib.sha256(log.read_bytes()).hexdigest()
    assert sidecar["files"]["scenario"]["sha256"] == json.loads(lines[0])["scenario_sha256"]


BAD_LOGS = [
    ("{not json", "line 2", "not a JSON object"),
    ('{"t": -1.0, "kind": "key", "key": "X"}', "line 2", "key 't'"),
    ('{"t": 5.0, "kind": "action", "action": "change", "speed": 3}', "line 2", "unknown key 'speed'"),
    ('{"t": 5.0, "kind": "action", "action": "warp"}', "line 2", "key 'action'"),
    ('{"t": 5.0, "kind": "action", "action": "change", "speed_kn": NaN}', "line 2", "NaN"),
    ('{"t": 5.0, "kind": "action", "action": "order", "engine": "flank speed"}', "line 2",
     "key 'engine': expected one of full astern"),
    ('{"t": 5.0, "kind": "action", "action": "order", "autopilot": "yes"}', "line 2", "key 'autopilot': expected true"),
    ('{"t": 5.0, "kind": "action", "action": "order", "rudder_deg": "hard"}', "line 2", "key 'rudder_deg': expected a"),
    ('{"t": 5.0, "kind": "action", "action": "order", "rudder_deg": 50}', "line 2",
     "order: rudder order must be in -35..35 deg"),
]


@pytest.mark.parametrize("line, where, words", BAD_LOGS)
def test_a_bad_session_log_is_refused_in_one_line(tmp_path, line, where, words):
    scenario = write(tmp_path, SESSION.format(limit=0.15))
    from marinesim.session.sidecar import sha256

    head = {"format": "marinesim session log", "version": 1, "scenario": str(scenario),
            "scenario_sha256": sha256(scenario), "seed": 1, "duration_s": 400.0, "dt_s": 0.25}
    log = tmp_path / "bad.jsonl"
    log.write_text(json.dumps(head) + "\n" + line + "\n")
    result = cli("replay", str(log), "--export", str(tmp_path / "x.csv"), "--unverified", "--quiet")
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 2 and len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    assert str(log) in lines[0] and where in lines[0] and words in lines[0], lines[0]
    assert not (tmp_path / "x.csv").exists()


def test_a_changed_scenario_is_not_replayed(tmp_path):
    """A replay of a scenario edited since the session would not be that session: refused, naming it."""
    scenario = load_scenario(write(tmp_path, SESSION.format(limit=0.15)))
    exercise, _ = _live_session(scenario, tmp_path, 5)
    log = write_log(tmp_path / "session.jsonl", exercise)
    scenario.path.write_text(scenario.path.read_text().replace("seed = 1", "seed = 2"))
    result = cli("replay", str(log), "--headless", "--quiet")
    assert result.returncode == 2 and "has changed since the session" in result.stderr, result.stderr
