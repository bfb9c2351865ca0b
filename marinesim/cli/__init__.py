"""The ``marinesim`` command: one module per command, each with ``add`` (its options) and ``handle``
(the work, importing what it needs only then, so that ``marinesim --version`` and ``--help`` answer
at once; those imports are made first, with Ctrl-C held: :func:`needs`). User mistakes print one line and
exit with status 2; Ctrl-C (SIGINT) and SIGTERM (what ``timeout``, ``docker stop`` and a cancelled job send)
discard the files being written, print one line and exit with 130 and 143.
"""

from __future__ import annotations

import argparse
import ast
import functools
import importlib.util
import inspect
import signal
import sys
import textwrap
from collections.abc import Callable
from typing import NoReturn

from marinesim import __version__
from marinesim.atomic import inputs_kept, signals_held
from marinesim.cli import (assess, capability, examples, export, hull, operability, rao, render, replay, report, run,
                           sea, serve, trials, wake)
from marinesim.errors import MarinesimError

COMMANDS = (run, serve, examples, render, export, assess, replay, report, trials, capability, operability, rao, hull,
            wake, sea)
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
        _load(needs(args.handler))
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


Imports = tuple[tuple[str, tuple[str, ...]], ...]
"""Import statements: (module, the names imported from it; none for ``import module``)."""
BRANCHES = (ast.If, ast.For, ast.AsyncFor, ast.While, ast.Try, ast.TryStar, ast.Match, ast.With, ast.AsyncWith)
"""The statements whose inner statements may not run (or not first): what they import or call is not loaded."""


@functools.cache
def needs(handle: Callable) -> Imports:
    """What a command's ``handle`` imports before its work, read from its source so that it cannot disagree
    with it: the imports at the top level of its body, and of the body of each function of the command line
    that it calls there (``hull_from_args``), and so on. An import inside a branch (a plot only when one is
    asked for, the viewer only where there is a display) is left to the moment it runs."""
    found: dict[tuple[str, tuple[str, ...]], None] = {}
    _imports(handle, found, set())
    return tuple(found)


def _imports(function: Callable, found: dict[tuple[str, tuple[str, ...]], None], seen: set[Callable]) -> None:
    """Add the imports of :func:`needs` made by ``function`` to ``found`` (its functions ``seen`` once)."""
    seen.add(function)
    try:
        (definition,) = ast.parse(textwrap.dedent(inspect.getsource(function))).body
    except (OSError, TypeError, ValueError):  # no source (a frozen or compiled module): it loads its own
        return
    package = sys.modules[function.__module__].__package__ or ""
    for statement in definition.body:
        if isinstance(statement, ast.Import):
            found.update(((alias.name, ()), None) for alias in statement.names)
        elif isinstance(statement, ast.ImportFrom):
            module = importlib.util.resolve_name("." * statement.level + (statement.module or ""), package)
            found[(module, tuple(alias.name for alias in statement.names if alias.name != "*"))] = None
        elif not isinstance(statement, BRANCHES):
            for node in ast.walk(statement):
                called = (function.__globals__.get(node.func.id)
                          if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) else None)
                if (inspect.isfunction(called) and called.__module__.startswith(f"{__name__}.")
                        and called not in seen):
                    _imports(called, found, seen)


def _load(imports: Imports) -> None:
    """Make the ``imports`` (as :func:`needs` gives them) with SIGINT and SIGTERM held until they are in: an
    interrupt inside an import (scipy's, for one) can leave the import broken and end in a traceback."""
    with signals_held():
        for name, names in imports:
            module = importlib.import_module(name)
            for attribute in names:
                if not hasattr(module, attribute):  # a submodule (a lazy attribute of a package loads here)
                    importlib.import_module(f"{name}.{attribute}")


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
