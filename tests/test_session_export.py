"""Motion export (marinesim.session.export): the CSV is exactly the computed series and reproducible,
Parquet holds the same table, every shipped scenario exports, and the sidecar reads on its own (units, conventions,
paths relative to its folder)."""

import json
import math
import re

import numpy as np
import pandas as pd
import pytest

from conftest import ROOT, VESSEL_SCENARIO as SCENARIO, write
from marinesim.constants import KNOT
from marinesim.manoeuvring.voyage import SHIP_COLUMNS
from marinesim.scenario import load_scenario, with_run
from marinesim.session.assembly import Assembly
from marinesim.session.exercise import AHEAD, BLOCK, Exercise
from marinesim.session.export import export_motions
from marinesim.session.sidecar import column_units, sha256
from marinesim.session.timeline import Simulation
from marinesim.vessel import motion_columns


def test_csv_round_trip_equals_the_in_memory_series_and_is_reproducible(tmp_path):
    scenario = load_scenario(write(tmp_path, SCENARIO))
    first = export_motions(Assembly(scenario), tmp_path / "a.csv")
    second = export_motions(Assembly(scenario), tmp_path / "b.csv")
    assert (tmp_path / "a.csv").read_bytes() == (tmp_path / "b.csv").read_bytes()
    a_meta, b_meta = (json.loads(p.read_text()) for p in (first.sidecar, second.sidecar))
    assert {k: v for k, v in a_meta.items() if k != "file"} == {k: v for k, v in b_meta.items() if k != "file"}
    frame = pd.read_csv(tmp_path / "a.csv")  # plain defaults: no comment lines, one header row
    assert list(frame.columns) == motion_columns(scenario.vessel.points) + list(SHIP_COLUMNS) == first.columns
    assert len(frame) == 1201 and frame["time_s"].iloc[-1] == pytest.approx(120.0)
    times = np.arange(1201) * 0.1
    memory = Assembly(scenario).response.frame(times)
    for name in memory:  # what was written is exactly what was computed: a straight run at 6 kn on 030
        np.testing.assert_allclose(frame[name].to_numpy(), memory[name], rtol=1e-10, atol=1e-12, err_msg=name)
    speed, heading = 6.0 * KNOT, math.radians(30.0)
    steady = {"north_m": speed * math.cos(heading) * times, "east_m": speed * math.sin(heading) * times,
              "heading_deg": (30.0 - memory["yaw_deg"]) % 360.0, "course_over_ground_deg": 30.0,
              "speed_over_ground_kn": 6.0, "rate_of_turn_deg_min": 0.0, "rudder_deg": 0.0, "rudder_order_deg": 0.0,
              "propeller_rpm": 60.0 * scenario.vessel.ship.rps_for_speed(speed), "drift_angle_deg": 0.0}
    for name, value in steady.items():
        np.testing.assert_allclose(frame[name].to_numpy(), np.broadcast_to(value, times.shape), rtol=1e-10, atol=1e-9,
                                   err_msg=name)
    assert a_meta["seed"] == 11 and a_meta["rows"] == 1201 and len(a_meta["vessel"]["rao_sha256"]) == 64
    assert a_meta["vessel"]["speed_kn"] == pytest.approx(6.0) and a_meta["columns"] == first.columns
    other_seed = export_motions(Assembly(with_run(scenario, seed=12)), tmp_path / "c.csv")
    assert pd.read_csv(other_seed.table)["heave_m"].std() != pytest.approx(frame["heave_m"].std(), rel=1e-6)


def test_a_day_streams_out_a_block_at_a_time(tmp_path):
    """A day at 10 Hz (864,001 rows) with no criterion to evaluate: its first block of rows is out, to be written,
    once at most :data:`AHEAD` rows have been computed. What would be wrong: the whole day computed before the first
    row reaches the file (gigabytes held in memory, the progress bar still until the end, and an interrupt landing
    before anything is written)."""
    scenario = with_run(load_scenario(write(tmp_path, SCENARIO)), duration=86400.0)
    exercise = Exercise(Simulation(scenario, wake=False))
    try:
        assert exercise.monitor is None
        first = next(exercise.blocks())
        assert BLOCK <= first["time_s"].size <= AHEAD and exercise.row <= AHEAD
        assert exercise.sim.time == pytest.approx(first["time_s"][-1])
    finally:
        exercise.sim.close()


def test_a_weather_event_of_a_run_without_criteria_acts_at_its_time(tmp_path):
    """The supply vessel on DP without her footprint criterion (so nothing is evaluated on the way), the wind
    freshening from 14 to 19 m/s over 20 s from 150 s: the exported wind she feels is the scenario's until 150 s and
    about 19 m/s after the ramp. What would be wrong: the change applied when the clock next stops (at the end of the
    export, or of a block of rows), so that the exported run never meets the weather its scenario scripts."""
    text = ((ROOT / "configs" / "supply_dp.toml").read_text().replace('"../', f'"{ROOT.as_posix()}/')
            .replace("footprint_m = 5.0\n", "").replace("duration_s = 1800.0", "duration_s = 300.0")
            .replace("at_s = 600.0", "at_s = 100.0").replace("at_s = 1200.0", "at_s = 150.0")
            .replace("ramp_s = 120.0", "ramp_s = 20.0"))
    scenario = load_scenario(write(tmp_path, text))
    assert not scenario.criteria
    export_motions(Assembly(scenario), tmp_path / "m.csv")
    table = pd.read_csv(tmp_path / "m.csv")
    calm = load_scenario(write(tmp_path, text.replace("wind_speed_m_s = 19.0", "wind_speed_m_s = 14.0"), "calm.toml"))
    export_motions(Assembly(calm), tmp_path / "calm.csv")
    before = table["time_s"] <= 150.0
    calm_wind = pd.read_csv(tmp_path / "calm.csv")["wind_speed_m_s"]
    np.testing.assert_array_equal(table["wind_speed_m_s"][before], calm_wind[before])
    after = table["wind_speed_m_s"][table["time_s"] >= 200.0]
    assert 17.5 < after.mean() < 20.5 and table["wind_speed_m_s"][before].mean() < 15.5, after.mean()


