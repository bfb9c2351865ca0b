"""``marinesim hull``: check a hull mesh and print its hydrostatics."""

from __future__ import annotations

import argparse
from pathlib import Path

import marinesim.hull  # noqa: F401  registers the mesh formats listed below
from marinesim.atomic import strict_json
from marinesim.cli.common import add_hull_options, hull_from_args
from marinesim.formats import extensions


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "hull", help="check a hull mesh and print its hydrostatics",
        description=f"Read a hull ({', '.join(extensions('mesh'))}), place it in the body frame "
                    "(x forward, y to port, z up, waterline z = 0), check it and print its hydrostatics.")
    p.add_argument("hull", type=Path, help="hull mesh file")
    add_hull_options(p)
    p.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.hull import format_hydrostatics, hydrostatics

    hull = hull_from_args(args)
    statics = hydrostatics(hull)
    if args.json:
        print(strict_json(statics.as_dict() | {"triangles": len(hull.faces), "notes": list(hull.notes)}))
    else:
        print(f"{hull.source}: {len(hull.faces):,} triangles")
        print(format_hydrostatics(statics))
        for note in hull.notes:
            print(f"note: {note}")
    return 0
