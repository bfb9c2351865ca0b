"""Benchmark: local wave solver sub-steps per second at 256^2, 512^2 and 1024^2.

For each grid size: the GPU solver on whatever OpenGL 4.3 context EGL gives (a real GPU when
there is one, Mesa's llvmpipe otherwise) and the NumPy reference in the same run, both stepping a
Wigley hull (10 m, 1200 triangles) heaving and travelling at 10 m/s (the hull render, five compute
passes and the grid scrolling, every sub-step), in frames of 1/60 s as the viewer calls it (the
cell is 0.25 m, so a frame is 2-3 sub-steps at the 20 m/s design speed). Figures: sub-steps per
second and the GPU / reference ratio; for the GPU also the same without a hull (the wave step alone).

Run: ``python benchmarks/solver.py [--seconds 3] [--sizes 256,512,1024]``.
"""

from __future__ import annotations

import argparse
import math
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from marinesim.gl import standalone_context  # noqa: E402
from marinesim.hull.shapes import wigley_hull  # noqa: E402
from marinesim.pose import Pose  # noqa: E402
from marinesim.solver import ReferenceSolver, SolverConfig  # noqa: E402
from marinesim.solver.gpu import GpuSolver  # noqa: E402


def pose(t: float) -> Pose:
    return Pose(10.0 * t, 0.0, 0.0, (0.0, 0.0, 0.2 * math.sin(1.5 * t), 0.05 * math.sin(t), 0.0, 0.0))


FRAME = 1.0 / 60.0


def rate(solver, seconds: float, with_hull: bool) -> float:
    """Sub-steps per second of wall time, stepping frames of 1/60 s (the GPU work finished)."""
    t = FRAME
    solver.step(FRAME, pose(t) if with_hull else None)   # warm up
    steps, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds or steps < 3:
        t += FRAME
        steps += solver.step(FRAME, pose(t) if with_hull else None)
    if hasattr(solver, "ctx"):
        solver.ctx.finish()
    return steps / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--sizes", default="256,512,1024")
    args = parser.parse_args()
    ctx = standalone_context()
    hull = wigley_hull(10.0, 1.5, 0.8, nx=60, nz=10)
    print(f"machine: {platform.machine()}, {platform.processor() or platform.system()}; "
          f"GL: {ctx.info['GL_RENDERER']} ({ctx.info['GL_VERSION']})")
    print(f"{'grid':>9} {'GPU steps/s':>12} {'no hull':>9} {'NumPy steps/s':>14} {'GPU / NumPy':>12}")
    for size in (int(s) for s in args.sizes.split(",")):
        config = SolverConfig(size=size, cell_m=0.25)
        gpu = GpuSolver(config, hull, pose(0.0), ctx=ctx)
        gpu_rate = rate(gpu, args.seconds, True)
        bare = GpuSolver(config, ctx=ctx)
        bare_rate = rate(bare, args.seconds, False)
        reference_rate = rate(ReferenceSolver(config, hull, pose(0.0)), args.seconds, True)
        print(f"{size:>4}^2    {gpu_rate:>12.1f} {bare_rate:>9.1f} {reference_rate:>14.1f} {gpu_rate / reference_rate:>12.2f}")
        gpu.release()
        bare.release()


if __name__ == "__main__":
    main()
