"""Benchmark: what the offshore world costs a frame: each exercise with other bodies, a crane's lift or a helicopter,
against the same scene with those not drawn (the baseline, timed in the same run on the same view).

Per exercise, at its busiest moment (the crossing 10 min in, the lift 60 s in, the helicopter in the hover), frames
of 1/60 s stepped and drawn as ``benchmarks/render.py`` does (``frames``): with everything, then with the other
bodies, the load, its wire and boom, the helicopter and the radar hidden. The step still computes the bodies'
poses and the lift (what the record needs anyway); the ratio is what drawing them adds.

Run: ``python benchmarks/offshore.py [--size 1280x720] [--frames 60] [--cascades cpu]``.
"""

from __future__ import annotations

import argparse
import platform
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from render import frames  # noqa: E402

from marinesim.render.offscreen import Offscreen, parse_size  # noqa: E402
from marinesim.render.renderer import RenderOptions  # noqa: E402
from marinesim.scenario import load_scenario  # noqa: E402

CASES = (("crossing_situation", 600.0, "orbit"), ("crane_lift", 60.0, "crane cab"),
         ("helideck_landing", 1530.0, "orbit"))
"""(exercise, time s, camera) for each measured scene."""


def hide(view: Offscreen) -> None:
    """The offshore world not drawn: the other bodies and their lights, the lift, the helicopter, the radar."""
    renderer = view.scene.renderer
    for layer in (*renderer.others, renderer.load, renderer.wire, renderer.boom, renderer.helicopter):
        if layer is not None:
            layer.shown = False
    for lights in renderer.others_lights:
        lights.lights = []
    if renderer.helicopter_lights is not None:
        renderer.helicopter_lights.lights = []
    view.scene.radar_shown = False


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--cascades", default="auto")
    args = parser.parse_args()
    size = parse_size(args.size)
    print(f"{platform.machine()} {platform.processor() or ''} python {platform.python_version()}, {args.size}, "
          f"{args.frames} frames, cascades {args.cascades}")
    for name, at, camera in CASES:
        scenario = load_scenario(name)
        options = RenderOptions(cascades=args.cascades, spray=False)
        with Offscreen(scenario, size, camera=camera, options=options) as view:
            view.go_to(at)
            renderer = view.ctx.info["GL_RENDERER"]
            frames(view, 5)
            full = frames(view, args.frames)
            hide(view)
            frames(view, 5)
            bare = frames(view, args.frames)
        print(f"{name:20s} {camera:10s} wall {1e3 * full['wall']:7.2f} ms, without the offshore world "
              f"{1e3 * bare['wall']:7.2f} ms: x{full['wall'] / bare['wall']:.2f}  (draw CPU x"
              f"{full['draw'] / bare['draw']:.2f}, step CPU x{full['step'] / bare['step']:.2f})  [{renderer}]")


if __name__ == "__main__":
    main()
