"""The vessel's motions over a run, exported: CSV (or Parquet) plus a JSON sidecar.

The rows come from the run as an exercise (:class:`~marinesim.session.exercise.Exercise`): the
scenario's events change the sea, speed and heading as they do in the viewer and in ``assess``.

Columns and sidecar as docs/CONVENTIONS.md ("Time series and files"); the sidecar carries each column's unit and
the conventions needed to read them (:data:`CONVENTIONS`). The table streams to
disk in blocks, so memory stays flat with duration; it and its sidecar are written to temporary
files renamed into place together at the end (:func:`~marinesim.session.sidecar.write_table`), so
an interrupted export leaves the previous pair or the new one, never a partial file or a mix.
Same scenario and seed: byte-identical files (the sidecar holds no clock time).

The sidecar's ``outside_rao_table`` says, per leg of the run, what share of each DOF's response
variance came from wave frequencies below the RAO table (the long-wave model) and above it (the
taper): an RAO table that stops short of the sea's peak is not silently extrapolated.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Iterable

import numpy as np

from marinesim.errors import MarinesimError, ParameterError, require_positive
from marinesim.scenario.model import MAX_ROWS
from marinesim.progress import Bar, task
from marinesim.session.assembly import Assembly
from marinesim.session.exercise import Exercise, last_row, quiet, run_exercise
from marinesim.session.sidecar import column_units, run_sidecar, sha256, write_table
from marinesim.session.timeline import record_columns

FORMATS = ("csv", "parquet")
EXTENSIONS = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}
"""The table format an export file's extension implies."""
CONVENTIONS = {
    "frames": "Earth frame: x east, y north, z up, origin on the mean free surface. Body frame: x forward, y to port, "
              "z up, origin at the RAO reference point (vessel.rao_reference_point_m). A named point's position "
              "(<point>_x_m, _y_m, _z_m) is in the steady vessel frame (the body frame carried along the ship's track "
              "without the wave motions): (surge, sway, heave) + R p, R = Rz(yaw) Ry(pitch) Rx(roll), p its body "
              "position (vessel.points_m).",
    "signs": "surge forward, sway to port, heave up; roll, pitch and yaw right-handed about x, y and z: roll starboard "
             "down, pitch bow down, yaw bow to port; roll_deg includes the heel of a turn. rudder_deg, "
             "rudder_order_deg and rate_of_turn_deg_min are positive to starboard; drift_angle_deg is heading less "
             "course over ground (+ bow to starboard of the track); propeller_rpm is negative astern.",
    "directions": "compass degrees, clockwise from north (0 north, 90 east): heading_deg the bow's (the manoeuvring "
                  "heading less the yaw), course_over_ground_deg, wind_from_deg where the wind comes from.",
    "waves": "wave_elevation_m is the incident wave at the reference point, up from the mean free surface: "
             "Re{a exp(i w t)} summed over the wave components. A motion responds as Re{H a exp(i w t)} with H its "
             "RAO: a positive phase of H is a response leading the wave (WAMIT's convention); <point>_relative_m is "
             "the point's vertical motion less the incident wave elevation at its mean position.",
    "columns": "one row per time step dt_s from time_s 0; north_m, east_m: the manoeuvring model's origin from the "
               "start; course_over_ground_deg, speed_over_ground_kn and drift_angle_deg are the manoeuvring "
               "motion's (the wave-frequency surge and sway have columns of their own). A vessel keeping station: "
               "set_point_offset_m, north_of_set_point_m, east_of_set_point_m her origin from her DP set point "
               "(moored: her start); wind_speed_m_s and wind_from_deg the wind at 10 m she feels (gusts in); "
               "wind_force_x_kn, wind_force_y_kn, wind_moment_knm its load (x forward, y to starboard, the moment "
               "turning the bow to starboard); thruster_<name>_pct each thruster's thrust in % of its rating; "
               "line_<name>_tension_kn each mooring line's fairlead tension.",
}
"""What the columns mean, as the sidecar states it (from docs/CONVENTIONS.md, which the sidecar's reader may not
have)."""
OUTSIDE_TABLE = ("share of each DOF's displacement variance (sum |H a|^2 / 2 over the wave components) from wave "
                 "frequencies below the RAO table (the long-wave model) and above it (the RAO tapered to zero at "
                 "1.5 times its highest frequency), per leg of the run from its start time")
