"""What a command loads before its work, with Ctrl-C held (``marinesim.cli.needs``): derived from the source of
its ``handle``, so that it holds every module the handle imports at the top of its body (and what the command-line
helpers it calls import), and nothing that only a branch imports."""

from __future__ import annotations

import dis
import inspect
import subprocess
import sys
from collections.abc import Callable

import pytest

from marinesim.cli import COMMANDS, needs


def top_level_imports(function: Callable) -> set[tuple[str, tuple[str, ...]]]:
    """(module, names) of each import statement at the top level of ``function``'s body, read from its bytecode
    (not its syntax tree, as ``needs`` reads it): an IMPORT_NAME on a line indented as a module function's body."""
    lines, first = inspect.getsourcelines(function)
    found = set()
    previous = None
    for instruction in dis.get_instructions(function):
        if instruction.opname == "IMPORT_NAME":
            line = lines[instruction.positions.lineno - first]
            if len(line) - len(line.lstrip()) == 4:
                found.add((instruction.argval, tuple(previous.argval or ())))  # the fromlist loaded just before
        previous = instruction
    return found


@pytest.mark.parametrize("command", COMMANDS, ids=lambda command: command.__name__.rpartition(".")[2])
def test_a_command_loads_every_module_its_handle_imports(command):
    imports = top_level_imports(command.handle)
    assert any(module.startswith("marinesim.") for module, _ in imports), "no import read from the handle"
    missing = imports - set(needs(command.handle))
    assert not missing, f"{command.__name__}: its handle imports {sorted(missing)}, not loaded first"


def test_a_helper_s_imports_are_loaded_and_a_branch_s_are_not():
    """``marinesim hull`` reads the mesh in ``hull_from_args`` (cli/common.py): the mesh reader loads first, and
    trimesh when the mesh is read (``marinesim.hull.trimesh_held`` holds Ctrl-C through its import). ``marinesim
    run`` imports the viewer only where there is a display: a headless run loads no pyglet."""
    code = ("import sys; from marinesim.cli import _load, needs, hull, run; _load(needs(hull.handle)); "
            "print('marinesim.hull.mesh' in sys.modules, 'trimesh' in sys.modules); _load(needs(run.handle)); "
            "print('marinesim.session.headless' in sys.modules, 'marinesim.render.viewer' in sys.modules, "
            "'pyglet' in sys.modules)")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.split() == ["True", "False", "True", "False", "False"], result.stdout
