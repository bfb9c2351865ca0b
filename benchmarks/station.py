"""Benchmark: a vessel keeping station.

1. The DP vessel's share of a 60 Hz frame: the supply vessel on DP in configs/supply_dp.toml's weather (gusts,
   current, the DP computer, the measured wave motion), the clock moving 1/60 s a frame (a 0.1 s step every sixth
   frame), against the KVLCC2's manoeuvring in a hard-over turn timed in the same run (the per-frame figure own-ship
   dynamics were held to).
2. Thirty minutes at 10 Hz of configs/supply_dp.toml exported (the record with the station's columns), against the
   same scenario with the vessel held exactly on station (``[station]`` left out: no DP, no weather loads) in the
   same run.
3. ``--exercises``: each training exercise on DP run through ``assess`` as the test of its scripted outcome runs it
   (seed 5, the crane's load left out), against the same exercise with its vessel held exactly on station, in the
   same run.

Run: ``python benchmarks/station.py [--exercises]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from manoeuvring import frames  # noqa: E402  (benchmarks/manoeuvring.py, beside this one)
from marinesim.manoeuvring.station import StationKeeping  # noqa: E402
from marinesim.criteria.quantities import CRANE_QUANTITIES, STATION_QUANTITIES  # noqa: E402
from marinesim.scenario import load_scenario, with_run  # noqa: E402
from marinesim.session.exercise import run_exercise  # noqa: E402
from marinesim.session.timeline import Simulation  # noqa: E402
from response import best_of  # noqa: E402

SCENARIO = ROOT / "configs" / "supply_dp.toml"
EXERCISES = ("crane_lift", "helideck_landing", "offshore_loading")


def dp_frames(seconds: float = 600.0) -> float:
    """Mean seconds of the DP vessel per 60 Hz frame over ``seconds`` of the shipped DP exercise's weather."""
    sim = Simulation(load_scenario(SCENARIO), wake=False)
    count = round(seconds * 60)
    start = time.perf_counter()
    for k in range(1, count + 1):
        t = k / 60.0
        sim.voyage.state(t)
        sim.voyage.path(np.array([t]))
    sim.close()
    return (time.perf_counter() - start) / count


def held_exactly(scenario):
    """``scenario`` with its vessel held exactly on station: no ``[station]``, no DP, no weather loads."""
    return dataclasses.replace(scenario, station=None,
                               vessel=dataclasses.replace(scenario.vessel, ship=StationKeeping("the vessel")))


def exercises() -> None:
    """Seconds of each DP exercise's assessed run, on DP and held exactly."""
    for name in EXERCISES:
        scenario = load_scenario(ROOT / "configs" / "training" / f"{name}.toml")
        scenario = with_run(dataclasses.replace(scenario, lifting=None, criteria=tuple(
            c for c in scenario.criteria if c.quantity not in CRANE_QUANTITIES)), None, seed=5)
        times = {}
        held = dataclasses.replace(held_exactly(scenario), criteria=tuple(
            c for c in scenario.criteria if c.quantity not in STATION_QUANTITIES))  # no footprint to judge
        for case, label in ((held, "held"), (scenario, "dp")):
            start = time.perf_counter()
            run_exercise(case).assessment()
            times[label] = time.perf_counter() - start
        print(f"{name} ({scenario.run.duration_s:.0f} s): held exactly {times['held']:.2f} s, on DP "
              f"{times['dp']:.2f} s: {times['dp'] / times['held']:.2f} x", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exercises", action="store_true", help="time the DP training exercises (item 3) only")
    if parser.parse_args().exercises:
        exercises()
        return
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    dp, ship = dp_frames(), frames("kvlcc2")
    print(f"supply vessel on DP: {1e6 * dp:.1f} us per 60 Hz frame; KVLCC2 hard over {1e6 * ship:.1f} us: "
          f"{dp / ship:.2f} x")

    scenario = load_scenario(SCENARIO)
    held = dataclasses.replace(held_exactly(scenario), criteria=())
    steps, dt = 18_001, 0.1

    def export(case) -> None:
        sim = Simulation(case, wake=False)
        for lo in range(0, steps, 8192):
            sim.frame_steps(lo * dt, dt, min(8192, steps - lo))
        sim.close()

    t_held, t_dp = best_of(lambda: export(held), 2), best_of(lambda: export(scenario), 2)
    print(f"thirty minutes at 10 Hz: held exactly {t_held:.2f} s, on DP {t_dp:.2f} s: {t_dp / t_held:.2f} x")


if __name__ == "__main__":
    main()
