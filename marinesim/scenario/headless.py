"""The headless run of a scenario: what ``marinesim run`` does without a viewer.

Writes, into one folder: ``sea.png`` (spectrum and surface); with a vessel, ``motions.csv``
and its JSON sidecar (as ``marinesim export``), ``motions.png`` and ``rao.png``, and with a hull
and a speed ``wake.png`` (the Kelvin wake, precomputed into the cache for every scenario speed); without one,
``wave_elevation.csv`` (elevation at the origin), its sidecar and ``wave_elevation.png``.
Same scenario and seed: bit-identical tables.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from marinesim.atomic import atomic_path
from marinesim.scenario.export import VARIANCE_FRACTION, build_ocean, export_motions, sha256
from marinesim.scenario.schema import Scenario
from marinesim.sea.plot import plot_sea, plot_series
from marinesim.sea.summary import summary
from marinesim.vessel.plot import plot_motions, plot_rao


def run_headless(scenario: Scenario, out_dir: Path, progress: bool = True) -> dict[str, Path]:
    """Run ``scenario`` without a display; return the files written by name."""
    out_dir.mkdir(parents=True, exist_ok=True)
    files = {"sea_plot": out_dir / "sea.png"}
    with atomic_path(files["sea_plot"]) as temp:
        plot_sea(build_ocean(scenario), temp)
    if scenario.vessel is None:
        return files | _wave_elevation(scenario, out_dir, progress)
    import pandas as pd

    export = export_motions(scenario, out_dir / "motions.csv", progress=progress)
    files |= {"motions": export.table, "sidecar": export.sidecar, "motions_plot": out_dir / "motions.png",
              "rao_plot": out_dir / "rao.png"}
    vessel = scenario.vessel
    with atomic_path(files["motions_plot"]) as temp:
        plot_motions(pd.read_csv(export.table), temp,
                     f"{scenario.name}: {vessel.rao_path.name}, {vessel.speed_kn:.3g} kn, heading "
                     f"{vessel.heading_deg:g} deg, seed {scenario.run.seed}")
    with atomic_path(files["rao_plot"]) as temp:
        plot_rao(vessel.rao, temp, [180.0, 135.0, 90.0, 45.0, 0.0], vessel.speed_m_s)
    if vessel.hull is not None and vessel.wake_speeds_m_s:
        files |= _wakes(scenario, out_dir, progress)
    return files


def _wakes(scenario: Scenario, out_dir: Path, progress: bool) -> dict[str, Path]:
    """Precompute (or read from the cache) the wakes of every scenario speed; draw the one at the vessel's."""
    from marinesim.constants import KNOT
    from marinesim.hull import hydrostatics
    from marinesim.wake.cache import precompute_wakes
    from marinesim.wake.compute import MIN_FROUDE, QUALITATIVE_BELOW_FROUDE, froude_number
    from marinesim.wake.plot import plot_wake

    vessel = scenario.vessel
    length = hydrostatics(vessel.hull).froude_length_m
    speeds = [u for u in vessel.wake_speeds_m_s if froude_number(u, length) >= MIN_FROUDE]
    for skipped in sorted(set(vessel.wake_speeds_m_s) - set(speeds)):
        print(f"no wake at {skipped / KNOT:.3g} kn: Fn {froude_number(skipped, length):.3f} is below {MIN_FROUDE}")
    wakes = precompute_wakes(vessel.hull, speeds, progress=progress)
    froude = froude_number(vessel.speed_m_s, length)
    if froude < QUALITATIVE_BELOW_FROUDE:
        if vessel.speed_m_s > 0:
            print(f"no wake drawn at {vessel.speed_kn:.3g} kn: Fn {froude:.3f} is below {QUALITATIVE_BELOW_FROUDE}, "
                  "where thin-ship theory does not hold for this hull")
        return {}
    wake = next(w for w, _ in wakes if w.info["speed_m_s"] == vessel.speed_m_s)
    path = out_dir / "wake.png"
    with atomic_path(path) as temp:
        plot_wake(wake, temp)
    return {"wake_plot": path}


def _wave_elevation(scenario: Scenario, out_dir: Path, progress: bool) -> dict[str, Path]:
    import pandas as pd
    from tqdm import tqdm

    ocean = build_ocean(scenario)
    files = {"elevation": out_dir / "wave_elevation.csv", "sidecar": out_dir / "wave_elevation.json",
             "elevation_plot": out_dir / "wave_elevation.png"}
    run = scenario.run
    steps = int(round(run.duration_s / run.dt_s)) + 1
    times = np.arange(steps) * run.dt_s
    components = ocean.components(variance_fraction=VARIANCE_FRACTION)
    elevation = np.empty(steps)
    chunk = 1000
    bar = tqdm(total=steps, desc="wave elevation", unit="step", disable=not progress, file=sys.stderr)
    for lo in range(0, steps, chunk):
        hi = min(lo + chunk, steps)
        elevation[lo:hi] = components.elevation(0.0, 0.0, times[lo:hi])
        bar.update(hi - lo)
    bar.close()
    with atomic_path(files["elevation"]) as temp:
        pd.DataFrame({"time_s": times, "wave_elevation_m": elevation}).to_csv(temp, index=False)
    with atomic_path(files["elevation_plot"]) as temp:
        plot_series(times, elevation, "elevation [m]", f"wave elevation at (0, 0), {scenario.name}, seed {run.seed}",
                    temp)
    sidecar = {"scenario": str(scenario.path), "scenario_sha256": sha256(scenario.path), "seed": run.seed,
               "duration_s": run.duration_s, "dt_s": run.dt_s, "point_m": [0.0, 0.0],
               "components": len(components), "variance_fraction": VARIANCE_FRACTION, "sea": summary(ocean)}
    with atomic_path(files["sidecar"]) as temp:
        temp.write_text(json.dumps(sidecar, indent=2) + "\n", encoding="utf-8")
    return files