def test_parquet_holds_the_same_table(tmp_path):
    scenario = with_run(load_scenario(write(tmp_path, SCENARIO)), duration=30.0)
    export_motions(Assembly(scenario), tmp_path / "m.csv")
    export_motions(Assembly(scenario), tmp_path / "m.parquet", "parquet")
    csv, parquet = pd.read_csv(tmp_path / "m.csv"), pd.read_parquet(tmp_path / "m.parquet")
    assert list(parquet.columns) == list(csv.columns)
    np.testing.assert_allclose(parquet.to_numpy(), csv.to_numpy(), rtol=1e-12, atol=1e-15)


CONFIGS = sorted((ROOT / "configs").glob("*.toml"))


@pytest.mark.parametrize("config", CONFIGS, ids=[c.stem for c in CONFIGS])
def test_shipped_scenarios_load_and_export(tmp_path, config):
    scenario = load_scenario(config)
    assert scenario.vessel is not None and scenario.vessel.points
    result = export_motions(Assembly(with_run(scenario, duration=10.0)), tmp_path / "m.csv")
    frame = pd.read_csv(result.table)
    assert np.all(np.isfinite(frame.to_numpy())) and frame["heave_m"].std() > 0.01
    meta = json.loads(result.sidecar.read_text())
    assert list(meta["units"]) == list(frame.columns), "a column without its unit in the sidecar"
    assert meta["units"]["speed_over_ground_kn"] == "kn" and meta["units"].get("wind_force_x_kn", "kN") == "kN"
    assert not _absolute(meta), f"an absolute path in the sidecar: {_absolute(meta)}"


def _absolute(value) -> list[str]:
    """The strings in a sidecar that are absolute paths (POSIX, a Windows drive or share)."""
    if isinstance(value, dict):
        return [s for item in value.values() for s in _absolute(item)]
    if isinstance(value, list):
        return [s for item in value for s in _absolute(item)]
    return [value] if isinstance(value, str) and re.match(r"/|[A-Za-z]:[\\/]|\\\\", value) else []


def test_the_sidecar_reads_without_the_checkout_and_moves_with_its_files(tmp_path):
    """The sidecar names the table, scenario, RAO and hull files relative to its own folder (each one resolves
    there to the file whose hash it gives), holds no absolute path (it broke when the folder was moved or
    shared), gives every column of the table read back its unit, and states the frames, signs and phase
    convention itself instead of citing docs/CONVENTIONS.md, which an installed wheel does not carry."""
    scenario = load_scenario(write(tmp_path, SCENARIO))
    result = export_motions(Assembly(with_run(scenario, duration=10.0)), tmp_path / "out" / "m.csv")
    meta = json.loads(result.sidecar.read_text())
    folder = result.sidecar.parent
    assert not _absolute(meta), _absolute(meta)
    assert (folder / meta["file"]).resolve() == result.table.resolve()
    assert sha256(folder / meta["file"]) == meta["data_sha256"]
    for name, path, digest in (("scenario", meta["scenario"], meta["scenario_sha256"]),
                               ("rao", meta["vessel"]["rao"], meta["vessel"]["rao_sha256"]),
                               ("hull", meta["vessel"]["hull"], meta["vessel"]["hull_sha256"])):
        assert sha256(folder / path) == digest, f"the sidecar's {name} {path} is not the file it hashed"
    assert (folder / meta["scenario"]).resolve() == scenario.path.resolve()
    frame = pd.read_csv(result.table)
    assert set(frame.columns) == set(meta["units"]) and all(meta["units"].values())
    assert meta["units"]["roll_vel_deg_s"] == "deg/s" and meta["units"]["bow_az_m_s2"] == "m/s^2"
    assert meta["units"]["time_s"] == "s" and meta["units"]["rate_of_turn_deg_min"] == "deg/min"
    text = result.sidecar.read_text()
    assert "CONVENTIONS.md" not in text
    assert {"frames", "signs", "directions", "waves", "columns"} <= set(meta["conventions"])
    assert "leading the wave" in meta["conventions"]["waves"] and "bow down" in meta["conventions"]["signs"]


def test_a_column_without_a_unit_in_its_name_is_refused():
    """A column added to the record without a unit ending would be written with none in the sidecar."""
    assert column_units(["wind_force_x_kn", "speed_over_ground_kn", "wind_moment_knm"]) == {
        "wind_force_x_kn": "kN", "speed_over_ground_kn": "kn", "wind_moment_knm": "kN m"}
    with pytest.raises(ValueError, match="'heading'"):
        column_units(["heading"])
