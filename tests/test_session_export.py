"""Motion export (marinesim.session.export): the CSV is exactly the computed series and reproducible,
Parquet holds the same table, and every shipped scenario exports."""

import json
import math

import numpy as np
import pandas as pd
import pytest

from conftest import ROOT, VESSEL_SCENARIO as SCENARIO, write
from marinesim.constants import KNOT
from marinesim.manoeuvring.voyage import SHIP_COLUMNS
from marinesim.scenario import load_scenario, with_run
from marinesim.session.assembly import Assembly
from marinesim.session.export import export_motions
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
