"""The vessel's motions for a scenario, and their export: CSV (or Parquet) plus a JSON sidecar.

Columns and sidecar as docs/CONVENTIONS.md ("Time series and files"). The table streams to
disk in blocks, so memory stays flat with duration; it is written to a temporary file renamed
into place at the end, so an interrupted export leaves no partial file. Same scenario and seed:
byte-identical files (the sidecar holds no clock time).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import platform
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim import __version__
from marinesim.angles import compass_to_math
from marinesim.atomic import atomic_path
from marinesim.errors import MarinesimError, ParameterError, ScenarioError
from marinesim.scenario.schema import Scenario, with_run_options
from marinesim.sea.ocean import Ocean
from marinesim.sea.summary import summary
from marinesim.vessel.response import Response, Track

VARIANCE_FRACTION = 0.999
"""Share of the elevation variance the vessel's wave components carry (the rest: short ripples
that move no ship). The viewer and the export use the same selection."""
FORMATS = ("csv", "parquet")


def build_ocean(scenario: Scenario) -> Ocean:
    o = scenario.ocean
    return Ocean(scenario.sea, tile_count=o.tiles, resolution=o.resolution, seed=scenario.run.seed,
                 choppiness=o.choppiness)


def build_response(scenario: Scenario, ocean: Ocean | None = None) -> Response:
    """The vessel's response in the scenario's sea: reference point starting at the origin."""
    vessel = scenario.vessel
    if vessel is None:
        raise ScenarioError(f"{scenario.path}: no [vessel] section: nothing to move")
    ocean = ocean or build_ocean(scenario)
    track = Track(heading=compass_to_math(vessel.heading_deg), speed=vessel.speed_m_s)
    return Response(vessel.rao, ocean.components(variance_fraction=VARIANCE_FRACTION), track, vessel.points)


def with_run(scenario: Scenario, duration: float | None = None, dt: float | None = None,
             seed: int | None = None) -> Scenario:
    """``scenario`` with its run options (s, s, -) overridden, validated as in the scenario file."""
    given = {"duration_s": duration, "dt_s": dt, "seed": seed}
    run = with_run_options(scenario.run, **{key: value for key, value in given.items() if value is not None})
    return dataclasses.replace(scenario, run=run)


@dataclass(frozen=True)
class Export:
    table: Path
    sidecar: Path
    rows: int
    columns: list[str]


def export_motions(scenario: Scenario, out: Path, file_format: str = "csv", progress: bool = True) -> Export:
    """Write the motions of ``scenario`` over its run to ``out`` (+ ``out.json`` sidecar)."""
    from tqdm import tqdm

    if file_format not in FORMATS:
        raise ParameterError(f"unknown export format {file_format!r} (known: {', '.join(FORMATS)})")
    out = Path(out)
    sidecar = out.with_suffix(".json")
    if sidecar == out:
        raise ParameterError(f"the export file needs an extension other than .json: {out}")
    ocean = build_ocean(scenario)
    response = build_response(scenario, ocean)
    run = scenario.run
    steps = int(round(run.duration_s / run.dt_s)) + 1
    bar = tqdm(total=steps, desc=f"export {out.name}", unit="step", disable=not progress, file=sys.stderr,
               mininterval=0.5)
    blocks = response.frames(0.0, run.dt_s, steps)
    with atomic_path(out) as temp:
        if file_format == "csv":
            _write_csv(temp, blocks, bar)
        else:
            _write_parquet(temp, blocks, bar)
    bar.close()
    with atomic_path(sidecar) as temp:
        temp.write_text(json.dumps(_sidecar(scenario, ocean, response, out, steps, file_format), indent=2) + "\n",
                        encoding="utf-8")
    return Export(out, sidecar, steps, response.columns)


def write_csv_block(handle, block: dict[str, np.ndarray], header: bool) -> None:
    """Motion rows (columns as :func:`~marinesim.vessel.response.motion_columns`) to an open text file."""
    import pandas as pd

    pd.DataFrame(block).to_csv(handle, index=False, header=header, lineterminator="\n")


def _write_csv(path: Path, blocks, bar) -> None:
    with path.open("w", encoding="utf-8", newline="") as handle:
        for i, block in enumerate(blocks):
            write_csv_block(handle, block, header=(i == 0))
            bar.update(len(block["time_s"]))


def _write_parquet(path: Path, blocks, bar) -> None:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise MarinesimError("Parquet export needs pyarrow: pip install 'marinesim[parquet]'") from None
    writer = None
    try:
        for block in blocks:
            table = pa.table(block)
            if writer is None:
                writer = pq.ParquetWriter(path, table.schema)
            writer.write_table(table)
            bar.update(len(block["time_s"]))
    finally:
        if writer is not None:
            writer.close()


def sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for chunk in iter(lambda: handle.read(1 << 20), b""):
            digest.update(chunk)
    return digest.hexdigest()


def _sidecar(scenario: Scenario, ocean: Ocean, response: Response, out: Path, steps: int, file_format: str) -> dict:
    vessel, run, rao = scenario.vessel, scenario.run, scenario.vessel.rao
    return {
        "file": out.name,
        "format": file_format,
        "rows": steps,
        "columns": response.columns,
        "conventions": ("body frame x forward, y port, z up, origin at the RAO reference point; "
                        "roll/pitch/yaw positive about x/y/z (pitch bow down, yaw bow to port), degrees; "
                        "points: position in the steady vessel frame, R = Rz(yaw) Ry(pitch) Rx(roll); "
                        "<point>_relative_m = point's vertical motion minus the incident wave elevation there; "
                        "wave_elevation_m: incident wave at the reference point (docs/CONVENTIONS.md)"),
        "scenario": str(scenario.path),
        "scenario_sha256": sha256(scenario.path),
        "seed": run.seed,
        "duration_s": run.duration_s,
        "dt_s": run.dt_s,
        "vessel": {
            "rao": str(vessel.rao_path),
            "rao_sha256": sha256(vessel.rao_path),
            "rao_format": rao.source_format,
            "rao_notes": list(rao.notes),
            "rao_reference_point_m": list(rao.reference_point),
            "hull": str(vessel.hull_path) if vessel.hull_path else None,
            "hull_sha256": sha256(vessel.hull_path) if vessel.hull_path else None,
            "speed_kn": vessel.speed_kn,
            "heading_deg": vessel.heading_deg,
            "points_m": {name: list(p) for name, p in vessel.points.items()},
        },
        "components": len(response.components),
        "variance_fraction": VARIANCE_FRACTION,
        "sea": summary(ocean),
        "versions": {"marinesim": __version__, "numpy": np.__version__, "python": platform.python_version()},
    }
