"""``marinesim examples``: the shipped scenarios and exercises, listed, or copied out with their files to edit."""

from __future__ import annotations

import argparse
from pathlib import Path


def add(commands: argparse._SubParsersAction) -> None:
    p = commands.add_parser(
        "examples", help="list the shipped scenarios and exercises, or copy them out to edit",
        description="List the scenarios and exercises that ship with marinesim. Any command that takes a scenario "
                    "takes one of them by name (marinesim assess crane_lift). `examples copy NAME... DIR` (or "
                    "`copy all DIR`) copies them into DIR with their RAO, hull and side files and the data's "
                    "licence notices, in the shipped layout (DIR/configs, DIR/rao, DIR/hulls), to edit and run.")
    actions = p.add_subparsers(dest="action", metavar="ACTION")
    copy = actions.add_parser("copy", help="copy shipped scenarios with their files into a folder",
                              description="Copy the shipped scenarios NAME (or all) into DIR with every file they "
                                          "read. A file already there with the same bytes is kept; one with other "
                                          "bytes is refused, and nothing is written.")
    copy.add_argument("names", nargs="+", metavar="NAME", help="a shipped scenario (marinesim examples), or all")
    copy.add_argument("dir", type=Path, metavar="DIR", help="the folder to copy into (made if missing)")
    p.set_defaults(handler=handle)


def handle(args: argparse.Namespace) -> int:
    from marinesim.scenario.examples import copy_examples, shipped

    if args.action is None:
        examples = shipped()
        width = max(len(example.name) for example in examples)
        for exercise, title in ((False, "scenarios: marinesim run NAME (or render, export, ...)"),
                                (True, "exercises, scored against their criteria: marinesim assess NAME")):
            print(f"shipped {title}")
            for example in (e for e in examples if e.exercise == exercise):
                print(f"  {example.name:<{width}}  {example.kind:<8}  {example.description}")
        print("copy them to edit, with their RAO and hull files: marinesim examples copy NAME|all DIR")
        return 0
    copied = copy_examples(args.names, args.dir)
    for path in copied.written:
        print(f"wrote {path}")
    if copied.unchanged:
        print(f"{len(copied.unchanged)} file(s) already in {args.dir} with the same contents: kept")
    for example in (next((e for e in copied.examples if not e.exercise), None),
                    next((e for e in copied.examples if e.exercise), None)):
        if example is not None:
            command = "assess" if example.exercise else "run"
            print(f"to run {example.name}: marinesim {command} {args.dir / 'configs' / example.relative}")
    return 0
