"""Benchmark: update of all ocean fields for 4 cascades x 256^2 per frame (issue 2).

Prints milliseconds per update and the ratio to the floor: the same batch of planned pyfftw
inverse transforms (4 per tile, one plan on every CPU) timed alone. Updates and floor are timed
in alternating rounds of 5 calls and the ratio is the median of the rounds' ratios, so that both
see the same machine (a shared VM's speed drifts by tens of percent within seconds). Each round
starts after a 12 ms pause, a 60 Hz frame's idle time: pyfftw's FFTW runs its threads on
OpenMP, whose threads spin for several milliseconds after each call, and back to back they
would slow whatever is timed next by up to a third. The ocean
itself runs one lane of tiles per CPU (``marinesim/sea/synthesis.py``). Also the numpy.fft
fallback and the ocean's memory (numpy allocations, traced). Run: ``python benchmarks/ocean.py``.
"""

from __future__ import annotations

import argparse
import gc
import os
import platform
import time
import tracemalloc

import numpy as np

from marinesim.angles import wave_beta_from_compass
from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem
from marinesim.sea.fft import InverseFFT2


def alternating_ms(first, second, repeats: int, calls: int = 5,
                   pause_s: float = 0.012) -> tuple[np.ndarray, np.ndarray]:
    """Mean time per call (ms) of each function over ``repeats // calls`` alternating rounds of
    ``calls`` calls, each round after ``pause_s`` idle."""
    first(), second()
    times = np.empty((max(1, repeats // calls), 2))
    for row in times:
        for j, function in enumerate((first, second)):
            time.sleep(pause_s)
            start = time.perf_counter()
            for _ in range(calls):
                function()
            row[j] = (time.perf_counter() - start) / calls * 1e3
    return times[:, 0], times[:, 1]


def measure(backend: str, sea: SeaState, tiles: int, resolution: int, repeats: int) -> dict:
    tracemalloc.start()
    gc.collect()
    before = tracemalloc.get_traced_memory()[0]
    ocean = Ocean(sea, tile_count=tiles, resolution=resolution, seed=1, fft_backend=backend)
    memory = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    clock = iter(np.arange(0.0, 1e6, 1.0 / 60.0))
    floor = InverseFFT2((len(ocean.tiles), 4, resolution, resolution), backend)
    update, raw = alternating_ms(lambda: ocean.fields(next(clock)), floor, repeats)
    return {"backend": backend, "update_ms": np.median(update), "fft_ms": np.median(raw),
            "ratio": np.median(update / raw), "ratio_quartiles": np.percentile(update / raw, [25, 75]),
            "memory_mb": memory / 2**20, "components": len(ocean.components()), "lanes": ocean.lane_count}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tiles", type=int, default=4)
    parser.add_argument("--resolution", type=int, default=256)
    parser.add_argument("--repeats", type=int, default=500, help="updates timed (numpy: a tenth)")
    args = parser.parse_args()
    sea = SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), wave_beta_from_compass(30.0), Cos2s(15.0)),))
    print(f"machine: {platform.machine()} {platform.processor() or ''} {os.cpu_count()} cpus, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    print(f"ocean: {args.tiles} tiles x {args.resolution}^2, JONSWAP Hs 4 m Tp 10 s, cos-2s s=15; "
          f"fields: height, displacement x/y, slopes x/y, Jacobian")
    for backend in ("pyfftw", "numpy"):
        repeats = args.repeats if backend == "pyfftw" else args.repeats // 10
        r = measure(backend, sea, args.tiles, args.resolution, repeats)
        low, high = r["ratio_quartiles"]
        print(f"{r['backend']:>7}: update {r['update_ms']:6.2f} ms, raw FFTs {r['fft_ms']:6.2f} ms, "
              f"ratio {r['ratio']:.2f} (quartiles {low:.2f}-{high:.2f}), memory {r['memory_mb']:.1f} MB, "
              f"{r['components']:,} components, {r['lanes']} lanes")


if __name__ == "__main__":
    main()
