"""Benchmark: vessel response for one hour at 20 Hz, and the memory of long streaming exports.

1. The default scenario's components (99.9 % of the elevation variance), 72,000 steps, 6 DOF
   displacement/velocity/acceleration + 3 points + wave elevations: seconds for the linear
   outputs and for the full frames (with point kinematics), and the ratio to the floor, a bare
   NumPy float64 product of the same size ``(72000 x 2n) @ (2n x columns)`` timed in the same
   run (as 141 products of 512-row blocks: the whole left matrix would be 13 GB).
2. Peak resident memory of ``marinesim export`` (CSV) in a fresh process for exports of
   increasing duration at 10 Hz: flat with duration means the export streams.

Run: ``python benchmarks/response.py [--export-hours 1 24]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from marinesim.scenario import load_scenario  # noqa: E402
from marinesim.session.assembly import Assembly  # noqa: E402

EXPORT = """
import resource, sys, time
from marinesim.scenario import load_scenario, with_run
from marinesim.session.assembly import Assembly
from marinesim.session.export import export_motions
scenario = with_run(load_scenario(sys.argv[1]), duration=float(sys.argv[2]), dt=0.1)
start = time.perf_counter()
export_motions(Assembly(scenario), sys.argv[3])
print(time.perf_counter() - start, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
"""


def best_of(function, repeats: int = 3) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--export-hours", type=float, nargs="*", default=[1.0, 24.0])
    args = parser.parse_args()
    exports = [export_memory(hours) for hours in args.export_hours]  # before this process grows
    scenario = load_scenario(ROOT / "configs" / "default.toml")
    response = Assembly(scenario).response
    steps, dt = 72_000, 0.05
    n, columns = len(response.components), response.linear([0.0]).shape[1]

    def linear():
        for _ in response.linear_steps(0.0, dt, steps):
            pass

    def frames():
        for _ in response.frames(0.0, dt, steps):
            pass

    rows = 512
    a = np.random.default_rng(0).random((rows, 2 * n))
    b = np.random.default_rng(1).random((2 * n, columns))
    floor = best_of(lambda: [a @ b for _ in range(-(-steps // rows))])
    del a, b
    t_linear, t_frames = best_of(linear), best_of(frames)
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    print(f"one hour at 20 Hz: {steps} steps, {n} components, {columns} linear columns "
          f"(6 DOF x disp/vel/acc, elevation at the reference and at {len(response.points)} points)")
    print(f"  bare float64 product (floor): {floor:.2f} s")
    print(f"  linear outputs:               {t_linear:.2f} s   ratio {t_linear / floor:.2f}")
    print(f"  full frames (with points):    {t_frames:.2f} s   ratio {t_frames / floor:.2f}")
    for line in exports:
        print(line)


def export_memory(hours: float) -> str:
    """Export ``hours`` of the default scenario at 10 Hz in a fresh process; report its peak memory."""
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "m.csv"
        result = subprocess.run([sys.executable, "-c", EXPORT, str(ROOT / "configs" / "default.toml"),
                                 str(hours * 3600.0), str(out)], capture_output=True, text=True, check=True, cwd=ROOT)
        seconds, peak_mb = (float(v) for v in result.stdout.split())
        return (f"export {hours:g} h at 10 Hz: {int(hours * 36000) + 1} rows, {out.stat().st_size / 1e6:.0f} MB "
                f"CSV in {seconds:.1f} s, peak memory {peak_mb:.0f} MB")


if __name__ == "__main__":
    main()
