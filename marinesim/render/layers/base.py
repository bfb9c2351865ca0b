"""What the layers share: the view of one frame, the sampled-layer protocol and texture helpers."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import moderngl
import numpy as np

from marinesim.gl import is_software
from marinesim.render.camera import Eye
from marinesim.render.daylight import Light


@dataclass(frozen=True)
class View:
    """One camera's view of a frame: the eye, its view-projection (4, 4) (E frame, m -> clip space) and the
    light it is drawn in (sun, moon, sky, clouds, haze)."""

    eye: Eye
    view_projection: np.ndarray
    light: Light

    def shared(self) -> dict[str, object]:
        """The uniforms of ``sky.glsl`` and the eye, which every drawn pass declares."""
        return self.light.uniforms() | {"u_eye": tuple(self.eye.position)}


class Sampled(Protocol):
    """A layer the ocean's program samples: it binds ``units`` texture units from ``unit`` on and returns the
    ocean program's uniforms for them (sampler units, rects, weights)."""

    units: int

    def bind(self, unit: int) -> dict[str, object]: ...


def mat4(m: np.ndarray) -> bytes:
    """A 4 x 4 matrix as a GLSL mat4 (column-major float32)."""
    return np.ascontiguousarray(m.T, dtype=np.float32).tobytes()


def tile_texture_array(ctx: moderngl.Context, n: int, tiles: int, components: int) -> moderngl.TextureArray:
    """An (n, n, ``tiles``) float32 texture array that repeats and is filtered through mipmaps."""
    texture = ctx.texture_array((n, n, tiles), components, dtype="f4")
    texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    texture.repeat_x = texture.repeat_y = True
    texture.anisotropy = 1.0 if is_software(ctx) else 8.0  # llvmpipe filters anisotropically at a crawl
    texture.build_mipmaps()  # every level allocated: a compute pass may store into level 0 before any upload (an
    return texture           # incomplete texture drops image stores on NVIDIA, leaving garbage in the first frame)


def blank_texture(ctx: moderngl.Context) -> moderngl.Texture:
    """A 1 x 1 RGBA float32 texture of zeros: what a sampled layer binds when it has nothing to show."""
    return ctx.texture((1, 1), 4, np.zeros(4, np.float32).tobytes(), dtype="f4")
