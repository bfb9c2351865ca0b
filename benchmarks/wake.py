"""Benchmark: the Kelvin wake of the WAMIT tanker at 15 kn on a 1024 x 2048 field.

1. Seconds for A(theta) (Michell resistance quadrature plus the samples the field interpolates)
   and for the field, best of ``--repeats``; the whole ``compute_wake`` call, Kelvin-angle and
   wavelength measurement included.
2. Speed-up over direct summation of the same quadrature: the direct sum is timed on a sub-grid
   in the same run and extrapolated to the full grid (it is exactly linear in the points); the
   largest difference between the two on that sub-grid, in % of the field's peak.
3. Peak resident memory of a fresh process computing the wake of a ~100k-triangle hull (a fine
   Wigley mesh) on the same grid size, against the 1 GB budget.

Run: ``python benchmarks/wake.py [--repeats 3]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from marinesim.constants import KNOT  # noqa: E402
from marinesim.hull import load_hull  # noqa: E402
from marinesim.wake.amplitude import wavenumber  # noqa: E402
from marinesim.wake.compute import WakeGrid, compute_wake  # noqa: E402
from marinesim.wake.field import wake_spectrum  # noqa: E402

LARGE_HULL = """
import resource, sys, time
from marinesim.hull import wigley_hull
from marinesim.wake.compute import WakeGrid, compute_wake
hull = wigley_hull(100.0, 10.0, 6.25, nx=300, nz=60)
start = time.perf_counter()
wake = compute_wake(hull, 15 * 0.514444, WakeGrid(2048, 1024))
print(len(hull.faces), time.perf_counter() - start, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"python {platform.python_version()}, numpy {np.__version__}")

    hull = load_hull(ROOT / "hulls" / "tanker.gdf")
    speed = 15 * KNOT
    grid = WakeGrid(2048, 1024)
    runs = []
    for _ in range(args.repeats):
        start = time.perf_counter()
        wake = compute_wake(hull, speed, grid)
        runs.append((wake.timings["amplitude"], wake.timings["field"], time.perf_counter() - start))
    amp, field, total = min(runs, key=lambda r: r[2])
    info = wake.info
    print(f"tanker {len(hull.faces):,} triangles, 15 kn (Fn {info['froude']:.3f}), field {grid.ny} x {grid.nx} at "
          f"{info['grid']['spacing_m']:.2f} m, {info['quadrature_nodes']:,} angular nodes")
    print(f"  A(theta) + resistance {amp:.2f} s, field {field:.2f} s, whole call {total:.2f} s "
          f"(best of {args.repeats}); R = {info['wave_resistance_N'] / 1e3:,.0f} kN, "
          f"Kelvin half-angle {info['kelvin_half_angle_deg']:.2f} deg")

    k0 = wavenumber(speed)
    x, y = wake.x, wake.y
    spectrum = wake_spectrum(hull.wetted(), k0, float(np.abs(x).max()), float(np.abs(y).max()),
                             info["grid"]["spacing_m"])
    start = time.perf_counter()
    on_grid = spectrum.on_grid(x, y)
    fft_seconds = time.perf_counter() - start
    columns, rows = slice(7, None, 64), slice(3, None, 32)
    X, Y = np.meshgrid(x[columns], y[rows])
    start = time.perf_counter()
    direct = spectrum.direct(X, Y)
    direct_seconds = (time.perf_counter() - start) * x.size * y.size / X.size
    error = np.abs(direct - on_grid[rows, columns]).max() / np.abs(on_grid).max()
    print(f"  field by NUFFT {fft_seconds:.2f} s; direct summation {direct_seconds:.0f} s extrapolated from "
          f"{X.size} points: speed-up {direct_seconds / fft_seconds:,.0f}x; largest difference "
          f"{100 * error:.1e} % of the peak")

    out = subprocess.run([sys.executable, "-c", LARGE_HULL], capture_output=True, text=True, check=True, cwd=ROOT)
    triangles, seconds, peak_mb = out.stdout.split()
    print(f"Wigley with {int(triangles):,} triangles, 15 kn, 1024 x 2048: {float(seconds):.1f} s, "
          f"peak resident memory {float(peak_mb):.0f} MB (budget 1024 MB)")


if __name__ == "__main__":
    main()
