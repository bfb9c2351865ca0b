"""Scenario files: validated before anything runs; `marinesim run` writes reproducible files."""

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario
from marinesim.scenario.export import VARIANCE_FRACTION, build_ocean

ROOT = Path(__file__).resolve().parent.parent
DEFAULT = ROOT / "configs" / "default.toml"

GOOD = """
[[sea]]
type = "jonswap"
hs_m = 3.0
tp_s = 9.0
from_deg = 45.0
spreading_s = 10.0

[run]
duration_s = 60.0
dt_s = 0.5
seed = 3
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "scenario.toml"
    path.write_text(text)
    return path


def test_default_scenario_is_a_north_sea_state():
    scenario = load_scenario(DEFAULT)
    assert 3.0 < scenario.sea.hs < 5.0 and 7.0 < scenario.sea.tp < 12.0
    assert len(scenario.sea.systems) == 2


def test_good_scenario_converts_directions(tmp_path):
    scenario = load_scenario(write(tmp_path, GOOD))
    # from 045 (north-east) travels towards south-west: beta = -135 deg
    assert math.degrees(scenario.sea.systems[0].beta) == pytest.approx(-135.0)
    assert scenario.run.seed == 3 and scenario.run.dt_s == 0.5


@pytest.mark.parametrize("change, key", [
    (("hs_m = 3.0", "hs_m = -3.0"), "sea[0]: hs"),
    (("hs_m = 3.0", "hs = 3.0"), "sea[0].hs: unknown key"),
    (("tp_s = 9.0", 'tp_s = "nine"'), "sea[0].tp_s: expected float"),
    (("tp_s = 9.0", "tp_s = nan"), "sea[0].tp_s"),
    (("from_deg = 45.0", "from_deg = 400.0"), "sea[0].from_deg"),
    (("from_deg = 45.0", ""), "sea[0].from_deg: required"),
    (('type = "jonswap"', 'type = "bretschneider"'), "bretschneider"),
    (("seed = 3", "seed = -3"), "run.seed"),
    (("seed = 3", "seed = 3.5"), "run.seed: expected int"),
    (("dt_s = 0.5", "dt_s = 0.0"), "run.dt_s"),
    (("duration_s = 60.0", "duration_s = -1.0"), "run.duration_s"),
    (("[run]", "[run]\nspeed = 3"), "run.speed: unknown key"),
    (("[run]", "[ocean]\nresolution = 100\n[run]"), "100"),
    (("[run]", "[ocean]\ndepth_m = -4.0\n[run]"), "depth"),
    (("[run]", "[vessl]\n[run]"), "vessl: unknown key"),
    (("[[sea]]", "[[sea]\n"), "not valid TOML"),
])
def test_bad_scenarios_are_refused_naming_the_key(tmp_path, change, key):
    path = write(tmp_path, GOOD.replace(*change))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert key in str(info.value) and str(path) in str(info.value)


def test_scenario_without_sea_is_refused(tmp_path):
    with pytest.raises(ScenarioError, match="at least one"):
        load_scenario(write(tmp_path, "[run]\nseed = 1\n"))


def run_cli(*args, cwd):
    return subprocess.run([sys.executable, "-m", "marinesim", "run", *args], capture_output=True, text=True,
                          cwd=cwd, timeout=600)


def test_run_writes_reproducible_files_that_match_the_surface(tmp_path):
    scenario_path = write(tmp_path, GOOD)
    first = run_cli(str(scenario_path), "--out", "a", "--quiet", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    assert "running headless" in first.stdout and "wave_elevation.csv" in first.stdout
    second = run_cli(str(scenario_path), "--out", "b", "--quiet", cwd=tmp_path)
    assert second.returncode == 0
    a, b = tmp_path / "a", tmp_path / "b"
    # same scenario and seed: byte-identical CSV
    assert (a / "wave_elevation.csv").read_bytes() == (b / "wave_elevation.csv").read_bytes()
    frame = pd.read_csv(a / "wave_elevation.csv")
    assert list(frame.columns) == ["time_s", "wave_elevation_m"]
    assert len(frame) == 121 and frame["time_s"].iloc[-1] == pytest.approx(60.0)
    sidecar = json.loads((a / "wave_elevation.json").read_text())
    assert sidecar["seed"] == 3 and len(sidecar["scenario_sha256"]) == 64
    # what the CSV holds is the drawn surface: at t = 0 the summed FFT tiles at the origin
    scenario = load_scenario(scenario_path)
    ocean = build_ocean(scenario)
    drawn = sum(float(f.height[0, 0]) for f in ocean.fields(0.0))
    sigma = scenario.sea.hs / 4
    assert frame["wave_elevation_m"].iloc[0] == pytest.approx(drawn, abs=0.1 * sigma)
    assert (a / "sea.png").stat().st_size > 20_000 and (a / "wave_elevation.png").stat().st_size > 10_000


def test_run_time_series_has_the_sea_states_variance(tmp_path):
    # a long record at one point: time-averaged eta^2 = sum |a|^2 / 2 of the kept components
    text = GOOD.replace("duration_s = 60.0", "duration_s = 3600.0")
    scenario = load_scenario(write(tmp_path, text))
    ocean = build_ocean(scenario)
    components = ocean.components(variance_fraction=VARIANCE_FRACTION)
    times = np.arange(0.0, 3600.0, 0.5)
    series = components.elevation(0.0, 0.0, times)
    assert np.var(series) == pytest.approx(components.variance, rel=0.1)  # 1 h record: ~5% scatter
    assert components.variance >= VARIANCE_FRACTION * ocean.components().variance


def test_run_with_bad_scenario_exits_2_with_one_line(tmp_path):
    path = write(tmp_path, GOOD.replace("hs_m = 3.0", "hs_m = -1.0"))
    result = run_cli(str(path), cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and "sea[0]" in result.stderr
    assert not (tmp_path / "out").exists()  # refused before anything ran
    missing = run_cli(str(tmp_path / "nope.toml"), cwd=tmp_path)
    assert missing.returncode == 2 and "no such scenario" in missing.stderr
