"""Scenario files (marinesim.scenario.model): validated before anything runs, each bad value refused
in one line naming the file, the key, the range and the unit; the vessel section and its meshes."""

import math
import os
from pathlib import Path

import numpy as np
import pytest

from conftest import DEFAULT, ROOT, SEA_SCENARIO as GOOD, VESSEL_SCENARIO as SCENARIO, write
from marinesim.errors import MarinesimError, ScenarioError
from marinesim.hull import load_hull
from marinesim.scenario import load_scenario, reference, with_run
from marinesim.scenario.model import with_reference


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
    (("hs_m = 3.0", "hs_m = -3.0"), "sea[0].hs_m: must be in 0..30 m (0 excluded)"),
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
    (("[run]", "[environment]\nvisibility_m = 10.0\n[run]"), "environment.visibility_m: must be in 50..200000 m"),
    (("[run]", "[environment]\nsun_elevation_deg = -95.0\n[run]"), "environment.sun_elevation_deg"),
    (("[run]", "[environment]\ntime_utc = 2026-11-25T16:00:00\nlatitude_deg = 60.0\nlongitude_deg = 2.0\n[run]"),
     "environment.time_utc"),
    (("[run]", "[environment]\ntime_utc = 2026-11-25T16:00:00Z\nlatitude_deg = 60.0\n[run]"),
     "time_utc needs latitude_deg and longitude_deg"),
    (("[run]", "[environment]\ntime_utc = 2026-11-25T16:00:00Z\nlatitude_deg = 60.0\nlongitude_deg = 2.0\n"
               "sun_elevation_deg = 10.0\n[run]"), "or the sun's keys, not both"),
    (("[run]", "[environment]\nlatitude_deg = 60.0\n[run]"), "latitude_deg and longitude_deg go together"),
    (("[run]", "[environment]\ncloud_cover_oktas = 9\n[run]"), "environment.cloud_cover_oktas: must be in 0..8"),
    (("[run]", "[environment]\nrain_mm_h = -1.0\n[run]"), "environment.rain_mm_h: must be in 0..200 mm/h"),
    (("[run]", "[environment]\nwind_speed_m_s = 100.0\n[run]"), "environment.wind_speed_m_s: must be in 0..60 m/s"),
    (("[run]", "[environment]\nwind_from_deg = 400.0\n[run]"), "environment.wind_from_deg: must be a compass"),
    (("[run]", "[[events]]\nat_s = 5.0\nrain_mm_h = 500.0\n[run]"), "events[0].rain_mm_h"),
    (("[run]", "[[events]]\nat_s = 5.0\nvisibility_m = 20.0\n[run]"), "events[0].visibility_m"),
    (("[run]", "[environment]\nfog = true\n[run]"), "environment.fog: unknown key"),
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


BARGE_VISUAL = ROOT / "hulls" / "barge_visual.glb"


def with_visual(tmp_path: Path, lines: str) -> Path:
    """GOOD with the tanker's RAOs and a [vessel] section ending in ``lines``; mesh paths relative to the file."""
    rao = ROOT / "rao" / "tanker" / "tanker.4"
    return write(tmp_path, GOOD + f'\n[vessel]\nrao = "{rao.as_posix()}"\n{lines}\n')


def relative(tmp_path: Path, path: Path) -> str:
    return Path(os.path.relpath(path, tmp_path)).as_posix()


def test_visual_mesh_in_centimetres_y_up_lands_in_the_body_frame(tmp_path):
    """hulls/barge_visual.glb holds 10000 x 3000 cm with y up and its origin at the keel at the stern; with
    units cm, axes x,-z,y and the offset it is the 100 m barge, keel at z = -5 m, beam along y, and the mast
    top 25 m above the waterline at x = -38 m (aft: the bow is at +x), while the hull stays the box barge."""
    path = with_visual(tmp_path, f'hull = "{relative(tmp_path, ROOT / "hulls" / "box_barge.stl")}"\n'
                                 f'visual_mesh = "{relative(tmp_path, BARGE_VISUAL)}"\n'
                                 'visual_mesh_units = "cm"\nvisual_mesh_axes = "x,-z,y"\n'
                                 'visual_mesh_offset_m = [-50.0, 0.0, -5.0]')
    vessel = load_scenario(path).vessel
    visual = vessel.visual
    assert visual.source == str(BARGE_VISUAL)
    assert np.allclose(visual.vertices.min(axis=0), [-50.0, -10.0, -5.0], atol=1e-4)
    assert np.allclose(visual.vertices.max(axis=0), [50.0, 10.0, 25.0], atol=1e-4)
    top = visual.vertices[visual.vertices[:, 2] > 25.0 - 1e-4]
    assert np.allclose(top[:, 0].mean(), -38.0, atol=1e-4) and np.allclose(top[:, 1].mean(), 0.0, atol=1e-4)
    # the file's own colours: anti-fouling red on every face reaching below the waterline, none above it
    red = np.all(np.abs(visual.colours - np.array([115, 23, 18]) / 255.0) < 1e-3, axis=(1, 2))
    z = visual.vertices[visual.faces][:, :, 2]
    assert red[z.min(axis=1) < -1e-6].all() and not red[z.max(axis=1) > 1e-6].any()
    assert vessel.hull.overall_length_m == pytest.approx(100.0) and vessel.hull_path.name == "box_barge.stl"


