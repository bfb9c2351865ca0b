"""Benchmark: own-ship dynamics.

1. The manoeuvring step per frame: the S175 (4 DOF) and the KVLCC2 (MMG) in a hard-over turn, the viewer's
   clock moving 1/60 s a frame (the voyage steps at 0.1 s, so one frame in six steps the ship): the mean time a
   frame spends on the ship (``Voyage.state`` and its sample for the pose), against a bare Python loop of the same
   number of float operations per step as the baseline (RK4's four evaluations of a dozen multiplies).
2. An hour's export at 20 Hz of the heavy-weather transit (S175, 10,600 wave components), in the export's blocks
   of 8,192 rows: with the dynamics on a straight run (the ship in surge equilibrium: the response's fast path),
   against the bare straight-track response in the same blocks (what the export computed before the dynamics),
   timed in the same run; and ten minutes of it through a hard-over turn (the manoeuvre's compiled sum), per
   simulated second.
3. The motions of one time in a turn, as a frame or the live recorder asks for them (one row through the compiled
   sum): on one core, as marinesim sums so small a call, against the same call woken on every core, timed in the
   same run, on a quiet machine and with every other core kept busy (a second process spinning per core, as
   another test worker or the renderer does).

Run: ``python benchmarks/manoeuvring.py``.
"""

from __future__ import annotations

import math
import multiprocessing
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from marinesim.constants import KNOT  # noqa: E402
from marinesim.manoeuvring.voyage import Voyage  # noqa: E402
from marinesim.scenario import Scenario, load_scenario  # noqa: E402
from marinesim.scenario.ship_file import load_ship  # noqa: E402
from marinesim.session.assembly import Assembly  # noqa: E402
from marinesim.session.timeline import Simulation  # noqa: E402
from marinesim.vessel import along  # noqa: E402
from response import best_of  # noqa: E402  (benchmarks/response.py, beside this one)


def frames(name: str, seconds: float = 600.0) -> float:
    """Mean seconds of ship per 60 Hz frame through a hard-over turn of ``seconds``."""
    file, ship = load_ship(ROOT / "configs" / "vessels" / f"{name}.toml")
    state, orders = ship.start(file.approach_speed_kn * KNOT, 0.0)
    voyage = Voyage(ship, state, orders, 0.1)
    voyage.order(0.0, rudder_deg=35.0)
    count = round(seconds * 60)
    start = time.perf_counter()
    for k in range(1, count + 1):
        t = k / 60.0
        voyage.state(t)
        voyage.path(np.array([t]))
    return (time.perf_counter() - start) / count


def bare_step() -> float:
    """Seconds of a bare Python loop doing a dozen float multiplies four times (RK4's evaluations), per step."""
    def evaluate(a: float, b: float) -> float:
        x = a
        for _ in range(12):
            x = x * b + a
        return x
    count = 100_000
    start = time.perf_counter()
    for k in range(count):
        for _ in range(4):
            evaluate(1.0001, 0.9999)
    return (time.perf_counter() - start) / count


def one_time_motions(scenario: Scenario, every_core_from: int, count: int = 600) -> float:
    """Mean seconds of the motions at one time (``Simulation.frame``) through a hard-over turn, 1/60 s apart, with
    calls of ``every_core_from`` steps times components or more summed on every core."""
    sim = Simulation(scenario, wake=False)
    sim.order(rudder_deg=35.0)
    sim.frame(np.array([30.0]))  # the knots' transfer functions of the turn's start
    kept, along.EVERY_CORE_FROM = along.EVERY_CORE_FROM, every_core_from
    try:
        start = time.perf_counter()
        for k in range(count):
            sim.frame(np.array([30.0 + k / 60.0]))
        return (time.perf_counter() - start) / count
    finally:
        along.EVERY_CORE_FROM = kept
        sim.close()


def _spin() -> None:
    """Keep a core busy (a process of its own, until terminated)."""
    while True:
        pass


def main() -> None:
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    floor = bare_step()
    for name in ("s175", "kvlcc2"):
        per_frame = frames(name)
        print(f"{name}: the ship per 60 Hz frame in a hard-over turn {1e6 * per_frame:.1f} us "
              f"({per_frame / floor:.2f} x a bare RK4-sized loop per step, {1e6 * floor:.1f} us)")

    scenario = load_scenario(ROOT / "configs" / "training" / "heavy_weather_transit.toml")
    steps, dt = 72_001, 0.05
    response = Assembly(scenario).response

    def straight():
        for lo in range(0, steps, 8192):
            for _ in response.frames(lo * dt, dt, min(8192, steps - lo)):
                pass

    def dynamics():
        sim = Simulation(scenario, wake=False)
        for lo in range(0, steps, 8192):
            sim.frame_steps(lo * dt, dt, min(8192, steps - lo))
        sim.close()

    t_straight, t_dynamics = best_of(straight), best_of(dynamics)
    print(f"an hour at 20 Hz, {len(response.components)} components: straight-track response {t_straight:.2f} s, "
          f"with the dynamics (a straight run) {t_dynamics:.2f} s: {t_dynamics / t_straight:.2f} x")

    def turn():
        sim = Simulation(scenario, wake=False)
        sim.order(rudder_deg=35.0)
        sim.frame_steps(0.0, dt, 12_000)
        sim.close()

    t_turn = best_of(turn, 1)
    print(f"ten minutes at 20 Hz through a hard-over turn: {t_turn:.1f} s ({t_turn / 600.0 * 1000:.0f} ms per "
          f"simulated second, {t_turn / 12_000 * 1e3:.2f} ms a row)")

    spawn = multiprocessing.get_context("spawn")  # not a fork of a process whose numba and FFTW threads run
    for load in ("quiet", "every other core busy"):
        spinning = [spawn.Process(target=_spin, daemon=True)
                    for _ in range((os.cpu_count() or 1) - 1 if load != "quiet" else 0)]
        for process in spinning:
            process.start()
        one = one_time_motions(scenario, along.EVERY_CORE_FROM)
        every = one_time_motions(scenario, 0)
        for process in spinning:
            process.terminate()
            process.join()
        print(f"the motions of one time in a turn, {load}: on one core {1e3 * one:.2f} ms, woken on every core "
              f"{1e3 * every:.2f} ms: {every / one:.2f} x")


if __name__ == "__main__":
    main()
