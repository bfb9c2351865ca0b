"""Scenario schema and validation. Unknown keys and bad values are refused with the key's path.

```toml
[ocean]                      # optional
depth_m = 80.0               # absent = deep water
tiles = 4                    # FFT cascades
resolution = 256             # samples per tile side
choppiness = 1.0

[[sea]]                      # one or more wave systems
type = "jonswap"             # jonswap | pm | tma | regular
hs_m = 3.0                   # jonswap/pm/tma (jonswap also: u10_m_s + fetch_km)
tp_s = 9.0
gamma = 3.3                  # optional: DNV default from Hs, Tp
from_deg = 45.0              # compass, coming from, 0..360
spreading_s = 10.0           # absent = long-crested
spreading = "cos2s"          # cos2s | mitsuyasu | cos2n-halfplane | long-crested
# regular: height_m, period_s, phase_deg

[vessel]                     # optional: without it the scenario is a sea only
rao = "../rao/tanker/tanker.4"  # RAO file, relative to this scenario file
hull = "../hulls/tanker.gdf"    # optional hull mesh (wake, rendering)
hull_units = "m"             # optional: the mesh's length units (m, cm, mm, ft, in)
hull_scale = 1.0             # optional: geometric scale of a model mesh (50 for 1:50)
hull_axes = "x,y,z"          # optional: mesh axes that become body x, y, z (e.g. "x,-z,y")
hull_draft_m = 10.0          # optional: lowest point of the hull at z = -draft (default: mesh z = 0)
hull_trim_deg = 0.0          # optional: trim, bow down positive
wake_speeds_kn = [8.0, 12.0] # optional: more speeds to precompute the Kelvin wake for
visual_mesh = "../hulls/barge_visual.glb"  # optional: drawn instead of the hull (may be open, above water)
visual_mesh_units = "cm"     # optional: as hull_units, hull_scale, hull_axes, for the visual mesh
visual_mesh_scale = 1.0
visual_mesh_axes = "x,-z,y"
visual_mesh_offset_m = [-50.0, 0.0, -5.0]  # optional: the mesh's origin in the body frame, m (after units, axes)
speed_kn = 0.0               # 0..40 kn, within the RAO table's speeds if it has several
heading_deg = 0.0            # compass, where the bow points
ulen_m = 1.0                 # optional: WAMIT length scale (default: from the .gdf beside)
roll_damping_pct = 5.0       # optional: extra roll damping for Capytaine datasets, % of critical

[vessel.points]              # optional named points, body frame m (x fwd, y port, z up)
bridge = [-100.0, 0.0, 30.0]

[run]
duration_s = 600.0
dt_s = 0.1
seed = 1
```
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from marinesim.constants import KNOT
from marinesim.errors import MarinesimError, ScenarioError, require_finite
from marinesim.hull import Hull, VisualMesh, load_hull, load_visual_mesh
from marinesim.sea.build import wave_system
from marinesim.sea.cascades import check_resolution, check_tile_count
from marinesim.sea.seastate import SeaState
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.read import read_rao

SEA_KEYS: dict[str, type] = {
    "type": str, "hs_m": float, "tp_s": float, "gamma": float, "from_deg": float, "spreading": str,
    "spreading_s": float, "height_m": float, "period_s": float, "phase_deg": float, "u10_m_s": float,
    "fetch_km": float,
}
OCEAN_KEYS: dict[str, type] = {"depth_m": float, "tiles": int, "resolution": int, "choppiness": float}
RUN_KEYS: dict[str, type] = {"duration_s": float, "dt_s": float, "seed": int}
VESSEL_KEYS: dict[str, type] = {"rao": str, "hull": str, "speed_kn": float, "heading_deg": float,
                                "ulen_m": float, "roll_damping_pct": float, "points": dict, "hull_units": str,
                                "hull_scale": float, "hull_axes": str, "hull_draft_m": float,
                                "hull_trim_deg": float, "wake_speeds_kn": list, "visual_mesh": str,
                                "visual_mesh_units": str, "visual_mesh_scale": float, "visual_mesh_axes": str,
                                "visual_mesh_offset_m": list}
HULL_OPTIONS = {"hull_units": "units", "hull_scale": "scale", "hull_axes": "axes", "hull_draft_m": "draft",
                "hull_trim_deg": "trim_deg"}  # scenario key -> load_hull option
VISUAL_MESH_OPTIONS = {"visual_mesh_units": "units", "visual_mesh_scale": "scale", "visual_mesh_axes": "axes",
                       "visual_mesh_offset_m": "offset"}  # scenario key -> load_visual_mesh option
SECTIONS = ("ocean", "sea", "vessel", "run")
MAX_SPEED_KN = 40.0
MAX_DURATION_S = 7 * 24 * 3600.0


@dataclass(frozen=True)
class OceanOptions:
    tiles: int = 4
    resolution: int = 256
    choppiness: float = 1.0


@dataclass(frozen=True)
class RunOptions:
    duration_s: float = 600.0
    dt_s: float = 0.1
    seed: int = 0


@dataclass(frozen=True)
class Vessel:
    """The vessel of a scenario: its RAO table (read and checked), hull file, course, points, visual mesh."""

    rao_path: Path
    rao: RaoTable
    hull_path: Path | None
    hull: Hull | None                       # in the body frame, waterline at z = 0
    speed_m_s: float
    heading_deg: float                      # compass, where the bow points
    points: dict[str, tuple[float, float, float]]
    wake_speeds_m_s: tuple[float, ...] = ()  # the vessel's speed (if > 0) and the extra wake speeds
    visual: VisualMesh | None = None        # drawn instead of the hull, body frame

    @property
    def speed_kn(self) -> float:
        return self.speed_m_s / KNOT


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: the sea state, the ocean's options, the vessel (if any), the run."""

    path: Path
    sea: SeaState
    ocean: OceanOptions
    run: RunOptions
    vessel: Vessel | None = None

    @property
    def name(self) -> str:
        return self.path.stem