def test_an_open_superstructure_alone_is_a_visual_mesh_without_a_hull(tmp_path):
    """A visual mesh may be open and lie wholly above the waterline (a superstructure model): it loads
    (no hull, so no wake or solver), though as a hull it would be refused, and it keeps no colours."""
    wall = tmp_path / "house.obj"
    wall.write_text("v -15 0 5\nv 15 0 5\nv 15 0 15\nv -15 0 15\nf 1 2 3\nf 1 3 4\n")
    vessel = load_scenario(with_visual(tmp_path, 'visual_mesh = "house.obj"')).vessel
    assert vessel.hull is None and vessel.visual.colours is None
    assert vessel.visual.vertices[:, 2].min() == pytest.approx(5.0)
    with pytest.raises(MarinesimError, match="nothing below the waterline"):
        load_hull(wall)


@pytest.mark.parametrize("lines, message", [
    ('visual_mesh = "nothere.glb"', r"vessel.visual_mesh: .*nothere.glb: no such file"),
    ('visual_mesh = "model.fbx"', r"vessel.visual_mesh: .*model.fbx: unknown visual mesh format '.fbx'"),
    ('visual_mesh = "empty.obj"', r"vessel.visual_mesh: .*empty.obj: the mesh has no faces"),
    ('visual_mesh = "nan.obj"', r"vessel.visual_mesh: .*nan.obj: vertex 1 is not finite"),
    ('visual_mesh = "BARGE"', r"vessel.visual_mesh: .*barge_visual.glb: a visual mesh 1e\+04 m long \(x\) is not a "
                              r"vessel .*units='cm' gives 100 m"),
    ('visual_mesh = "BARGE"\nvisual_mesh_units = "cm"\nvisual_mesh_axes = "x,x,z"', r"vessel.visual_mesh: axes"),
    ('visual_mesh = "BARGE"\nvisual_mesh_units = "cm"\nvisual_mesh_offset_m = [1.0, 2.0]',
     r"vessel.visual_mesh: offset must be \[x, y, z\]"),
    ('visual_mesh = "BARGE"\nvisual_mesh_units = "cm"\nvisual_mesh_scale = 0.0',
     r"vessel.visual_mesh_scale: must be > 0"),
    ('visual_mesh_units = "cm"', r"vessel.visual_mesh_units: given without vessel.visual_mesh"),
    ('visual_mesh_offset_m = "up"', r"vessel.visual_mesh_offset_m: expected list"),
])
def test_bad_visual_meshes_are_refused_naming_the_key_and_file(tmp_path, lines, message):
    (tmp_path / "model.fbx").write_text("not a mesh")
    (tmp_path / "empty.obj").write_text("# no faces\nv 0 0 0\n")
    (tmp_path / "nan.obj").write_text("v 0 0 0\nv 30 0 nan\nv 0 1 0\nf 1 2 3\n")
    path = with_visual(tmp_path, lines.replace("BARGE", relative(tmp_path, BARGE_VISUAL)))
    with pytest.raises(ScenarioError, match=message):
        load_scenario(path)


TANKER = ROOT / "rao" / "tanker" / "tanker.4"


@pytest.mark.parametrize("change, message", [
    (("[run]", f'[vessel]\nrao = "{TANKER.as_posix()}"\nspeed_kn = 55\n[run]'),
     "vessel.speed_kn: must be in 0..40 kn, got 55"),
    (("[run]", f'[vessel]\nrao = "{TANKER.as_posix()}"\nroll_damping_pct = 100\n[run]'),
     "vessel.roll_damping_pct: must be in 0..100 % of critical (100 excluded), got 100"),
    (("[run]", f'[vessel]\nrao = "{TANKER.as_posix()}"\nwake_speeds_kn = [12.0]\n[run]'),
     "vessel.wake_speeds_kn: given without vessel.hull"),
    (("from_deg = 45.0", "from_deg = 400"), "sea[0].from_deg: must be a compass direction in 0..360 deg, got 400"),
    (("spreading_s = 10.0", "gamma = 0.5"), "sea[0].gamma: must be in 1..20, got 0.5"),
    (("[run]", "[ocean]\ntiles = 9\n[run]"), "ocean.tiles: must be in 1..8, got 9"),
    (("[run]", "[ocean]\nresolution = 100\n[run]"), "ocean.resolution: must be a power of two in 16..4096, got 100"),
    (("duration_s = 60.0", "duration_s = 0"), "run.duration_s: must be in 0..604800 s (0 excluded), got 0"),
    (("dt_s = 0.5", "dt_s = 90.0"), "run.dt_s: must be <= duration_s (60 s), got 90.0"),
    (("tp_s = 9.0", 'tp_s = "nine"'), "sea[0].tp_s: expected float, got 'nine'"),
    (("tp_s = 9.0", "tp_s = true"), "sea[0].tp_s: expected float, got True"),
    (("tp_s = 9.0", "tp_s = inf"), "sea[0].tp_s: expected a finite number, got inf"),
    (("hs_m = 3.0", "hs = 3.0"), "sea[0].hs: unknown key (known: type, from_deg, hs_m, tp_s, gamma, u10_m_s, "
                                 "fetch_km, spreading, spreading_s, height_m, period_s, phase_deg)"),
])
def test_the_model_refuses_each_value_with_key_range_and_unit(tmp_path, change, message):
    """A value outside its key's range (or of the wrong type) is refused in one line naming the file, the
    key's path, the range with its unit, and the value as written. If this fails, the model lost a range, words it
    differently from the scenario reference (docs/SCENARIOS.md), or reports a key other than the one at fault."""
    path = write(tmp_path, GOOD.replace(*change))
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == f"{path}: {message}"


