"""Benchmark: the viewer's frame time, split into simulation, upload and draw (issue 6).

The underway default scenario (the WAMIT tanker at 14 kn, so the Kelvin wake is drawn) with
4 x 256^2 cascades, the wake and, with ``--solver``, the 512^2 local solver, orbit camera, HUD
on, frames of 1/60 s of simulated time. Each stage is timed with the GPU finished
(``ctx.finish()``) so that the split is true; the frame time is their sum. Figures are printed
as milliseconds and as ratios to a baseline measured in the same run: the sky-only full-screen
pass at the same size (the cheapest frame the window can draw) and the raw inverse FFTs of the
cascades (the floor of the simulation stage).

Run: ``python benchmarks/render.py [--size 1280x720] [--frames 20] [--solver]``.
"""

from __future__ import annotations

import argparse
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from marinesim.render.offscreen import Offscreen, parse_size  # noqa: E402
from marinesim.render.renderer import RenderOptions  # noqa: E402
from marinesim.scenario import load_scenario  # noqa: E402
from marinesim.sea.fft import InverseFFT2  # noqa: E402


def underway(folder: Path) -> Path:
    text = (ROOT / "configs" / "default.toml").read_text().replace("speed_kn = 4.0", "speed_kn = 14.0")
    path = folder / "underway.toml"
    path.write_text(text.replace('"../', f'"{ROOT.as_posix()}/'))
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--solver", action="store_true", help="with the 512^2 local solver")
    args = parser.parse_args()
    size = parse_size(args.size)
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        scenario = load_scenario(underway(Path(folder)))
    view = Offscreen(scenario, size, solver="on" if args.solver else "off", options=RenderOptions())
    scene, ctx = view.scene, view.ctx
    view.go_to(1.0)
    view.frame()
    stages = {"simulation": [], "upload": [], "draw": []}
    for _ in range(args.frames):
        scene.sim.advance(1.0 / 60.0)
        times = scene.renderer.update(sync=True)
        view.bind()
        start = time.perf_counter()
        scene.draw(size)
        ctx.finish()
        stages["simulation"].append(times.simulation)
        stages["upload"].append(times.upload)
        stages["draw"].append(time.perf_counter() - start)
    sky_view = scene.renderer.view(scene.camera.eye(scene.sim.pose()), size)
    sky = []
    for _ in range(args.frames):
        start = time.perf_counter()
        ctx.clear()
        scene.renderer.sky.draw(sky_view)
        ctx.finish()
        sky.append(time.perf_counter() - start)
    ocean = scene.sim.ocean
    fft = InverseFFT2((len(ocean.tiles), 4, ocean.resolution, ocean.resolution))  # the cascades' transforms
    raw = []
    for _ in range(args.frames):
        start = time.perf_counter()
        fft()
        raw.append(time.perf_counter() - start)
    median = {name: float(np.median(v)) for name, v in stages.items()}
    frame = sum(median.values())
    print(f"machine: {platform.processor() or platform.machine()}, {ctx.info['GL_RENDERER']}")
    print(f"frame {size[0]}x{size[1]}, {len(scene.sim.ocean.tiles)} x {scene.sim.ocean.resolution}^2 cascades, "
          f"wake {'on' if scene.sim.wakes() else 'off'}, solver "
          f"{scene.sim.solver.config.size if scene.sim.solver else 'off'}; median of {args.frames} frames")
    for name, value in median.items():
        print(f"  {name:10s} {1000 * value:8.2f} ms")
    print(f"  frame      {1000 * frame:8.2f} ms  ({1 / frame:.1f} frames/s)")
    print(f"  draw / sky-only pass        {median['draw'] / np.median(sky):6.1f}  "
          f"(sky pass {1000 * np.median(sky):.2f} ms)")
    print(f"  simulation / raw cascade FFTs {median['simulation'] / np.median(raw):6.2f}  "
          f"(FFTs {1000 * np.median(raw):.2f} ms)")
    view.release()


if __name__ == "__main__":
    main()
