"""Benchmark: update of all ocean fields for 4 cascades x 256^2 per frame (issue 2).

Prints milliseconds per update and the ratio to the floor: the same batch of planned pyfftw
inverse transforms (4 per tile, one plan on every CPU) timed alone in the same run. The ocean
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


def per_call_ms(function, repeats: int) -> float:
    """Median over 5 batches of the mean time per call (ms)."""
    function()
    batches = []
    for _ in range(5):
        start = time.perf_counter()
        for _ in range(repeats):
            function()
        batches.append((time.perf_counter() - start) / repeats * 1e3)
    return float(np.median(batches))


def measure(backend: str, sea: SeaState, tiles: int, resolution: int, repeats: int) -> dict:
    tracemalloc.start()
    gc.collect()
    before = tracemalloc.get_traced_memory()[0]
    ocean = Ocean(sea, tile_count=tiles, resolution=resolution, seed=1, fft_backend=backend)
    memory = tracemalloc.get_traced_memory()[0] - before
    tracemalloc.stop()
    clock = iter(np.arange(0.0, 1e6, 1.0 / 60.0))
    update = per_call_ms(lambda: ocean.fields(next(clock)), repeats)
    floor = InverseFFT2((len(ocean.tiles), 4, resolution, resolution), backend)
    raw = per_call_ms(floor, repeats)
    return {"backend": backend, "update_ms": update, "fft_ms": raw, "ratio": update / raw,
            "memory_mb": memory / 2**20, "components": len(ocean.components()), "lanes": ocean.lane_count}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--tiles", type=int, default=4)
    parser.add_argument("--resolution", type=int, default=256)
    parser.add_argument("--repeats", type=int, default=100)
    args = parser.parse_args()
    sea = SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), wave_beta_from_compass(30.0), Cos2s(15.0)),))
    print(f"machine: {platform.machine()} {platform.processor() or ''} {os.cpu_count()} cpus, "
          f"Python {platform.python_version()}, numpy {np.__version__}")
    print(f"ocean: {args.tiles} tiles x {args.resolution}^2, JONSWAP Hs 4 m Tp 10 s, cos-2s s=15; "
          f"fields: height, displacement x/y, slopes x/y, Jacobian")
    for backend in ("pyfftw", "numpy"):
        r = measure(backend, sea, args.tiles, args.resolution, args.repeats if backend == "pyfftw" else 10)
        print(f"{r['backend']:>7}: update {r['update_ms']:6.2f} ms, raw FFTs {r['fft_ms']:6.2f} ms, "
              f"ratio {r['ratio']:.2f}, memory {r['memory_mb']:.1f} MB, {r['components']:,} components, "
              f"{r['lanes']} lanes")


if __name__ == "__main__":
    main()
