"""Benchmark: what the exercise engine (events, the record on the run's grid, the criteria every
second) costs on top of the bare motion record of the same run.

The shipped exercise (``configs/s175_heavy_weather.toml``: three events, six criteria at three points)
runs as ``marinesim assess`` runs it; the baseline, timed in the same run, is the same scenario's
record without events or criteria, computed as the export computes it. Printed: the median of
``--repeats`` runs of each, the ratio, and the time per simulated hour.
Run: ``python benchmarks/exercise.py [--duration 1800] [--repeats 3]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import platform
import statistics
import time

from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario, with_run
from marinesim.session.exercise import Exercise
from marinesim.session.timeline import Simulation


def timed(scenario, bare: bool) -> float:
    """Seconds to go through ``scenario``'s run (``bare``: its record only, no events or criteria)."""
    if bare:
        scenario = dataclasses.replace(scenario, events=(), criteria=())
    simulation = Simulation(scenario, wake=False)
    simulation.assembly.response  # the response is built before the clock starts, in both
    start = time.perf_counter()
    exercise = Exercise(simulation)
    for _ in exercise.blocks():
        pass
    elapsed = time.perf_counter() - start
    simulation.close()
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--duration", type=float, default=1800.0)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    scenario = with_run(load_scenario(resource_dir("configs") / "s175_heavy_weather.toml"), args.duration)
    times = {"bare record": [], "exercise": []}
    for _ in range(args.repeats):
        times["bare record"].append(timed(scenario, bare=True))
        times["exercise"].append(timed(scenario, bare=False))
    base = statistics.median(times["bare record"])
    print(f"{platform.processor() or platform.machine()}, Python {platform.python_version()}; "
          f"{args.duration:g} s at dt {scenario.run.dt_s:g} s, median of {args.repeats}")
    for name, values in times.items():
        median = statistics.median(values)
        print(f"{name:12s} {median:7.2f} s   {median / base:5.2f}x   {3600.0 * median / args.duration:6.2f} s per "
              "simulated hour")


if __name__ == "__main__":
    main()
