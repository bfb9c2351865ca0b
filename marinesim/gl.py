"""OpenGL plumbing shared by the solver and the renderer: contexts and shader sources.

Shaders are GLSL files in the ``shaders`` resources (:mod:`marinesim.resources`); compile-time constants are
injected as ``#define`` lines after the ``#version`` line, so one file serves every grid size.
"""

from __future__ import annotations

import moderngl

from marinesim.errors import MarinesimError
from marinesim.resources import resource_dir

SHADER_DIR = resource_dir("shaders")
GL_VERSION = 430
"""Compute shaders need OpenGL 4.3."""


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
