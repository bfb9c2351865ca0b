"""`marinesim run` without a display: the headless run's files, reproducible and equal to the drawn
surface; the wake drawn (and computed) only where thin-ship theory holds; an exercise's session log that replay and
report read; a bad scenario refused before anything runs."""

import json
import os

import numpy as np
import pandas as pd
import pytest

from conftest import SEA_SCENARIO as GOOD, VESSEL_SCENARIO as SCENARIO, cli, write
from marinesim.scenario import load_scenario
from marinesim.session.assembly import Assembly


@pytest.mark.slow  # 14-21 s here: a headless run with its video, twice
def test_run_writes_reproducible_files_that_match_the_surface(tmp_path):
    """--duration 2 (the scenario says 60 s): the same files, a 2 s video instead of 10 s, 4x faster."""
    scenario_path = write(tmp_path, GOOD)
    first = cli("run", str(scenario_path), "--out", "a", "--duration", "2", "--quiet", "--video", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    assert "running headless" in first.stdout and "wave_elevation.csv" in first.stdout
    assert "2 s at dt 0.5 s" in first.stdout and "rendering 2 s of video" in first.stdout
    second = cli("run", str(scenario_path), "--out", "b", "--duration", "2", "--quiet", cwd=tmp_path)
    assert second.returncode == 0
    a, b = tmp_path / "a", tmp_path / "b"
    # same scenario and seed: byte-identical CSV
    assert (a / "wave_elevation.csv").read_bytes() == (b / "wave_elevation.csv").read_bytes()
    frame = pd.read_csv(a / "wave_elevation.csv")
    assert list(frame.columns) == ["time_s", "wave_elevation_m"]
    assert len(frame) == 5 and frame["time_s"].iloc[-1] == pytest.approx(2.0)  # 0 to --duration at dt_s
    sidecar = json.loads((a / "wave_elevation.csv.json").read_text())
    assert sidecar["seed"] == 3 and len(sidecar["scenario_sha256"]) == 64
    # what the CSV holds is the drawn surface: at t = 0 the summed FFT tiles at the origin
    scenario = load_scenario(scenario_path)
    ocean = Assembly(scenario).ocean
    drawn = sum(float(f.height[0, 0]) for f in ocean.fields(0.0))
    sigma = scenario.sea.hs / 4
    assert frame["wave_elevation_m"].iloc[0] == pytest.approx(drawn, abs=0.1 * sigma)
    assert (a / "sea.png").stat().st_size > 20_000 and (a / "wave_elevation.png").stat().st_size > 10_000


def test_run_with_bad_scenario_exits_2_with_one_line(tmp_path):
    path = write(tmp_path, GOOD.replace("hs_m = 3.0", "hs_m = -1.0"))
    result = cli("run", str(path), cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and "sea[0]" in result.stderr
    assert not (tmp_path / "out").exists()  # refused before anything ran
    missing = cli("run", str(tmp_path / "nope.toml"), cwd=tmp_path)
    assert missing.returncode == 2 and "no such scenario" in missing.stderr


def test_run_with_a_hull_computes_and_draws_only_the_wake_at_her_speed(tmp_path):
    """`marinesim run` on a vessel with a hull draws the wake at her speed, computing it into the cache; below
    Fn 0.1, where thin-ship theory does not hold, it computes none and says why; the other speeds a scenario names
    for the viewer are not computed by a headless run (they cost the run time and draw nothing)."""
    cache = tmp_path / "cache"
    env = {**os.environ, "MARINESIM_CACHE_DIR": str(cache)}
    slow = write(tmp_path, SCENARIO.replace("duration_s = 120.0", "duration_s = 20.0"), "slow.toml")
    result = cli("run", str(slow), "--out", "slow", "--duration", "2", "--quiet", cwd=tmp_path, env=env)
    assert result.returncode == 0 and "no wake drawn at 6 kn: Fn 0.062" in result.stdout
    assert not (tmp_path / "slow" / "wake.png").exists() and not list(cache.glob("wake/*.npz"))
    text = SCENARIO.replace("speed_kn = 6.0", "speed_kn = 12.0\nwake_speeds_kn = [6.0]")
    path = write(tmp_path, text.replace("duration_s = 120.0", "duration_s = 20.0"))
    result = cli("run", str(path), "--out", "out", "--duration", "2", "--quiet", cwd=tmp_path, env=env)
    assert result.returncode == 0, result.stderr
    assert "the Kelvin wake" in result.stdout and (tmp_path / "out" / "wake.png").stat().st_size > 20_000
    speeds = sorted(json.loads(str(np.load(p)["info_json"]))["speed_kn"] for p in cache.glob("wake/*.npz"))
    assert speeds == pytest.approx([12.0])
    assert not (tmp_path / "out" / "video.mp4").exists() and "--video" in result.stdout  # a video on request only


def test_headless_exercise_writes_a_session_log_that_replay_and_report_read(tmp_path):
    """If this fails, an exercise run without a display leaves no session log (or one cut short, or one whose
    replay differs from the run), so a trainee's run cannot be replayed or debriefed on a machine without a
    screen."""
    from conftest import ROOT

    exercise = ROOT / "configs" / "training" / "crane_lift.toml"
    run = cli("run", str(exercise), "--out", "out", "--duration", "30", "--quiet", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    log = tmp_path / "out" / "session.jsonl"
    assert "marinesim report out/session.jsonl" in run.stdout
    replay = cli("replay", str(log), "--export", "replay.csv", "--quiet", cwd=tmp_path)
    assert replay.returncode == 0, replay.stderr
    assert "session log verified" in replay.stdout and "runs to the session's end" in replay.stdout
    ran, replayed = pd.read_csv(tmp_path / "out" / "motions.csv"), pd.read_csv(tmp_path / "replay.csv")
    assert list(ran.columns) == list(replayed.columns) and len(ran) == len(replayed) == 301
    assert np.allclose(ran.to_numpy(), replayed.to_numpy(), rtol=0, atol=1e-9)  # the same run, replayed
    report = cli("report", str(log), "--out", "debrief.html", "--quiet", cwd=tmp_path)
    assert report.returncode == 0, report.stderr
    assert "crane tip vertical velocity" in (tmp_path / "debrief.html").read_text()