"""What the sidecar's ``outside_rao_table`` holds."""
NOTE_SHARE = 0.01
"""Where some DOF's share from outside the RAO table reaches this, the command line notes the shares."""


@dataclass(frozen=True)
class Export:
    table: Path
    sidecar: Path
    rows: int
    columns: list[str]
    exercise: Exercise
    outside_table: dict
    """The sidecar's ``outside_rao_table`` (:func:`outside_table`)."""


def export_motions(assembly: Assembly, out: Path, file_format: str | None = None,
                   duration_s: float | None = None, log: Callable[[str], None] = quiet) -> Export:
    """Write the motions of the assembled scenario over ``[0, duration_s]`` (default: its run) at the run's
    dt to ``out`` (``file_format`` csv or parquet; default: from the extension, else csv), with its
    sidecar ``<out>.json``, as one unit. Each event that happens is passed to ``log``; the returned
    :class:`Export` holds the exercise run (its events and criteria)."""
    out = Path(out)
    if not out.name or out.name in (".", ".."):
        raise ParameterError(f"the export needs a file name, got {str(out)!r}")
    file_format = table_format(out, file_format)
    scenario = assembly.scenario
    run = scenario.run
    duration = run.duration_s if duration_s is None else require_positive("duration", duration_s)
    steps = last_row(duration, run.dt_s) + 1
    if steps > MAX_ROWS:
        raise ParameterError(f"{duration:g} s at dt {run.dt_s:g} s is {steps:.3g} rows, more than {MAX_ROWS:.0e} "
                             "per export")
    assembly.response  # refuses a scenario without a vessel
    columns = record_columns(scenario)
    coverage: dict = {}
    sidecars: list[Path] = []

    def write_motions(exercise: Exercise) -> None:
        def write(temp: Path) -> None:
            with task(f"export {out.name}", steps) as bar:
                (_write_csv if file_format == "csv" else _write_parquet)(temp, exercise.blocks(), bar)

        def describe() -> dict:
            metadata = {"format": file_format, **motions_sidecar(exercise, steps, duration)}
            coverage.update(metadata["outside_rao_table"])
            return metadata

        sidecars.append(write_table(out, write, describe))

    exercise = run_exercise(scenario, duration_s=duration, log=log, assembly=assembly, drive=write_motions)
    return Export(out, sidecars[0], steps, columns, exercise, coverage)


def motions_sidecar(exercise: Exercise, rows: int, duration_s: float) -> dict:
    """What a motion table's sidecar says after its format: its rows and columns, their units and what they mean,
    the run (:func:`run_sidecar`), the vessel's files (paths made relative by
    :func:`~marinesim.session.sidecar.write_table`) and course, the share of the response from outside the RAO
    table (:func:`outside_table`), the events that happened and the live actions."""
    assembly = exercise.sim.assembly
    scenario = assembly.scenario
    vessel, rao, response = scenario.vessel, scenario.vessel.rao, assembly.response
    columns = record_columns(scenario)
    return {
        "rows": rows,
        "columns": columns,
        "units": column_units(columns),
        "conventions": CONVENTIONS,
        **run_sidecar(assembly, duration_s, scenario.run.dt_s, response.components),
        "vessel": {
            "rao": vessel.rao_path,
            "rao_sha256": sha256(vessel.rao_path),
            "rao_format": rao.source_format,
            "rao_notes": list(rao.notes),
            "rao_reference_point_m": list(rao.reference_point),
            "hull": vessel.hull_path,
            "hull_sha256": sha256(vessel.hull_path) if vessel.hull_path else None,
            "speed_kn": vessel.speed_kn,
            "heading_deg": vessel.heading_deg,
            "points_m": {name: list(p) for name, p in vessel.points.items()},
            "manoeuvring": {"ship": vessel.ship.name, "model": vessel.ship.describe()},
        },
        "outside_rao_table": outside_table(exercise),
        "events": [{"index": h.index, "time_s": h.time_s, "what": h.event.describe()} for h in exercise.happened],
        "actions": [entry for entry in exercise.journal if entry["kind"] == "action"],
    }


