"""Benchmark: update of all ocean fields for 4 cascades x 256^2 per frame.

Prints milliseconds per update and the ratio to the floor: the same batch of planned pyfftw
inverse transforms (4 per tile, one plan on every CPU) timed alone. Two ways of calling:

- **60 Hz frames** (the figure that counts): one call per frame, as a viewer makes it, with
  the CPUs idle for the rest of the frame. Blocks of 30 frames of updates and of the floor
  alternate; the ratio is the median over blocks of a block's median update over the mean of
  the two floor blocks beside it. A shared VM's speed drifts by tens of percent within seconds,
  so both must see the same machine.
- **Back to back**: alternating rounds of 5 calls, each round after a 12 ms pause. Warm caches
  and threads that just ran: faster than any frame loop sees. pyfftw's FFTW runs its threads on
  OpenMP, whose threads spin for several milliseconds after each call, and without the pause
  they would slow whatever is timed next by up to a third.

Also the numpy.fft fallback and the ocean's memory (numpy allocations, traced). The ocean runs
one lane of tiles per CPU (``marinesim/sea/synthesis.py``). Run: ``python benchmarks/ocean.py``.
"""

from __future__ import annotations

import argparse
import gc
import itertools
import os
import platform
import time
import tracemalloc
from collections.abc import Callable

import numpy as np

from marinesim.angles import wave_beta_from_compass
from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem
from marinesim.sea.fft import InverseFFT2

FRAME_S = 1.0 / 60.0
FRAMES_PER_BLOCK = 30
SETTLING_FRAMES = 5
"""Frames at the start of each block left out of its median (the switch from the other job)."""


def frame_blocks_ms(update: Callable[[], object], floor: Callable[[], object],
                    pairs: int) -> tuple[np.ndarray, np.ndarray]:
    """Median time (ms) per call in ``pairs`` blocks of each function, one call per 60 Hz frame,
    blocks alternating floor, update, floor, ...; floors are the mean of the blocks either side."""
    medians = np.empty(2 * pairs + 1)
    tick = time.perf_counter()
    for block in range(medians.size):
        function = floor if block % 2 == 0 else update
        times = []
        for _ in range(FRAMES_PER_BLOCK):
            tick = max(tick + FRAME_S, time.perf_counter())  # a frame that overruns is not made up
            start = time.perf_counter()
            function()
            times.append(time.perf_counter() - start)
            time.sleep(max(0.0, tick - time.perf_counter()))
        medians[block] = np.median(times[SETTLING_FRAMES:]) * 1e3
    floors = medians[0::2]
    return medians[1::2], (floors[:-1] + floors[1:]) / 2.0


def back_to_back_ms(update: Callable[[], object], floor: Callable[[], object], repeats: int,
                    calls: int = 5, pause_s: float = 0.012) -> tuple[np.ndarray, np.ndarray]:
    """Mean time per call (ms) of each function over ``repeats // calls`` alternating rounds of
    ``calls`` calls, each round after ``pause_s`` idle."""
    update(), floor()
    times = np.empty((max(1, repeats // calls), 2))
    for row in times:
        for j, function in enumerate((update, floor)):
            time.sleep(pause_s)
            start = time.perf_counter()
            for _ in range(calls):
                function()
            row[j] = (time.perf_counter() - start) / calls * 1e3
    return times[:, 0], times[:, 1]


def summary(update: np.ndarray, floor: np.ndarray) -> dict:
    ratio = update / floor
    return {"update_ms": np.median(update), "fft_ms": np.median(floor), "ratio": np.median(ratio),
            "ratio_quartiles": np.percentile(ratio, [25, 75])}


def measure(backend: str, sea: SeaState, tiles: int, resolution: int, pairs: int, repeats: int) -> dict:
    tracemalloc.start()
    gc.collect()
    before = tracemalloc.get_traced_memory()[0]
    ocean = Ocean(sea, tile_count=tiles, resolution=resolution, seed=1, fft_backend=backend)
    memory = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    frame = itertools.count()
    floor = InverseFFT2((len(ocean.tiles), 4, resolution, resolution), backend)
    update = lambda: ocean.fields(next(frame) * FRAME_S)  # noqa: E731
    return {"backend": backend, "frames": summary(*frame_blocks_ms(update, floor, pairs)),
            "back_to_back": summary(*back_to_back_ms(update, floor, repeats)),
            "memory_mb": memory / 2**20, "components": len(ocean.components()), "lanes": ocean.lane_count}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tiles", type=int, default=4)
    parser.add_argument("--resolution", type=int, default=256)
    parser.add_argument("--pairs", type=int, default=20, help="blocks of 30 frames of updates (numpy: a quarter)")
    parser.add_argument("--repeats", type=int, default=500, help="updates timed back to back (numpy: a tenth)")
    args = parser.parse_args()
    sea = SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), wave_beta_from_compass(30.0), Cos2s(15.0)),))
    print(f"machine: {platform.machine()} {platform.processor() or ''} {os.cpu_count()} cpus, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    print(f"ocean: {args.tiles} tiles x {args.resolution}^2, JONSWAP Hs 4 m Tp 10 s, cos-2s s=15; "
          f"fields: height, displacement x/y, slopes x/y, Jacobian")
    for backend in ("pyfftw", "numpy"):
        fallback = backend == "numpy"
        r = measure(backend, sea, args.tiles, args.resolution, max(1, args.pairs // 4) if fallback else args.pairs,
                    args.repeats // 10 if fallback else args.repeats)
        print(f"{r['backend']:>7}: memory {r['memory_mb']:.1f} MB, {r['components']:,} components, {r['lanes']} lanes")
        for protocol, label in (("frames", "60 Hz frames"), ("back_to_back", "back to back")):
            s = r[protocol]
            low, high = s["ratio_quartiles"]
            print(f"  {label:>12}: update {s['update_ms']:6.2f} ms, raw FFTs {s['fft_ms']:6.2f} ms, "
                  f"ratio {s['ratio']:.2f} (quartiles {low:.2f}-{high:.2f})")


if __name__ == "__main__":
    main()
