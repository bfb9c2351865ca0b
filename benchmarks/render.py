"""Benchmark: the viewer's frame, with the cascades synthesised on the CPU and on the GPU.

The underway default scenario (the WAMIT tanker at 14 kn, so the Kelvin wake is drawn) with
4 x 256^2 cascades, the wake, optionally the 512^2 local solver (``--solver``), orbit camera, HUD on;
frames of 1/60 s of simulated time, each what the window does per frame: ``Scene.step`` (the
exercise, the pose, the solver's sub-steps, the cascades) and ``Scene.draw``. Per frame:

- step CPU: the calling thread's CPU time for ``Scene.step`` (simulation, the cascades' synthesis or
  its submission, upload), the GPU's work not waited for, and every thread's (the CPU synthesis runs
  its FFTs on worker threads; a driver or llvmpipe may work on threads of its own);
- draw CPU: the same for ``Scene.draw``'s submission (on a software renderer, llvmpipe, this thread
  also runs the vertex shaders; the rest of the GPU's work runs on other threads of the same CPU, so
  there the wall time says what a frame costs);
- wall: the same with the GPU's work finished (``ctx.finish()``), i.e. frames/s drawing flat out.

Baselines timed in the same run: one raw pyfftw update of the cascades (the 16 inverse FFTs the CPU
synthesis does per frame, wall time, every CPU) and the sky-only full-screen pass at the same size.

Run: ``python benchmarks/render.py [--size 1280x720] [--frames 60] [--solver] [--cascades cpu,gpu]``.
"""

from __future__ import annotations

import argparse
import platform
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from marinesim.render.offscreen import Offscreen, parse_size  # noqa: E402
from marinesim.render.renderer import RenderOptions  # noqa: E402
from marinesim.scenario import load_scenario  # noqa: E402
from marinesim.sea.fft import InverseFFT2  # noqa: E402

FRAME_S = 1.0 / 60.0


def underway(folder: Path) -> Path:
    text = (ROOT / "configs" / "default.toml").read_text().replace("speed_kn = 4.0", "speed_kn = 14.0")
    path = folder / "underway.toml"
    path.write_text(text.replace('"../', f'"{ROOT.as_posix()}/'))
    return path


def frames(view: Offscreen, count: int) -> dict[str, float]:
    """Median seconds over ``count`` frames, each stepped, drawn and finished: ``step`` and ``draw`` (the
    calling thread's CPU), ``step_process`` (every thread's CPU during the step) and ``wall``."""
    scene, ctx = view.scene, view.ctx
    times: dict[str, list[float]] = {"step": [], "step_process": [], "draw": [], "wall": []}
    for _ in range(count):
        start_thread, start_process, start = time.thread_time(), time.process_time(), time.perf_counter()
        scene.step(FRAME_S)
        stepped_thread, stepped_process = time.thread_time(), time.process_time()
        view.bind()
        scene.draw(view.size)
        times["step"].append(stepped_thread - start_thread)
        times["step_process"].append(stepped_process - start_process)
        times["draw"].append(time.thread_time() - stepped_thread)
        ctx.finish()
        times["wall"].append(time.perf_counter() - start)
    return {name: float(np.median(values)) for name, values in times.items()}


def sky_pass(view: Offscreen, count: int) -> float:
    """Median seconds of the sky-only pass (the cheapest full-screen frame) at the view's size."""
    scene, ctx = view.scene, view.ctx
    sky_view = scene.renderer.view(scene.camera.eye(scene.sim.pose()), view.size)
    times = []
    for _ in range(count):
        start = time.perf_counter()
        ctx.clear()
        scene.renderer.sky.draw(sky_view)
        ctx.finish()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def raw_fft(tiles: int, n: int, count: int) -> float:
    """Median wall seconds of one raw pyfftw update of ``tiles`` cascades (4 transforms of n^2 each)."""
    fft = InverseFFT2((tiles, 4, n, n))
    fft()
    times = []
    for _ in range(count):
        start = time.perf_counter()
        fft()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--solver", action="store_true", help="with the 512^2 local solver")
    parser.add_argument("--cascades", default="cpu,gpu", help="where the cascades are synthesised, comma list")
    args = parser.parse_args()
    size = parse_size(args.size)
    with tempfile.TemporaryDirectory() as folder:
        scenario = load_scenario(underway(Path(folder)))
    rows = []
    for where in args.cascades.split(","):
        with Offscreen(scenario, size, solver="on" if args.solver else "off",
                       options=RenderOptions(cascades=where)) as view:
            view.go_to(1.0)
            frames(view, 5)  # warm: shaders compiled, FFTW planned, buffers allocated
            measured = frames(view, args.frames)
            sky = sky_pass(view, 10)
            ocean, sim = view.scene.sim.ocean, view.scene.sim
            info = view.ctx.info["GL_RENDERER"]
            solver = f"{sim.solver.config.size}^2" if sim.solver else "off"
            rows.append((where, measured, sky))
    fft = raw_fft(len(ocean.tiles), ocean.resolution, args.frames)
    print(f"machine: {platform.processor() or platform.machine()}, {info}")
    print(f"frame {size[0]}x{size[1]}, {len(ocean.tiles)} x {ocean.resolution}^2 cascades, wake "
          f"{'on' if sim.wakes() else 'off'}, solver {solver}, HUD on; median of {args.frames} frames of 1/60 s")
    print(f"raw pyfftw cascade update {1000 * fft:.2f} ms (baseline)")
    print(f"{'cascades':>8} {'step CPU ms':>12} {'/ raw FFT':>10} {'all threads':>12} {'draw CPU ms':>12} "
          f"{'wall ms':>8} {'frames/s':>9} {'wall / sky':>11}")
    for where, m, sky in rows:
        print(f"{where:>8} {1000 * m['step']:12.2f} {m['step'] / fft:10.2f} {1000 * m['step_process']:12.2f} "
              f"{1000 * m['draw']:12.2f} {1000 * m['wall']:8.2f} {1 / m['wall']:9.1f} {m['wall'] / sky:11.1f}")

if __name__ == "__main__":
    main()
