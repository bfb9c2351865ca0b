"""`marinesim run` without a display: the headless run's files, reproducible and equal to the drawn
surface; the wake drawn and cached for every scenario speed; a bad scenario refused before anything runs."""

import json

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
    first = cli("run", str(scenario_path), "--out", "a", "--duration", "2", "--quiet", cwd=tmp_path)
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


@pytest.mark.slow  # 14-21 s here: a headless run with its video, twice
def test_run_with_a_hull_draws_the_wake_and_caches_every_scenario_speed(tmp_path):
    """`marinesim run` on a vessel with a hull precomputes the wake at each scenario speed (into the
    cache) and draws the one at the vessel's speed; below Fn 0.1 it draws none and says why."""
    from marinesim.wake.cache import cache_dir

    slow = write(tmp_path, SCENARIO.replace("duration_s = 120.0", "duration_s = 20.0"), "slow.toml")
    result = cli("run", str(slow), "--out", "slow", "--duration", "2", "--quiet", cwd=tmp_path)  # a 2 s video
    assert result.returncode == 0 and "no wake drawn at 6 kn: Fn 0.062" in result.stdout
    assert not (tmp_path / "slow" / "wake.png").exists()
    text = SCENARIO.replace("speed_kn = 6.0", "speed_kn = 12.0\nwake_speeds_kn = [6.0]")
    path = write(tmp_path, text.replace("duration_s = 120.0", "duration_s = 20.0"))
    before = set(cache_dir().glob("*.npz")) if cache_dir().is_dir() else set()
    result = cli("run", str(path), "--out", "out", "--duration", "2", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "the Kelvin wake" in result.stdout and (tmp_path / "out" / "wake.png").stat().st_size > 20_000
    speeds = sorted(json.loads(str(np.load(p)["info_json"]))["speed_kn"] for p in set(cache_dir().glob("*.npz")) - before)
    assert speeds == pytest.approx([12.0])  # 6 kn came from the cache filled by the slow run
