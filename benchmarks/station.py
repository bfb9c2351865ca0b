"""Benchmark: a vessel keeping station.

1. The DP vessel's share of a 60 Hz frame: the supply vessel on DP in configs/supply_dp.toml's weather (gusts,
   current, the DP computer, the measured wave motion), the clock moving 1/60 s a frame (a 0.1 s step every sixth
   frame), against the KVLCC2's manoeuvring in a hard-over turn timed in the same run (the per-frame figure own-ship
   dynamics were held to).
2. Thirty minutes at 10 Hz of configs/supply_dp.toml exported (the record with the station's columns), against the
   same scenario with the vessel held exactly on station (``[station]`` left out: no DP, no weather loads) in the
   same run.

Run: ``python benchmarks/station.py``.
"""

from __future__ import annotations

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
from marinesim.scenario import load_scenario  # noqa: E402
from marinesim.session.timeline import Simulation  # noqa: E402
from response import best_of  # noqa: E402

SCENARIO = ROOT / "configs" / "supply_dp.toml"


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


def main() -> None:
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    dp, ship = dp_frames(), frames("kvlcc2")
    print(f"supply vessel on DP: {1e6 * dp:.1f} us per 60 Hz frame; KVLCC2 hard over {1e6 * ship:.1f} us: "
          f"{dp / ship:.2f} x")

    scenario = load_scenario(SCENARIO)
    held = dataclasses.replace(scenario, station=None, criteria=(),
                               vessel=dataclasses.replace(scenario.vessel, ship=StationKeeping("the vessel")))
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
