"""The tree reads as the data flow: every import points down the layers, and no modules import each other.

Layers, lowest first: the shared base (errors, constants, the pose, atomic writes, ...), the physics
packages (sea, hull, vessel, wake, solver, in that order), the motion criteria, the scenario model, the session layer,
the renderer, the command line. A module may import its own layer and those below it; an import
the other way (the renderer's timeline being imported by the export, as it once was) fails here.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from conftest import ROOT

PACKAGE = ROOT / "marinesim"
LAYERS = (
    {"__init__", "errors", "constants", "angles", "atomic", "cache", "tokens", "recent", "progress", "compiled",
     "resources", "formats", "pose", "gl", "figures", "views"},
    {"sea"}, {"hull"}, {"vessel"}, {"manoeuvring"}, {"station"}, {"offshore"}, {"wake"}, {"solver"}, {"criteria"},
    {"scenario"}, {"session"}, {"study"}, {"report"}, {"render"}, {"net"}, {"cli", "__main__"},
)


def _modules() -> dict[str, Path]:
    """Dotted module name -> file, for every module of the package (packages by their ``__init__``)."""
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


MODULES = _modules()


def _imports(name: str, path: Path) -> set[str]:
    """The package modules ``name`` imports anywhere in its file (inside functions too); ``from p import m``
    counts as importing ``p.m`` when that is a module."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package.split(".")[: len(package.split(".")) - node.level + 1] + ([base] if base else []))
            for alias in node.names:
                found.add(f"{base}.{alias.name}" if f"{base}.{alias.name}" in MODULES else base)
    return {m for m in found if m in MODULES and m != name}


def _layer(name: str) -> int:
    top = name.split(".")[1] if "." in name else "__init__"
    return next(i for i, layer in enumerate(LAYERS) if top in layer)


def test_every_module_belongs_to_a_layer():
    """A new top-level module must be placed in a layer, or the direction of its imports is unchecked."""
    for name in MODULES:
        _layer(name)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_imports_point_down_the_layers(name):
    """No upward import: physics never imports the session, the renderer or the command line, and so on."""
    upward = [m for m in _imports(name, MODULES[name]) if _layer(m) > _layer(name)]
    assert not upward, f"{name} (layer {_layer(name)}) imports {upward} from a higher layer"


def test_no_import_cycle():
    """Modules that import each other (directly or round a loop) have no order to be read in."""
    graph = {name: _imports(name, path) for name, path in MODULES.items()}
    done: set[str] = set()

    def visit(node: str, stack: list[str]) -> None:
        for nxt in sorted(graph[node]):
            assert nxt not in stack, "import cycle: " + " -> ".join(stack[stack.index(nxt):] + [nxt])
            if nxt not in done:
                visit(nxt, stack + [nxt])
        done.add(node)

    for name in sorted(graph):
        if name not in done:
            visit(name, [name])


def _strings(path: Path) -> list[str]:
    """The string constants of the file ``path`` (f-strings' literal parts included), docstrings left out."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                  if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                  and node.body and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant)}
    return [node.value for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings]


@pytest.mark.parametrize("name", sorted(MODULES))
def test_no_higher_layer_named_in_a_string(name):
    """A module named in a string (``"marinesim.vessel.wamit:read_wamit"``, imported by that name when used) is an
    import the checks above cannot see: a base module registering the readers so would hide that it depends on the
    vessel and hull packages. Such a string may name the module's own layer and those below it only."""
    named = {f"marinesim.{top}" for text in _strings(MODULES[name]) for top in re.findall(r"\bmarinesim\.(\w+)", text)}
    upward = sorted(m for m in named if m in MODULES and _layer(m) > _layer(name))
    assert not upward, f"{name} (layer {_layer(name)}) names {upward} from a higher layer in a string"
