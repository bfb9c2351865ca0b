"""``marinesim rao``: read an RAO file in any registered format and summarise it."""

from __future__ import annotations

import argparse
from pathlib import Path

import marinesim.vessel  # noqa: F401  registers the RAO formats listed below
from marinesim.cli.common import number_list, refuse_overwriting
from marinesim.errors import require_finite, require_within
from marinesim.formats import formats


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "rao", help="summarise an RAO file (ranges, long-wave limits, resonances)",
        description="Read an RAO file (" + "; ".join(f.description for f in formats("rao"))
                    + ") and summarise it: DOFs, "
                    "frequency/heading/speed ranges, the long-wave-limit check per DOF, resonance periods.")
    p.add_argument("file", type=Path, help="RAO file")
    p.add_argument("--json", action="store_true", help="print the summary as one JSON object")
    p.add_argument("--plot", type=Path, metavar="PATH", help="draw amplitude and phase against period (PNG)")
    p.add_argument("--headings", default="180,135,90,45,0",
                   help="relative headings to plot, deg, waves towards (180 = head seas; default 180,135,90,45,0)")
    p.add_argument("--speed-kn", type=float,
                   help="speed, kn: for the plot (default 0), and the one speed --write puts in a .4 (a .4 has no "
                        "speed column: a table of several speeds needs it); a table of one speed used far from it "
                        "is noted")
    p.add_argument("--write", type=Path, metavar="PATH",
                   help="write the table as PATH: .4 (WAMIT numeric output: periods, ULEN 1, phase lead) or .csv "
                        "(marinesim's native table, every speed), for another program to read")
    p.add_argument("--ulen", type=float, help="WAMIT length scale ULEN, m (default: from the .gdf beside)")
    p.add_argument("--roll-damping-pct", type=float, default=0.0,
                   help="Capytaine: extra linear roll damping, %% of critical (default 0)")
    p.add_argument("--body", help="Capytaine, WAMIT: the body whose motions to read from a dataset or run of several "
                                  "bodies (WAMIT: its number, or its .gdf file's name in the .pot)")
    p.add_argument("--accept-resonance", action="store_true",
                   help="accept a lightly damped resonance beyond the plausibility limits (a moored body's surge, "
                        "a flap's roll) as real")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.atomic import atomic_path, strict_json
    from marinesim.constants import KNOT
    from marinesim.scenario.model import MAX_SPEED_KN
    from marinesim.vessel import read_rao
    from marinesim.vessel.plot import plot_rao
    from marinesim.vessel.rao import one_speed_note
    from marinesim.vessel.summary import format_rao_summary, rao_summary
    from marinesim.vessel.write import check_extension, write_rao

    headings = [require_within("--headings", h, -360.0, 360.0, "deg") % 360.0  # -90 is 270
                for h in number_list("--headings", args.headings, "degrees")]
    if args.write:
        check_extension(args.write)  # before reading a large file
    roll_damping = require_finite("roll damping", args.roll_damping_pct) / 100
    table = read_rao(args.file, ulen=args.ulen, roll_damping=roll_damping, body=args.body,
                     accept_resonance=args.accept_resonance)
    several = table.speed.size > 1
    low, high = (v / KNOT for v in table.speed_range) if several else (0.0, MAX_SPEED_KN)
    what = "the RAO table's speeds" if several else "a ship's speeds"
    speed = None if args.speed_kn is None else require_within(f"--speed-kn ({what})", args.speed_kn, low, high,
                                                              "kn") * KNOT
    refuse_overwriting(args.write, "--write")
    refuse_overwriting(args.plot, "--plot")
    notes = write_rao(table, args.write, speed=speed) if args.write else ()  # refused before anything is printed
    report = rao_summary(table)
    note = None if speed is None else one_speed_note(table, speed, table.length, "the RAO file's")
    if note is not None:
        report["notes"].append(f"--speed-kn: {note}")
    if args.write:
        report["written"] = {"path": str(args.write), "notes": list(notes)}
    print(strict_json(report) if args.json else format_rao_summary(report))
    if args.plot:
        with atomic_path(args.plot) as temp:
            plot_rao(table, temp, headings, speed or 0.0)
        if not args.json:
            print(f"wrote {args.plot}")
    if args.write and not args.json:
        print(f"wrote {args.write}" + "".join(f"\nnote: {note}" for note in notes))
    return 0
