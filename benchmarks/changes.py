"""Benchmark: what a live sea change costs the viewer's frames, and the memory a session of them keeps.

The default scenario runs at 60 frames/s of simulated time (``Simulation.advance`` and the
ocean's fields, no GL). Every 15 s an instructor's key press changes the sea (Hs x1.1 or /1.1
over 10 s). Printed: the frame time with no blend under way (the baseline, same run), the longest frame
within a second of each key press, the key press itself, and the traced memory after each
change. Run: ``python benchmarks/changes.py [--changes 20]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import tracemalloc
from pathlib import Path

import numpy as np

from marinesim.session.timeline import Simulation
from marinesim.scenario import load_scenario

DEFAULT = Path(__file__).resolve().parents[1] / "configs" / "default.toml"
FRAME_S = 1.0 / 60.0


def frame(sim: Simulation) -> float:
    """One frame's simulation work (s of wall time): advance, the pose, the ocean's fields."""
    start = time.perf_counter()
    sim.advance(FRAME_S)
    sim.pose()
    sim.ocean.fields(sim.time)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--changes", type=int, default=20)
    args = parser.parse_args()
    print(f"machine: {platform.machine()} {os.cpu_count()} cpus, Python {platform.python_version()}, "
          f"numpy {np.__version__}; scenario {DEFAULT.name}")
    scenario = load_scenario(DEFAULT)
    sim = Simulation(scenario, wake=False)
    steady = [frame(sim) for _ in range(300)]
    press, worst = [], []
    for i in range(args.changes):
        start = time.perf_counter()
        sim.change(hs_factor=1.1 if i % 2 == 0 else 1 / 1.1, ramp_s=10.0)
        press.append(time.perf_counter() - start)
        frames = [frame(sim) for _ in range(int(15.0 / FRAME_S))]
        worst.append(max(frames[:60]))
        steady += frames[int(11.0 / FRAME_S):]  # after the blend (0.5 s + 10 s)
    sim.close()
    # memory on its own pass: tracing every allocation would slow the frames timed above
    sim = Simulation(scenario, wake=False)
    tracemalloc.start()
    memory = []
    for i in range(args.changes):
        sim.change(hs_factor=1.1 if i % 2 == 0 else 1 / 1.1, ramp_s=10.0)
        sim.advance(15.0)
        sim.ocean.fields(sim.time)
        memory.append(tracemalloc.get_traced_memory()[0] / 2**20)
    tracemalloc.stop()
    base = float(np.median(steady))
    print(f"frame without a change: {base * 1e3:.2f} ms (median)")
    print(f"key press: {np.median(press) * 1e3:.2f} ms (median), {max(press) * 1e3:.2f} ms (max)")
    print(f"longest frame within 1 s of a change: {np.median(worst) * 1e3:.1f} ms (median), "
          f"{max(worst) * 1e3:.1f} ms (max) = {np.median(worst) / base:.1f} x the frame without")
    print(f"traced memory after change 5: {memory[4]:.1f} MB, after change {args.changes}: {memory[-1]:.1f} MB "
          f"({(memory[-1] - memory[4]) / (args.changes - 5):+.2f} MB per change)")
    sim.close()


if __name__ == "__main__":
    main()
