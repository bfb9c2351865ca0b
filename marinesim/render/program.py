"""A compiled GLSL program that knows the uniforms its source declares.

The compiler drops uniforms a program does not use, so a name missing from the linked program may
be a uniform optimised away (setting it is skipped, as the values are shared between programs) or
a misspelt name (a programming error). :class:`Program` tells them apart by the ``uniform``
declarations of its source after ``#include`` expansion: setting a name it does not declare raises.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import moderngl

from marinesim.gl import GraphicsError, shader_source

_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
_UNIFORM = re.compile(r"\buniform\s+(?:(?:lowp|mediump|highp)\s+)?\w+\s+([^;{]+);")
_DECLARATOR = re.compile(r"\s*(\w+)")


def declared_uniforms(source: str) -> frozenset[str]:
    """The names of the ``uniform <type> <name>[, <name>...];`` declarations in a GLSL source
    (arrays by their name without the brackets; comments ignored)."""
    names = set()
    for match in _UNIFORM.finditer(_COMMENT.sub("", source)):
        names |= {_DECLARATOR.match(part).group(1) for part in match.group(1).split(",")}
    return frozenset(names)


class Program:
    """``name``'s program on ``ctx`` from GLSL sources (a vertex and a fragment shader, or a compute
    shader); :meth:`from_files` compiles ``shaders/<name>.vert|frag`` or ``shaders/<name>.comp``."""

    def __init__(self, ctx: moderngl.Context, name: str, *, vertex_shader: str | None = None,
                 fragment_shader: str | None = None, compute_shader: str | None = None) -> None:
        self.name = name
        sources = [s for s in (vertex_shader, fragment_shader, compute_shader) if s is not None]
        try:
            if compute_shader is not None:
                self.gl = ctx.compute_shader(compute_shader)
            else:
                self.gl = ctx.program(vertex_shader=vertex_shader, fragment_shader=fragment_shader)
        except moderngl.Error as error:
            raise GraphicsError(f"the {name} shader did not compile: {error}") from None
        self.declared = frozenset().union(*(declared_uniforms(s) for s in sources))

    @classmethod
    def from_files(cls, ctx: moderngl.Context, name: str, compute: bool = False, **defines: str | float) -> Program:
        """Compile ``shaders/<name>.comp`` (``compute``) or ``shaders/<name>.vert`` and ``.frag`` with ``defines``."""
        if compute:
            return cls(ctx, name, compute_shader=shader_source(f"{name}.comp", **defines))
        return cls(ctx, name, vertex_shader=shader_source(f"{name}.vert", **defines),
                   fragment_shader=shader_source(f"{name}.frag", **defines))

    def __setitem__(self, name: str, value: object) -> None:
        """Set uniform ``name`` to ``value`` (bytes are written as they are: arrays, matrices); a declared
        uniform the compiler dropped is skipped, an undeclared name raises ValueError."""
        if name not in self.declared:
            raise ValueError(f"the {self.name} program declares no uniform {name!r} "
                             f"(it declares {', '.join(sorted(self.declared))})")
        try:
            member = self.gl[name]
        except KeyError:
            return
        if isinstance(value, bytes):
            member.write(value)
        else:
            member.value = value

    def update(self, values: Mapping[str, object]) -> None:
        """Set every uniform of ``values`` (name -> value) as :meth:`__setitem__` does."""
        for name, value in values.items():
            self[name] = value

    def release(self) -> None:
        self.gl.release()
