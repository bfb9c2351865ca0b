"""Benchmark: the spray's CPU cost per frame (session/spray.py), against the pose the viewer asks for every frame.

The S175 at 18 kn in its heavy-weather sea, the sea doubled and 24 m/s of wind (Beaufort 9: bow spray and
spindrift both on); frames of 1/60 s of simulated time. Per frame: ``Spray.update`` (the sea at the stem, the
puffs' flight, the births) and, the baseline, ``Simulation.pose`` at a new time (the response's 6 DOF). Also
the warm-up a jump costs (a seek, a first frame: four seconds of spray worked out at once). Puffs are born 30
times a second, so at 60 frames a second every other frame only flies them.

Run: ``python benchmarks/spray.py [--frames 600]``.
"""

from __future__ import annotations

import argparse
import dataclasses
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from marinesim.session.spray import Bow, Spray  # noqa: E402
from marinesim.scenario import load_scenario  # noqa: E402
from marinesim.sea.seastate import scaled_sea  # noqa: E402
from marinesim.session.timeline import Simulation  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=600)
    args = parser.parse_args()
    scenario = load_scenario(ROOT / "configs" / "s175_heavy_weather.toml")
    scenario = dataclasses.replace(scenario, sea=scaled_sea(scenario.sea, 2.0, 1.0, 0.0),
                                   environment=scenario.environment.model_copy(
                                       update={"wind_speed_m_s": 24.0, "wind_from_deg": 0.0}))
    sim = Simulation(scenario, wake=False)
    spray = Spray(sim, Bow.of(scenario.vessel.hull, scenario.vessel.hull.vertices))
    sim.advance_to(100.0)
    started = time.perf_counter()
    spray.update()  # the run's wind, as the renderer asks
    warm_up = time.perf_counter() - started
    update, pose, puffs = [], [], []
    for _ in range(args.frames):
        sim.advance(1.0 / 60.0)
        started = time.perf_counter()
        sim.pose()
        pose.append(time.perf_counter() - started)
        started = time.perf_counter()
        spray.update()
        update.append(time.perf_counter() - started)
        puffs.append(len(spray.puffs))
    ms = 1e3
    print(f"{platform.processor() or platform.machine()}, {args.frames} frames of 1/60 s, "
          f"{len(sim.response_now().components)} wave components, puffs in flight: median {np.median(puffs):.0f}, "
          f"max {max(puffs)}")
    print(f"pose (baseline): median {np.median(pose) * ms:.2f} ms")
    print(f"spray update:    median {np.median(update) * ms:.2f} ms, mean {np.mean(update) * ms:.2f} ms, "
          f"95 % {np.percentile(update, 95) * ms:.2f} ms; mean = {np.mean(update) / np.median(pose):.1f} x the pose")
    print(f"warm-up after a jump (4 s of spray): {warm_up * ms:.0f} ms")
    sim.close()


if __name__ == "__main__":
    main()