def load_scenario(path: str | Path) -> Scenario:
    """Read and validate ``path``; raise :class:`ScenarioError` naming the file and the key."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ScenarioError(f"{path}: no such scenario file") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    try:
        return _parse(path, data)
    except ScenarioError as error:
        raise ScenarioError(f"{path}: {error}") from None


def _parse(path: Path, data: dict[str, Any]) -> Scenario:
    _known(data, SECTIONS, "")
    ocean_table = _table(data.get("ocean", {}), "ocean")
    run_table = _table(data.get("run", {}), "run")
    ocean = _typed(ocean_table, OCEAN_KEYS, "ocean")
    run = _typed(run_table, RUN_KEYS, "run")
    depth = ocean.pop("depth_m", math.inf)
    systems_data = data.get("sea")
    if not isinstance(systems_data, list) or not systems_data:
        raise ScenarioError("sea: at least one [[sea]] wave system is required")
    systems = []
    for i, entry in enumerate(systems_data):
        where = f"sea[{i}]"
        values = _typed(_table(entry, where), SEA_KEYS, where)
        for key in ("type", "from_deg"):
            if key not in values:
                raise ScenarioError(f"{where}.{key}: required")
        if not 0.0 <= values["from_deg"] <= 360.0:
            raise ScenarioError(f"{where}.from_deg: must be a compass direction in 0..360, got {values['from_deg']!r}")
        systems.append(_checked(where, lambda v=values: wave_system(
            v["type"], from_deg=v["from_deg"], hs=v.get("hs_m"), tp=v.get("tp_s"), gamma=v.get("gamma"),
            u10=v.get("u10_m_s"), fetch_km=v.get("fetch_km"), height=v.get("height_m"),
            period=v.get("period_s"), phase_deg=v.get("phase_deg", 0.0), spreading=v.get("spreading"),
            spreading_s=v.get("spreading_s"), depth=depth)))
    sea = _checked("ocean.depth_m", lambda: SeaState(tuple(systems), depth=depth))
    options = OceanOptions(**ocean)
    run_options = RunOptions(**run)
    check_run(run_options)
    _checked("ocean", lambda: _check_ocean(options))
    vessel = _vessel(path, _table(data["vessel"], "vessel")) if "vessel" in data else None
    return Scenario(path.resolve(), sea, options, run_options, vessel)


def _vessel(path: Path, table: dict) -> Vessel:
    values = _typed(table, VESSEL_KEYS, "vessel")
    if "rao" not in values:
        raise ScenarioError("vessel.rao: required (the RAO file, relative to the scenario)")
    speed_kn = values.get("speed_kn", 0.0)
    if not 0.0 <= speed_kn <= MAX_SPEED_KN:
        raise ScenarioError(f"vessel.speed_kn: must be in 0..{MAX_SPEED_KN:g} kn, got {speed_kn!r}")
    heading = values.get("heading_deg", 0.0)
    if not 0.0 <= heading <= 360.0:
        raise ScenarioError(f"vessel.heading_deg: must be a compass heading in 0..360, got {heading!r}")
    damping = values.get("roll_damping_pct", 0.0)
    if not 0.0 <= damping < 100.0:
        raise ScenarioError(f"vessel.roll_damping_pct: must be in 0..100 % of critical, got {damping!r}")
    ulen = values.get("ulen_m")
    if ulen is not None and ulen <= 0:
        raise ScenarioError(f"vessel.ulen_m: must be > 0, got {ulen!r}")
    points = {}
    for name, point in values.get("points", {}).items():
        where = f"vessel.points.{name}"
        if not name.isidentifier():
            raise ScenarioError(f"{where}: a point name must be a plain identifier (letters, digits, _)")
        if (not isinstance(point, list) or len(point) != 3 or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in point)):
            raise ScenarioError(f"{where}: expected [x, y, z] in metres (body frame), got {point!r}")
        points[name] = tuple(float(v) for v in point)
    rao_path = (path.parent / values["rao"]).resolve()
    rao = _checked("vessel.rao", lambda: read_rao(rao_path, ulen=ulen, roll_damping=damping / 100.0))
    low, high = rao.speed_range
    speed = speed_kn * KNOT
    if rao.speed.size > 1 and not low - 1e-6 <= speed <= high + 1e-6:
        raise ScenarioError(f"vessel.speed_kn: {speed_kn:g} kn is outside the RAO table's speeds "
                            f"{low / KNOT:.3g}..{high / KNOT:.3g} kn")
    hull_path, hull = _mesh(path, values, "hull", HULL_OPTIONS, load_hull)
    _, visual = _mesh(path, values, "visual_mesh", VISUAL_MESH_OPTIONS, load_visual_mesh)
    extra = values.get("wake_speeds_kn", [])
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and 0.0 < v <= MAX_SPEED_KN for v in extra):
        raise ScenarioError(f"vessel.wake_speeds_kn: expected speeds in 0..{MAX_SPEED_KN:g} kn, got {extra!r}")
    if extra and hull is None:
        raise ScenarioError("vessel.wake_speeds_kn: given without vessel.hull")
    wake_speeds = tuple(sorted({v * KNOT for v in ([speed_kn] if speed_kn > 0 else []) + list(extra)}))
    return Vessel(rao_path, rao, hull_path, hull, speed, heading, points, wake_speeds, visual)


def _mesh(path: Path, values: dict, key: str, options: dict[str, str],
          load: Callable[..., Any]) -> tuple[Path | None, Any]:
    """(file, loaded mesh) for ``vessel.<key>`` (relative to the scenario ``path``) with its option keys
    (scenario key -> ``load`` option), or (None, None) without it; options without the file are refused."""
    given = [name for name in options if name in values]
    if key not in values:
        if given:
            raise ScenarioError(f"vessel.{given[0]}: given without vessel.{key}")
        return None, None
    file = (path.parent / values[key]).resolve()
    return file, _checked(f"vessel.{key}", lambda: load(file, **{options[name]: values[name] for name in given}))


def _known(table: dict, allowed: tuple[str, ...] | dict, where: str) -> None:
    for key in table:
        if key not in allowed:
            at = f"{where}.{key}" if where else key
            raise ScenarioError(f"{at}: unknown key (known: {', '.join(allowed)})")


def _table(value: Any, where: str) -> dict:
    if not isinstance(value, dict):
        raise ScenarioError(f"{where}: must be a table")
    return value


def _typed(table: dict, schema: dict[str, type], where: str) -> dict:
    """The entries of ``table`` checked against ``schema`` (ints accepted as floats, NaN refused)."""
    _known(table, schema, where)
    out = {}
    for key, value in table.items():
        want = schema[key]
        ok = isinstance(value, want) and not isinstance(value, bool)
        if want is float and isinstance(value, int) and not isinstance(value, bool):
            value, ok = float(value), True
        if not ok:
            raise ScenarioError(f"{where}.{key}: expected {want.__name__}, got {value!r}")
        if want is float and math.isnan(value):
            raise ScenarioError(f"{where}.{key}: expected a number, got nan")
        out[key] = value
    return out


def _checked(where: str, build):
    try:
        return build()
    except MarinesimError as error:
        raise ScenarioError(f"{where}: {error}") from None


def check_run(run: RunOptions) -> None:
    """Refuse run options out of range (:class:`ScenarioError` naming the ``run.*`` key)."""
    if not 0.0 < run.duration_s <= MAX_DURATION_S:
        raise ScenarioError(f"run.duration_s: must be in (0, {MAX_DURATION_S:g}] s, got {run.duration_s!r}")
    if not 0.0 < run.dt_s <= run.duration_s:
        raise ScenarioError(f"run.dt_s: must be in (0, duration_s], got {run.dt_s!r}")
    if run.seed < 0:
        raise ScenarioError(f"run.seed: must be >= 0, got {run.seed!r}")


def _check_ocean(options: OceanOptions) -> None:
    check_resolution(options.resolution)
    check_tile_count(options.tiles)
    require_finite("choppiness", options.choppiness)
