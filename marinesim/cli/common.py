"""What several commands share: strict JSON, progress bars, number lists, hull placement and view options, an output
refused where it is one of the command's inputs."""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from marinesim.atomic import refuse_input, sidecar_path
from marinesim.errors import ParameterError, require_finite
from marinesim.progress import Bar, Reporter
from marinesim.render import CAMERAS, CASCADES, HUDS


def json_text(value: Any, indent: int | None = None) -> str:
    """``value`` as strict JSON: a non-finite float (NaN, infinity) becomes null."""
    return json.dumps(_finite(value), indent=indent, allow_nan=False)


def _finite(value: Any) -> Any:
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value


def bars(quiet: bool) -> Reporter | None:
    """A progress reporter drawing tqdm bars on stderr (None when ``quiet``)."""
    if quiet:
        return None
    from tqdm import tqdm

    def bar(name: str, total: int, unit: str) -> Bar:
        return tqdm(total=total, desc=name, unit=unit, file=sys.stderr, mininterval=0.5)
    return bar


def number_list(option: str, text: str, unit: str) -> list[float]:
    """Comma-separated finite numbers, or a ParameterError naming the option."""
    try:
        return [require_finite(option, float(v)) for v in text.split(",")]
    except ValueError:
        raise ParameterError(f"{option} must be comma-separated {unit}, got {text!r}") from None


def add_hull_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("hull placement (meshes carry no units and often other axes)")
    g.add_argument("--units", default="m", help="mesh length units: m, cm, mm, ft, in (default m)")
    g.add_argument("--scale", type=float, default=1.0, help="geometric scale of a model mesh, e.g. 50 for 1:50")
    g.add_argument("--axes", default="x,y,z", help="mesh axes that become body x (forward), y (port), z (up), "
                                                   "e.g. 'x,-z,y' for a y-up mesh (default x,y,z)")
    g.add_argument("--draft", type=float, help="draft, m: the lowest point goes to z = -draft (default: the "
                                               "mesh's z = 0 is the waterline)")
    g.add_argument("--trim-deg", type=float, default=0.0, help="trim, deg, bow down positive (default 0)")


def hull_from_args(args: argparse.Namespace):
    """The hull the ``hull`` argument and the placement options describe."""
    from marinesim.hull import load_hull

    return load_hull(args.hull, units=args.units, scale=args.scale, axes=args.axes, draft=args.draft,
                     trim_deg=args.trim_deg)


def add_view_options(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("view")
    g.add_argument("--camera", choices=CAMERAS, default="orbit", help="orbit (default), bridge or free")
    g.add_argument("--solver", choices=("auto", "on", "off"), default="auto",
                   help="the local wave solver around the hull: auto = on with a GPU, off on a software renderer")
    g.add_argument("--cascades", choices=CASCADES, default="auto",
                   help="where the ocean's waves are synthesised each frame: auto = gpu with a GPU, cpu (pyfftw) "
                        "on a software renderer")
    g.add_argument("--no-wake", action="store_true", help="do not draw the Kelvin wake")
    g.add_argument("--hud", choices=HUDS, default="strip",
                   help="strip (default: a compact strip), panels (text, strip charts, every criterion) or off; "
                        "TAB toggles strip and panels in the window")


def render_options(args: argparse.Namespace):
    """The renderer's options from the view options."""
    from marinesim.render.renderer import RenderOptions

    return RenderOptions(wake=not args.no_wake, cascades=args.cascades, hud=args.hud)


def refuse_overwriting(output: Path | None, option: str, sidecar: bool = False) -> None:
    """Refuse (one line naming ``option``) an ``output`` (with ``sidecar``, its sidecar too) that is one of the
    files the command has read so far, by any path or link: checked once the inputs are read, before the work,
    so that nothing is computed for an output that would be refused (:func:`marinesim.atomic.refuse_input`)."""
    if output is not None and output.name:  # an empty path is refused where it is written
        for path in (output, sidecar_path(output)) if sidecar else (output,):
            refuse_input(path, f"{option} {path}")
