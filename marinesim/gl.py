"""OpenGL plumbing shared by the solver and the renderer: contexts, shader sources, programs and the GPU FFT.

Shaders are GLSL files in the ``shaders`` resources (:mod:`marinesim.resources`); compile-time constants are
injected as ``#define`` lines after the ``#version`` line, so one file serves every grid size. Every program is a
:class:`Program`, and every compute shader gets its work-group side :data:`GROUP` as the ``GROUP`` define.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping

import moderngl
import numpy as np

from marinesim.errors import MarinesimError
from marinesim.resources import resource_dir

SHADER_DIR = resource_dir("shaders")
GL_VERSION = 430
"""Compute shaders need OpenGL 4.3."""
GROUP = 16
"""The work groups of the cell-wise compute passes are GROUP x GROUP cells (the ``GROUP`` define)."""
FFT_THREADS = 256
"""Most threads of one FFT line's work group (``fft.comp``'s ``THREADS``)."""


class GraphicsError(MarinesimError):
    """No OpenGL context with the features marinesim needs could be made."""


def standalone_context() -> moderngl.Context:
    """A headless OpenGL 4.3 context (EGL: a GPU driver if there is one, else Mesa's llvmpipe)."""
    try:
        return moderngl.create_standalone_context(backend="egl", require=GL_VERSION)
    except Exception as error:  # noqa: BLE001 (moderngl raises plain Exception for a missing driver or version)
        raise GraphicsError(f"no headless OpenGL {GL_VERSION // 100}.{GL_VERSION // 10 % 10} context "
                            f"through EGL ({error}); install Mesa's EGL driver (libegl1, libgl1-mesa-dri)") from None


def is_software(ctx: moderngl.Context) -> bool:
    """Whether ``ctx`` renders on the CPU (Mesa llvmpipe, softpipe, swrast): no GPU behind it."""
    renderer = ctx.info.get("GL_RENDERER", "").lower()
    return any(name in renderer for name in ("llvmpipe", "softpipe", "swrast"))


def shader_source(name: str, **defines: str | float) -> str:
    """The GLSL file ``shaders/<name>`` with ``#define NAME value`` lines for ``defines`` and each
    ``#include "file"`` line replaced by ``shaders/file`` (one level; ``#line`` keeps error lines right)."""
    path = SHADER_DIR / name
    version, *body = path.read_text().split("\n")
    if not version.startswith("#version"):
        raise GraphicsError(f"{path}: the first line must be #version")
    lines = [version, *(f"#define {key} {value}" for key, value in defines.items()), "#line 2"]
    for number, line in enumerate(body, start=2):
        if line.startswith("#include"):
            lines += [(SHADER_DIR / line.split('"')[1]).read_text(), f"#line {number + 1}"]
        else:
            lines.append(line)
    return "\n".join(lines)


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
    shader); :meth:`from_files` compiles ``shaders/<name>.vert|frag`` or ``shaders/<name>.comp``.

    The compiler drops uniforms a program does not use, so a name missing from the linked program may be a
    uniform optimised away (setting it is skipped, as the values are shared between programs) or a misspelt
    name (a programming error). The ``uniform`` declarations of the sources after ``#include`` expansion tell
    them apart: setting a name they do not declare raises.
    """

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
        """Compile ``shaders/<name>.comp`` (``compute``, with ``GROUP`` defined) or ``shaders/<name>.vert`` and
        ``.frag`` with ``defines``."""
        if compute:
            return cls(ctx, name, compute_shader=shader_source(f"{name}.comp", GROUP=GROUP, **defines))
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

    def run(self, x: int = 1, y: int = 1, z: int = 1) -> None:
        """Dispatch ``x`` x ``y`` x ``z`` work groups of the compute shader."""
        self.gl.run(x, y, z)

    def release(self) -> None:
        self.gl.release()


class GpuFFT:
    """The one GPU FFT (``shaders/fft.comp``): a pass transforms every row, or every column, of ``fields``
    ``size`` x ``size`` complex float32 fields, stored one after another in a buffer ([field][row][column]).

    An inverse pass conjugates the twiddles and, where ``normalised``, divides by ``size`` (a forward and an
    inverse 2-D transform then give back the field). ``variants`` are further programs of ``fft.comp`` by the
    name of their define (the solver's ``ADD_DEPTH`` and ``FINISH``), for :meth:`lines`' ``variant``; their
    extra images and buffers are bound by the caller.
    """

    def __init__(self, ctx: moderngl.Context, size: int, fields: int = 1, normalised: bool = False,
                 variants: tuple[str, ...] = ()) -> None:
        self.ctx, self.size, self.fields, self.normalised = ctx, size, fields, normalised
        defines = {"SIZE": f"{size}u", "THREADS": min(size // 2, FFT_THREADS)}
        self.programs = {variant: Program.from_files(ctx, "fft", compute=True, **defines, **{variant: 1})
                         for variant in variants}
        self.programs[None] = Program.from_files(ctx, "fft", compute=True, **defines)
        twiddle = np.exp(-2j * math.pi * np.arange(size // 2) / size)
        self.twiddle = ctx.buffer(np.column_stack([twiddle.real, twiddle.imag]).astype(np.float32).tobytes())

    def lines(self, source: moderngl.Buffer, target: moderngl.Buffer, rows: bool, inverse: bool = False,
              variant: str | None = None) -> None:
        """One pass from ``source`` into ``target``: every row (``rows``) or column of every field."""
        n = self.size
        program = self.programs[variant]
        source.bind_to_storage_buffer(0)
        target.bind_to_storage_buffer(1)
        self.twiddle.bind_to_storage_buffer(2)
        program.update({"line_stride": n if rows else 1, "element_stride": 1 if rows else n,
                        "batch_stride": n * n if self.fields > 1 else 0, "inverse": inverse,
                        "scale": 1.0 / n if inverse and self.normalised else 1.0})
        program.run(n, self.fields)
        self.ctx.memory_barrier()

    def release(self) -> None:
        for program in self.programs.values():
            program.release()
        self.twiddle.release()
