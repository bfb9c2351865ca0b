"""Benchmark: an operability study, in the frequency domain and its time-domain check on Dask.

Frequency domain: the shipped crane lift's supply vessel with 8 criteria at 4 points over a 20 Hs x 20 Tp
scatter at 24 headings (``marinesim.study.run.evaluate``). The baseline, timed in the same run, is the bare
matrix product of the same size: the spectral moments' contraction (T, W x D) @ (W x D, series) once per
heading, with the criteria's 14 series.

Time domain: tasks per second of the time-domain check (3 h records of one sea state) on a LocalCluster of
1, 2, ... worker processes (started and warmed up before the clock starts), against the same tasks run
serially in this process; the parallel efficiency rate / (workers x the first count's rate per worker) and a
task's peak memory.
Run: ``python benchmarks/operability.py [--workers 1,2] [--tasks 16] [--repeats 3]``.
"""

from __future__ import annotations

import argparse
import math
import platform
import statistics
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from dask.distributed import LocalCluster

from marinesim.criteria.monitor import Criterion
from marinesim.resources import resource_dir
from marinesim.scenario import load_scenario
from marinesim.study import run
from marinesim.study.distributed import ONE_THREAD, run_tasks
from marinesim.study.scatter import Scatter
from marinesim.study.timedomain import Task, TimeDomainStudy

POINTS = {"crane_tip": (-22.0, -16.0, 20.0), "bridge": (30.0, 0.0, 15.0), "cargo_deck": (-25.0, 0.0, 3.0),
          "bow": (35.0, 0.0, 8.0)}
CRITERIA = (Criterion("vertical_velocity_max_m_s", 1.8, "crane_tip", window_s=120.0),
            Criterion("vertical_acc_rms_m_s2", 0.6, "crane_tip"), Criterion("roll_max_deg", 4.0),
            Criterion("pitch_rms_deg", 2.0), Criterion("lateral_acc_rms_m_s2", 1.0, "bridge"),
            Criterion("vertical_acc_rms_m_s2", 1.0, "bridge"),
            Criterion("relative_motion_exceedance", 0.05, "bow", options=replace(Criterion("heave_rms_m").options,
                                                                                threshold_m=6.0)),
            Criterion("heave_rate_significant_m_s", 1.3, "cargo_deck"))


def study() -> run.Study:
    """The crane lift's vessel with :data:`CRITERIA` over a 20 x 20 scatter at 24 headings."""
    scenario = load_scenario(resource_dir("configs") / "training" / "crane_lift.toml")
    vessel = replace(scenario.vessel, points=POINTS)
    scenario = replace(scenario, vessel=vessel, criteria=CRITERIA)
    hs, tp = np.meshgrid(np.arange(0.5, 10.5, 0.5), np.arange(3.0, 23.0, 1.0), indexing="ij")
    scatter = Scatter(hs.ravel(), tp.ravel(), np.full(hs.size, 1.0 / hs.size), "tp", "20 x 20 uniform")
    system = scenario.sea.spectral_systems[0]
    return run.Study(scenario, scatter, system, scenario.sea.depth, tp.ravel(), np.unique(tp),
                     np.arange(0.0, 360.0, 15.0), 3 * 3600.0)


def frequency_domain(repeats: int) -> None:
    s = study()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run.evaluate(s)
        times.append(time.perf_counter() - start)
    spread = 144
    weight = np.random.default_rng(0).random((s.tp.size, 800 * spread))
    power = np.random.default_rng(1).random((800 * spread, 14))
    base = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in s.headings_deg:
            weight @ power
        base.append(time.perf_counter() - start)
    b, f = statistics.median(base), statistics.median(times)
    print(f"frequency domain: 20 Hs x 20 Tp, 24 headings, {len(CRITERIA)} criteria at 4 points; median of {repeats}")
    print(f"  bare contraction (baseline)  {b:6.3f} s   1.00x")
    print(f"  operability study            {f:6.3f} s   {f / b:5.2f}x")


def time_domain(workers: list[int], tasks: int) -> None:
    s = study()
    td = TimeDomainStudy(s.scenario.vessel.rao, POINTS, 0.0, CRITERIA[:4], s.system, s.depth_m,
                         np.array([3.0]), np.array([10.0]), np.array([180.0]), tuple(range(tasks)), 3 * 3600.0)
    with tempfile.TemporaryDirectory() as folder:
        start = time.perf_counter()
        run_tasks(Task(td), td.tasks, 4, Path(folder) / "serial.zarr", "bench", serial=True)
        serial = td.tasks / (time.perf_counter() - start)
        print(f"time domain: {td.tasks} tasks of a 3 h record (3 x 128^2 ocean, 4 criteria)")
        print(f"  serial (baseline)   {serial:6.2f} tasks/s   {1 / serial:5.2f} s per task (BLAS on every core)")
        one = None
        for count in workers:
            with LocalCluster(n_workers=count, threads_per_worker=1, processes=True, dashboard_address=None,
                              env=ONE_THREAD, silence_logs=40) as cluster:
                address = cluster.scheduler_address
                warm = replace(td, seeds=tuple(range(1000, 1000 + count)))   # workers import and plan first
                run_tasks(Task(warm), warm.tasks, 4, Path(folder) / f"warm{count}.zarr", "warm", scheduler=address)
                start = time.perf_counter()
                run_tasks(Task(td), td.tasks, 4, Path(folder) / f"w{count}.zarr", "bench", scheduler=address)
                rate = td.tasks / (time.perf_counter() - start)
            one = one or rate
            print(f"  {count:2d} worker(s)        {rate:6.2f} tasks/s   efficiency {rate / (count * one):4.2f}")
    print(f"  memory per worker: {_task_memory(td):.0f} MB peak for one task (tracemalloc, this process)")


def _task_memory(td: TimeDomainStudy) -> float:
    import tracemalloc

    tracemalloc.start()
    Task(td)(0)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak / 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--workers", default="1,2")
    parser.add_argument("--tasks", type=int, default=16)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    print(f"{platform.processor() or platform.machine()}, Python {platform.python_version()}")
    frequency_domain(args.repeats)
    time_domain([int(w) for w in args.workers.split(",")], args.tasks)


if __name__ == "__main__":
    main()