def test_ints_are_accepted_where_numbers_are_expected(tmp_path):
    """TOML writes 3 for 3.0: an int is a valid float key. If this fails, the model is stricter than
    scenario files have always been read."""
    text = GOOD.replace("hs_m = 3.0", "hs_m = 3").replace("duration_s = 60.0", "duration_s = 60")
    scenario = load_scenario(write(tmp_path, text))
    assert scenario.sea.systems[0].spectrum.hs == 3.0 and isinstance(scenario.run.duration_s, float)


def test_scenario_reference_is_the_models():
    """docs/SCENARIOS.md's scenario reference is the table generated from the model. If this fails, a key, range,
    unit or default changed in marinesim/scenario/model.py and the page was not regenerated
    (python -m marinesim.scenario docs/SCENARIOS.md)."""
    readme = (ROOT / "docs" / "SCENARIOS.md").read_text(encoding="utf-8")
    assert readme == with_reference(readme)
    assert "| `[vessel]` | `speed_kn` | float | kn | 0..40 | `0.0` |" in reference()


@pytest.mark.parametrize("overrides, message", [
    ({"dt": 100.0}, "run.dt_s: must be <= duration_s (60 s), got 100.0"),
    ({"duration": 1e7}, "run.duration_s: must be in 0..604800 s (0 excluded), got 10000000.0"),
    ({"seed": -1}, "run.seed: must be >= 0, got -1"),
    ({"seed": 1.5}, "run.seed: expected int, got 1.5"),
])
def test_run_overrides_are_checked_by_the_model(tmp_path, overrides, message):
    """`marinesim export --duration/--dt/--seed` go through the same [run] model as the file. If this
    fails, an override can set a run the scenario file could not (or is refused in other words)."""
    scenario = load_scenario(write(tmp_path, GOOD))
    with pytest.raises(ScenarioError) as info:
        with_run(scenario, **overrides)
    assert str(info.value) == message
    run = with_run(scenario, duration=30.0, seed=4).run
    assert (run.duration_s, run.dt_s, run.seed) == (30.0, 0.5, 4)


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
    (("hull = ", "hull_trim_deg = 1.0\n# hull = "), "vessel.hull_trim_deg: given without vessel.hull"),    (("speed_kn = 6.0", "speed_kn = 6.0\nnav_lights = \"blinking\""), "vessel.nav_lights: .*underway"),
    (("speed_kn = 6.0", "speed_kn = 6.0\ndeck_layout = \"tilted\""), "vessel.deck_layout: .*hatches"),
    (("speed_kn = 6.0", "speed_kn = 6.0\ntopsides_rgb = [10, 20]"), "vessel.topsides_rgb"),
    (("speed_kn = 6.0", "speed_kn = 6.0\ntopsides_rgb = [300, 0, 0]"), "vessel.topsides_rgb: expected colour levels in 0..255"),
])
def test_bad_vessel_sections_are_refused_with_the_key(tmp_path, change, message):
    path = write(tmp_path, SCENARIO.replace(*change))
    if message is None:
        assert load_scenario(path).vessel.hull_path is None
        return
    with pytest.raises(ScenarioError, match=message):
        load_scenario(path)


def test_speed_outside_a_multi_speed_table_is_refused(tmp_path):
    text = SCENARIO.replace(str(ROOT / "rao" / "tanker" / "tanker.4"), str(ROOT / "rao" / "s175" / "input.re1"))
    with pytest.raises(ScenarioError, match="22 kn is outside the RAO table's speeds 0..20 kn"):
        load_scenario(write(tmp_path, text.replace("speed_kn = 6.0", "speed_kn = 22.0")))
