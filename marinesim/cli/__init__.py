"""The ``marinesim`` command: one module per command, each with ``add`` (its options) and ``handle``
(the work, importing what it needs only then, so that ``marinesim --version`` and ``--help`` answer
at once). User mistakes print one line and exit with status 2; Ctrl-C (SIGINT) and SIGTERM (what
``timeout``, ``docker stop`` and a cancelled job send) discard the files being written, print one
line and exit with 130 and 143.
"""

from __future__ import annotations

import argparse
import importlib
import signal
import sys
from typing import NoReturn

from marinesim import __version__
from marinesim.atomic import inputs_kept, signals_held
from marinesim.cli import (assess, capability, examples, export, hull, operability, rao, render, replay, report, run,
                           sea, trials, wake)
from marinesim.errors import MarinesimError

COMMANDS = (run, examples, render, export, assess, replay, report, trials, capability, operability, rao, hull, wake,
            sea)
"""The command modules, in the order ``--help`` lists them."""


class Terminated(BaseException):
    """SIGTERM arrived: unwind as Ctrl-C does (temporary files are discarded on the way out)."""


def main(argv: list[str] | None = None) -> int:
    """Run the command line ``argv`` (default: the process's); the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        _load(sys.modules[args.handler.__module__].NEEDS)
        with inputs_kept():  # no output is written over a file the command reads
            return args.handler(args)
    except MarinesimError as error:
        print(f"marinesim {args.command}: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"marinesim {args.command}: interrupted (files being written were discarded)", file=sys.stderr)
        return 130
    except Terminated:
        print(f"marinesim {args.command}: terminated (files being written were discarded)", file=sys.stderr)
        return 143
    except OSError as error:
        print(f"marinesim {args.command}: error: {error.strerror or error}: {error.filename}", file=sys.stderr)
        return 2
    finally:
        signal.signal(signal.SIGTERM, previous)


def _terminate(signum: int, frame: object) -> None:
    raise Terminated


def _load(modules: tuple[str, ...]) -> None:
    """Import ``modules`` with SIGINT and SIGTERM held until they are in: an interrupt inside an import
    (scipy's, for one) can leave the import broken and end in a traceback."""
    with signals_held():
        for name in modules:
            importlib.import_module(name)


class Parser(argparse.ArgumentParser):
    """argparse whose usage errors are one line (the usage itself is what ``--help`` prints); the commands'
    parsers are of this class too (``add_subparsers`` makes them of their parent's)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {' '.join(message.split())} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    """The whole command line: every command's options."""
    parser = Parser(
        prog="marinesim",
        description="Ship motion and wake simulator: waves on FFT cascades, RAO response, Kelvin wake.",
    )
    parser.add_argument("--version", action="version", version=f"marinesim {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    for command in COMMANDS:
        command.add(commands)
    return parser