def outside_table(exercise: Exercise) -> dict:
    """The RAO table's frequency range (rad/s) and, per leg of the run (``from_s``, s), the share of each
    DOF's response variance from below and above it (:meth:`Response.variance_outside_table`, rounded to
    1e-6) for the leg's sea on the ship's track when it blends in, as :data:`OUTSIDE_TABLE` says."""
    sim = exercise.sim
    rao = sim.vessel.rao
    legs = []
    for leg in sim.legs:
        shares = sim.response_at(leg.after, leg.start + leg.ramp_s).variance_outside_table()
        legs.append({"from_s": leg.start, **{side: {dof: None if share is None else round(share, 6)
                                                    for dof, share in by_dof.items()}
                                             for side, by_dof in shares.items()}})
    return {"what": OUTSIDE_TABLE, "omega_rad_s": [float(rao.omega[0]), float(rao.omega[-1])], "legs": legs}


def outside_table_note(coverage: dict) -> str | None:
    """One line for the console from :func:`outside_table`: per DOF the percentage of its variance from
    below / above the RAO table (the largest over the legs), or None where each is under :data:`NOTE_SHARE`."""
    legs = coverage["legs"]
    largest = {side: {dof: max((leg[side][dof] for leg in legs if leg[side][dof] is not None), default=None)
                      for dof in legs[0][side]} for side in ("below", "above")}
    if all(share is None or share < NOTE_SHARE for by_dof in largest.values() for share in by_dof.values()):
        return None

    def percent(share: float | None) -> str:
        return "-" if share is None else f"{100 * share:.1f}"

    low, high = coverage["omega_rad_s"]
    cells = ", ".join(f"{dof} {percent(largest['below'][dof])}/{percent(largest['above'][dof])}"
                      for dof in largest["below"])
    over = f"; the largest over {len(legs)} legs" if len(legs) > 1 else ""
    return (f"note: response variance from wave frequencies outside the RAO table's {low:.4g}..{high:.4g} rad/s "
            f"(below: long-wave model, above: tapered), % below/above{over}: {cells}")


def table_format(path: Path, file_format: str | None) -> str:
    """The table format of ``path``: ``file_format`` if given (it must agree with a .csv or .parquet
    extension), else the extension's, else csv."""
    by_extension = EXTENSIONS.get(path.suffix.lower())
    if file_format is None:
        return by_extension or "csv"
    if file_format not in FORMATS:
        raise ParameterError(f"unknown export format {file_format!r} (known: {', '.join(FORMATS)})")
    if by_extension is not None and by_extension != file_format:
        raise ParameterError(f"--format {file_format} does not fit {path.name}: give a .{file_format} file "
                             f"or --format {by_extension}")
    return file_format


def write_csv_block(handle: IO[str], block: dict[str, np.ndarray], header: bool) -> None:
    """Motion rows (columns as :func:`~marinesim.session.timeline.record_columns`) to an open text file."""
    import pandas as pd

    pd.DataFrame(block).to_csv(handle, index=False, header=header, lineterminator="\n")


def _write_csv(path: Path, blocks: Iterable[dict[str, np.ndarray]], bar: Bar) -> None:
    with path.open("w", encoding="utf-8", newline="") as handle:
        for i, block in enumerate(blocks):
            write_csv_block(handle, block, header=(i == 0))
            bar.update(len(block["time_s"]))


def _write_parquet(path: Path, blocks: Iterable[dict[str, np.ndarray]], bar: Bar) -> None:
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
