"""Scenarios with a vessel, `marinesim export` and `marinesim rao`: real files written and read back."""

import json
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from marinesim.errors import ScenarioError
from marinesim.scenario import load_scenario, with_run
from marinesim.session.assembly import Assembly
from marinesim.session.export import export_motions
from marinesim.vessel import motion_columns

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = sorted((ROOT / "configs").glob("*.toml"))

SCENARIO = f"""
[ocean]
resolution = 64
tiles = 3

[[sea]]
type = "jonswap"
hs_m = 4.0
tp_s = 10.0
from_deg = 200.0
spreading_s = 10.0

[vessel]
rao = "{ROOT / 'rao' / 'tanker' / 'tanker.4'}"
hull = "{ROOT / 'hulls' / 'tanker.gdf'}"
speed_kn = 6.0
heading_deg = 30.0

[vessel.points]
bridge = [-100.0, 0.0, 30.0]
bow = [120.0, 0.0, 12.0]

[run]
duration_s = 120.0
dt_s = 0.1
seed = 11
"""


def write(tmp_path: Path, text: str, name: str = "ship.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def cli(*args, cwd=None, **kwargs):
    return subprocess.run([sys.executable, "-m", "marinesim", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=600, **kwargs)


def test_csv_round_trip_equals_the_in_memory_series_and_is_reproducible(tmp_path):
    scenario = load_scenario(write(tmp_path, SCENARIO))
    first = export_motions(Assembly(scenario), tmp_path / "a.csv")
    second = export_motions(Assembly(scenario), tmp_path / "b.csv")
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
    a_meta, b_meta = (json.loads(p.read_text()) for p in (first.sidecar, second.sidecar))
    assert {k: v for k, v in a_meta.items() if k != "file"} == {k: v for k, v in b_meta.items() if k != "file"}
    frame = pd.read_csv(tmp_path / "a.csv")  # plain defaults: no comment lines, one header row
    assert list(frame.columns) == motion_columns(scenario.vessel.points) == first.columns
    assert len(frame) == 1201 and frame["time_s"].iloc[-1] == pytest.approx(120.0)
    memory = Assembly(scenario).response.frame(np.arange(1201) * 0.1)
    for name in frame.columns:  # what was written is exactly what was computed
        np.testing.assert_allclose(frame[name].to_numpy(), memory[name], rtol=1e-10, atol=1e-12, err_msg=name)
    assert a_meta["seed"] == 11 and a_meta["rows"] == 1201 and len(a_meta["vessel"]["rao_sha256"]) == 64
    assert a_meta["vessel"]["speed_kn"] == pytest.approx(6.0) and a_meta["columns"] == first.columns
    other_seed = export_motions(Assembly(with_run(scenario, seed=12)), tmp_path / "c.csv")
    assert pd.read_csv(other_seed.table)["heave_m"].std() != pytest.approx(frame["heave_m"].std(), rel=1e-6)


def test_parquet_holds_the_same_table(tmp_path):
    pytest.importorskip("pyarrow")
    scenario = with_run(load_scenario(write(tmp_path, SCENARIO)), duration=30.0)
    export_motions(Assembly(scenario), tmp_path / "m.csv")
    export_motions(Assembly(scenario), tmp_path / "m.parquet", "parquet")
    csv, parquet = pd.read_csv(tmp_path / "m.csv"), pd.read_parquet(tmp_path / "m.parquet")
    assert list(parquet.columns) == list(csv.columns)
    np.testing.assert_allclose(parquet.to_numpy(), csv.to_numpy(), rtol=1e-12, atol=1e-15)


def test_interrupted_export_leaves_no_partial_file(tmp_path):
    # a day at 10 Hz takes a while: interrupt it once the temporary file is growing
    scenario = write(tmp_path, SCENARIO.replace("duration_s = 120.0", "duration_s = 86400.0"))
    old = b"time_s\n0.0\n"
    (tmp_path / "motions.csv").write_bytes(old)  # an earlier export must survive intact
    process = subprocess.Popen([sys.executable, "-m", "marinesim", "export", str(scenario), "--out", "motions.csv",
                                "--quiet"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while time.time() < deadline:
        parts = list(tmp_path.glob(".motions.*.part.csv"))
        if parts and parts[0].stat().st_size > 100_000:
            break
        time.sleep(0.05)
    else:
        process.kill()
        pytest.fail("the export never started writing")
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 130 and "interrupted" in stderr and "Traceback" not in stderr
    assert (tmp_path / "motions.csv").read_bytes() == old
    assert not list(tmp_path.glob(".motions.*")) and not (tmp_path / "motions.csv.json").exists()


def test_cli_export_and_rao(tmp_path):
    scenario = write(tmp_path, SCENARIO)
    result = cli("export", str(scenario), "--out", "m.csv", "--duration", "20", "--dt", "0.5", "--seed", "3",
                 "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "41 rows" in result.stdout
    assert json.loads((tmp_path / "m.csv.json").read_text())["seed"] == 3
    report = cli("rao", str(ROOT / "rao" / "s175" / "input.re1"), "--json", "--plot", str(tmp_path / "rao.png"))
    assert report.returncode == 0, report.stderr
    summary = json.loads(report.stdout)
    assert summary["speeds_kn"] == pytest.approx([0, 5, 10, 15, 20], abs=0.01)
    assert summary["long_wave_limits"]["heave"]["status"] == "ok"
    assert summary["long_wave_limits"]["pitch"]["ratio"] == pytest.approx(1.0, abs=0.05)
    assert 15.0 < summary["resonance_period_s"]["roll"] < 30.0  # S175: slow roll, T ~ 21 s
    assert (tmp_path / "rao.png").stat().st_size > 30_000
    text = cli("rao", str(ROOT / "rao" / "tanker" / "tanker.4")).stdout
    assert "long-wave limits" in text and re.search(r"pitch\s+1\.000\s+ok", text)
    for args, message in ((("export", str(scenario), "--out", "x.csv", "--dt", "0"), "run.dt_s: must be in (0"),
                          (("rao", str(scenario)), "unknown RAO format; supported"),
                          (("rao", str(ROOT / "rao" / "s175" / "input.re1"), "--plot", "x.png", "--headings", "head"),
                           "--headings must be comma-separated degrees")):
        refused = cli(*args, cwd=tmp_path)
        assert refused.returncode == 2 and message in refused.stderr and "Traceback" not in refused.stderr
        assert len(refused.stderr.strip().splitlines()) == 1 and not (tmp_path / "x.csv").exists()


@pytest.mark.parametrize("change,message", [
    (("speed_kn = 6.0", "speed_kn = 6.0\ndraft_m = 3.0"), "vessel.draft_m: unknown key"),
    (("speed_kn = 6.0", "speed_kn = 45.0"), "vessel.speed_kn: must be in 0..40 kn"),
    (("heading_deg = 30.0", "heading_deg = 400.0"), "vessel.heading_deg: must be a compass heading"),
    (("bow = [120.0, 0.0, 12.0]", "bow = [120.0, 0.0]"), r"vessel.points.bow: expected \[x, y, z\]"),
    (("tanker.4\"", "nothere.4\""), "vessel.rao: .*nothere.4: no such file"),
    (("speed_kn = 6.0", "speed_kn = 6.0\nroll_damping_pct = 150.0"), "vessel.roll_damping_pct: must be in 0..100"),
    (("speed_kn = 6.0", "speed_kn = 6.0\nroll_damping_pct = 5.0"), "vessel.rao: extra roll damping applies to "
                                                                  "Capytaine datasets only"),
    (("speed_kn = 6.0", "speed_kn = 6.0\nulen_m = -2.0"), "vessel.ulen_m: must be in 0.01..1000 m"),
    (("bow = [120.0, 0.0, 12.0]", "bow = [120.0, 0.0, 12.0]\n\"bad name\" = [0.0, 0.0, 0.0]"),
     "vessel.points.bad name: a point name must be a plain identifier"),
    (("hull = ", "# hull = "), None),
    (("speed_kn = 6.0", "speed_kn = 6.0\nhull_units = \"mm\""), "vessel.hull: .*units='m' gives 256.9 m"),
    (("speed_kn = 6.0", "speed_kn = 6.0\nhull_draft_m = -1.0"), "vessel.hull_draft_m: must be > 0 m"),
    (("speed_kn = 6.0", "speed_kn = 6.0\nwake_speeds_kn = [0.0]"), "vessel.wake_speeds_kn: expected speeds"),
    (("hull = ", "hull_trim_deg = 1.0\n# hull = "), "vessel.hull_trim_deg: given without vessel.hull"),
])
def test_bad_vessel_sections_are_refused_with_the_key(tmp_path, change, message):
    path = write(tmp_path, SCENARIO.replace(*change))
    if message is None:
        assert load_scenario(path).vessel.hull_path is None
        return
    with pytest.raises(ScenarioError, match=message):
        load_scenario(path)


def test_malformed_rao_file_is_refused_naming_file_and_line(tmp_path):
    lines = (ROOT / "rao" / "tanker" / "tanker.4").read_text().splitlines()
    lines[41] = lines[41].replace("E", "X", 1)
    bad = tmp_path / "bad.4"
    bad.write_text("\n".join(lines) + "\n")
    path = write(tmp_path, SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), "bad.4"))
    result = cli("export", str(path), "--out", "m.csv", cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert f"vessel.rao: {bad}, line 42: expected PER" in result.stderr
    assert not (tmp_path / "m.csv").exists()


def test_speed_outside_a_multi_speed_table_is_refused(tmp_path):
    text = SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), str(ROOT / "rao" / "s175" / "input.re1"))
    with pytest.raises(ScenarioError, match="22 kn is outside the RAO table's speeds 0..20 kn"):
        load_scenario(write(tmp_path, text.replace("speed_kn = 6.0", "speed_kn = 22.0")))


def test_export_needs_a_vessel(tmp_path):
    text = SCENARIO.split("[vessel]")[0] + "[run]\nseed = 1\n"
    result = cli("export", str(write(tmp_path, text)), "--out", "m.csv", cwd=tmp_path)
    assert result.returncode == 2 and "no [vessel] section" in result.stderr


def test_run_with_a_hull_draws_the_wake_and_caches_every_scenario_speed(tmp_path):
    """`marinesim run` on a vessel with a hull precomputes the wake at each scenario speed (into the
    cache) and draws the one at the vessel's speed; below Fn 0.1 it draws none and says why."""
    from marinesim.wake.cache import cache_dir

    slow = write(tmp_path, SCENARIO.replace("duration_s = 120.0", "duration_s = 20.0"), "slow.toml")
    result = cli("run", str(slow), "--out", "slow", "--quiet", cwd=tmp_path)
    assert result.returncode == 0 and "no wake drawn at 6 kn: Fn 0.062" in result.stdout
    assert not (tmp_path / "slow" / "wake.png").exists()
    text = SCENARIO.replace("speed_kn = 6.0", "speed_kn = 12.0\nwake_speeds_kn = [6.0]")
    path = write(tmp_path, text.replace("duration_s = 120.0", "duration_s = 20.0"))
    before = set(cache_dir().glob("*.npz")) if cache_dir().is_dir() else set()
    result = cli("run", str(path), "--out", "out", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "the Kelvin wake" in result.stdout and (tmp_path / "out" / "wake.png").stat().st_size > 20_000
    speeds = sorted(json.loads(str(np.load(p)["info_json"]))["speed_kn"] for p in set(cache_dir().glob("*.npz")) - before)
    assert speeds == pytest.approx([12.0])  # 6 kn came from the cache filled by the slow run


@pytest.mark.parametrize("config", CONFIGS, ids=[c.stem for c in CONFIGS])
def test_shipped_scenarios_load_and_export(tmp_path, config):
    scenario = load_scenario(config)
    assert scenario.vessel is not None and scenario.vessel.points
    result = export_motions(Assembly(with_run(scenario, duration=10.0)), tmp_path / "m.csv")
    frame = pd.read_csv(result.table)
    assert np.all(np.isfinite(frame.to_numpy())) and frame["heave_m"].std() > 0.01
