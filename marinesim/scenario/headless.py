"""The headless run of a scenario: what ``marinesim run`` does without a viewer.

Writes, into one folder: ``sea.png`` (spectrum and surface), ``wave_elevation.csv`` (elevation at
the origin, where the vessel's reference point will sit), its JSON sidecar (scenario, seed,
versions, the sea state's summary) and ``wave_elevation.png``. Same scenario and seed: bit-identical files.
"""

from __future__ import annotations

import hashlib
import json
import platform
import sys
from pathlib import Path

import numpy as np

from marinesim import __version__
from marinesim.atomic import atomic_path
from marinesim.scenario.schema import Scenario
from marinesim.sea.ocean import Ocean
from marinesim.sea.plot import plot_sea, plot_series
from marinesim.sea.summary import summary

VARIANCE_FRACTION = 0.999
"""Share of the variance the time series' components carry (the rest are tiny ripples)."""


def build_ocean(scenario: Scenario) -> Ocean:
    o = scenario.ocean
    return Ocean(scenario.sea, tile_count=o.tiles, resolution=o.resolution, seed=scenario.run.seed,
                 choppiness=o.choppiness)


def run_headless(scenario: Scenario, out_dir: Path, progress: bool = True) -> dict[str, Path]:
    """Run ``scenario`` without a display; return the files written by name."""
    import pandas as pd
    from tqdm import tqdm

    out_dir.mkdir(parents=True, exist_ok=True)
    ocean = build_ocean(scenario)
    files = {"plot": out_dir / "sea.png", "csv": out_dir / "wave_elevation.csv",
             "sidecar": out_dir / "wave_elevation.json", "series_plot": out_dir / "wave_elevation.png"}
    with atomic_path(files["plot"]) as temp:
        plot_sea(ocean, temp)
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
    with atomic_path(files["csv"]) as temp:
        pd.DataFrame({"time_s": times, "wave_elevation_m": elevation}).to_csv(temp, index=False)
    with atomic_path(files["series_plot"]) as temp:
        plot_series(times, elevation, "elevation [m]", f"wave elevation at (0, 0), {scenario.name}, seed {run.seed}",
                    temp)
    sidecar = {
        "scenario": str(scenario.path),
        "scenario_sha256": hashlib.sha256(scenario.path.read_bytes()).hexdigest(),
        "seed": run.seed,
        "duration_s": run.duration_s,
        "dt_s": run.dt_s,
        "point_m": [0.0, 0.0],
        "components": len(components),
        "variance_fraction": VARIANCE_FRACTION,
        "versions": {"marinesim": __version__, "numpy": np.__version__, "python": platform.python_version()},
        "sea": summary(ocean),
    }
    with atomic_path(files["sidecar"]) as temp:
        temp.write_text(json.dumps(sidecar, indent=2) + "\n", encoding="utf-8")
    return files
