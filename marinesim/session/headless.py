"""The headless run of a scenario: what ``marinesim run`` writes without a viewer.

Into one folder: ``sea.png`` (spectrum and surface); with a vessel, ``motions.csv`` and its JSON
sidecar ``motions.csv.json`` (as ``marinesim export``), ``motions.png`` and ``rao.png``, and with a hull at a speed
where thin-ship theory holds for it ``wake.png`` (the Kelvin wake at her speed, from the cache or computed into it;
no wake is computed that would not be drawn); without a vessel, ``wave_elevation.csv`` (elevation at the origin),
its sidecar ``wave_elevation.csv.json`` and ``wave_elevation.png``. An exercise (a scenario with criteria or events)
also gets ``assessment.json``, what ``marinesim assess --json`` prints, and its session log ``session.jsonl``, which
``marinesim replay`` and ``marinesim report`` read as they read a viewer's; its events change the run as in the
viewer.
Same scenario and seed: bit-identical tables. The ocean is built once, for all of them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path, json_text
from marinesim.progress import task
from marinesim.sea.plot import plot_sea, plot_series
from marinesim.session.assembly import Assembly
from marinesim.session.exercise import last_row, quiet
from marinesim.session.export import export_motions
from marinesim.session.log import write_log
from marinesim.session.sidecar import column_units, run_sidecar, write_table
from marinesim.vessel.plot import plot_motions, plot_rao

ELEVATION_CHUNK = 1000
"""Time steps of the wave elevation computed at once."""


@dataclass
class Headless:
    """What a headless run wrote (by name: sea_plot, motions, sidecar, ...) and what it has to say."""

    files: dict[str, Path] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def run_headless(assembly: Assembly, out_dir: Path, log: Callable[[str], None] = quiet) -> Headless:
    """Run the assembled scenario without a display into ``out_dir`` (made if missing); each event that
    happens is passed to ``log``."""
    out_dir.mkdir(parents=True, exist_ok=True)
    scenario = assembly.scenario
    result = Headless({"sea_plot": out_dir / "sea.png"})
    with atomic_path(result.files["sea_plot"]) as temp:
        plot_sea(assembly.ocean, temp)
    if scenario.vessel is None:
        result.files |= _wave_elevation(assembly, out_dir)
        return result
    import pandas as pd

    export = export_motions(assembly, out_dir / "motions.csv", log=log)
    result.files |= {"motions": export.table, "sidecar": export.sidecar, "motions_plot": out_dir / "motions.png",
                     "rao_plot": out_dir / "rao.png"}
    if scenario.criteria:
        result.files["assessment"] = out_dir / "assessment.json"
        with atomic_path(result.files["assessment"]) as temp:
            temp.write_text(json_text(export.exercise.assessment().as_dict()), encoding="utf-8")
    if scenario.criteria or scenario.events:
        export.exercise.note("end")  # the session ran to its end: a log without this entry reads as cut short
        result.files["session_log"] = write_log(out_dir / "session.jsonl", export.exercise)
    vessel = scenario.vessel
    with atomic_path(result.files["motions_plot"]) as temp:
        plot_motions(pd.read_csv(export.table), temp,
                     f"{scenario.name}: {vessel.rao_path.name}, {vessel.speed_kn:.3g} kn, heading "
                     f"{vessel.heading_deg:g} deg, seed {scenario.run.seed}")
    with atomic_path(result.files["rao_plot"]) as temp:
        plot_rao(vessel.rao, temp, [180.0, 135.0, 90.0, 45.0, 0.0], vessel.speed_m_s)
    if vessel.hull is not None:
        _wake(assembly, out_dir, result)
    return result


def _wake(assembly: Assembly, out_dir: Path, result: Headless) -> None:
    """Draw the Kelvin wake at the vessel's speed (read from the cache, or computed into it) where thin-ship theory
    holds for her hull; below that speed none is computed, and a note says why."""
    from marinesim.wake.cache import cached_wake
    from marinesim.wake.compute import QUALITATIVE_BELOW_FROUDE
    from marinesim.wake.plot import plot_wake

    vessel = assembly.scenario.vessel
    froude = assembly.hydrostatics.froude(vessel.speed_m_s)
    if froude < QUALITATIVE_BELOW_FROUDE:
        if vessel.speed_m_s > 0:
            result.notes.append(f"no wake drawn at {vessel.speed_kn:.3g} kn: Fn {froude:.3f} is below "
                                f"{QUALITATIVE_BELOW_FROUDE}, where thin-ship theory does not hold for this hull")
        return
    wake, _ = cached_wake(vessel.hull, vessel.speed_m_s)
    path = out_dir / "wake.png"
    with atomic_path(path) as temp:
        plot_wake(wake, temp)
    result.files["wake_plot"] = path


def _wave_elevation(assembly: Assembly, out_dir: Path) -> dict[str, Path]:
    """The incident wave elevation at (0, 0) over the run (m), its sidecar and its plot."""
    import pandas as pd

    files = {"elevation": out_dir / "wave_elevation.csv", "elevation_plot": out_dir / "wave_elevation.png"}
    scenario, run = assembly.scenario, assembly.scenario.run
    steps = last_row(run.duration_s, run.dt_s) + 1
    times = np.arange(steps) * run.dt_s
    components = assembly.components()
    elevation = np.empty(steps)
    with task("wave elevation", steps) as bar:
        for lo in range(0, steps, ELEVATION_CHUNK):
            hi = min(lo + ELEVATION_CHUNK, steps)
            elevation[lo:hi] = components.elevation(0.0, 0.0, times[lo:hi])
            bar.update(hi - lo)
    files["sidecar"] = write_table(
        files["elevation"],
        lambda temp: pd.DataFrame({"time_s": times, "wave_elevation_m": elevation}).to_csv(temp, index=False),
        lambda: run_sidecar(assembly, run.duration_s, run.dt_s, components)
        | {"point_m": [0.0, 0.0], "units": column_units(["time_s", "wave_elevation_m"])})
    with atomic_path(files["elevation_plot"]) as temp:
        plot_series(times, elevation, "elevation [m]", f"wave elevation at (0, 0), {scenario.name}, seed {run.seed}",
                    temp)
    return files
