"""Loading a scenario file: the TOML validated by :mod:`marinesim.scenario.model`, then the sea, the
vessel (RAO table, meshes) and the run built from it. Errors name the file and the key's path."""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable
import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from marinesim import formats
from marinesim.constants import KNOT
from marinesim.errors import FileFormatError, MarinesimError, ScenarioError
from marinesim.hull import Hull, VisualMesh, load_hull, load_visual_mesh
from marinesim.scenario.model import (HULL_OPTIONS, VISUAL_MESH_OPTIONS, WAVE_PARAMETERS, OceanOptions, RunOptions,
                                      ScenarioFile, VesselOptions, validate)
from marinesim.sea.build import wave_system
from marinesim.sea.seastate import SeaState
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.read import read_rao


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
        formats.check_file(path, "scenario file")
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))  # a byte-order mark is no TOML error
    except FileFormatError as error:
        raise ScenarioError(str(error)) from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ScenarioError(f"{path}: not valid TOML: {error}") from None
    except RecursionError:  # tomllib reads nested arrays and tables recursively
        raise ScenarioError(f"{path}: not valid TOML: arrays or tables nested too deeply") from None
    try:
        return _build(path, validate(ScenarioFile, data))
    except ScenarioError as error:
        raise ScenarioError(f"{path}: {error}") from None


def with_run(scenario: Scenario, duration: float | None = None, dt: float | None = None,
             seed: int | None = None) -> Scenario:
    """``scenario`` with its run options (s, s, -) overridden, validated as in the scenario file."""
    given = {"duration_s": duration, "dt_s": dt, "seed": seed}
    run = validate(RunOptions, scenario.run.model_dump() | {k: v for k, v in given.items() if v is not None}, "run")
    return dataclasses.replace(scenario, run=run)


def _build(path: Path, file: ScenarioFile) -> Scenario:
    depth = math.inf if file.ocean.depth_m is None else file.ocean.depth_m
    systems = [_checked(f"sea[{i}]", lambda s=s: wave_system(
        s.type, from_deg=s.from_deg, depth=depth,
        **{WAVE_PARAMETERS[key]: getattr(s, key) for key in s.model_fields_set if key in WAVE_PARAMETERS}))
        for i, s in enumerate(file.sea)]
    sea = _checked("ocean.depth_m", lambda: SeaState(tuple(systems), depth=depth))
    vessel = None if file.vessel is None else _vessel(path, file.vessel)
    if vessel is not None and vessel.hull is not None:
        draft = -float(vessel.hull.vertices[:, 2].min())
        if depth <= draft:
            raise ScenarioError(f"ocean.depth_m: {depth:g} m is not deeper than the hull's draft ({draft:.4g} m, "
                                "vessel.hull): the keel would be on the sea bed")
    return Scenario(path.resolve(), sea, file.ocean, file.run, vessel)


def _vessel(path: Path, options: VesselOptions) -> Vessel:
    rao_path = _checked("vessel.rao", lambda: _file(path, options.rao))
    rao = _checked("vessel.rao", lambda: read_rao(rao_path, ulen=options.ulen_m,
                                                   roll_damping=options.roll_damping_pct / 100.0))
    low, high = rao.speed_range
    speed = options.speed_kn * KNOT
    if rao.speed.size > 1 and not low - 1e-6 <= speed <= high + 1e-6:
        raise ScenarioError(f"vessel.speed_kn: {options.speed_kn:g} kn is outside the RAO table's speeds "
                            f"{low / KNOT:.3g}..{high / KNOT:.3g} kn")
    hull_path, hull = _mesh(path, options, "hull", HULL_OPTIONS, load_hull)
    _, visual = _mesh(path, options, "visual_mesh", VISUAL_MESH_OPTIONS, load_visual_mesh)
    speeds_kn = ([options.speed_kn] if options.speed_kn > 0 else []) + options.wake_speeds_kn
    wake_speeds = tuple(sorted({v * KNOT for v in speeds_kn}))
    points = {name: (p[0], p[1], p[2]) for name, p in options.points.items()}
    return Vessel(rao_path, rao, hull_path, hull, speed, options.heading_deg, points, wake_speeds, visual)


def _mesh(path: Path, options: VesselOptions, key: str, names: dict[str, str],
          load: Callable[..., Any]) -> tuple[Path | None, Any]:
    """(file, loaded mesh) for ``vessel.<key>`` (relative to the scenario ``path``) with its options
    (scenario key -> ``load`` option), or (None, None) without it."""
    if getattr(options, key) is None:
        return None, None
    file = _checked(f"vessel.{key}", lambda: _file(path, getattr(options, key)))
    return file, _checked(f"vessel.{key}", lambda: load(file, **{names[n]: getattr(options, n) for n in names}))


def _file(scenario: Path, name: str) -> Path:
    """The file ``name`` (relative to the ``scenario`` file's folder), resolved once it is known to be a
    regular file (:func:`~marinesim.formats.check_file`)."""
    file = scenario.parent / name
    formats.check_file(file)
    return file.resolve()


def _checked(where: str, build: Callable[[], Any]) -> Any:
    try:
        return build()
    except MarinesimError as error:
        raise ScenarioError(f"{where}: {error}") from None
