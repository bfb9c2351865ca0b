"""The local solver on the GPU: moderngl compute shaders (OpenGL 4.3) and one render pass.

Per sub-step (shaders/): the hull is drawn into a float texture of displaced depth
(``hull_depth.vert/.frag``, additive blending); then five compute passes: FFT of the rows with the
depth added (``fft.comp`` ADD_DEPTH, through :class:`~marinesim.gl.GpuFFT`), FFT of the columns,
the rotation in k-space (``solver_rotate.comp``), inverse FFT of the columns, inverse FFT of the rows
with the depth taken off, the sponge/obstacle factor and the non-finite check (FINISH). Scrolling is
``solver_shift.comp``. The state stays on the GPU; :attr:`GpuSolver.height_texture` is what the
renderer samples (R32F, texel (i, j) = cell column i, row j, at world position
``origin + (i + 1/2, j + 1/2) * cell``). Everything is float32; the NumPy reference
(reference.py) is the same numerics in float64.
"""

from __future__ import annotations

import logging

import moderngl
import numpy as np

from marinesim.gl import GROUP, GpuFFT, Program, standalone_context
from marinesim.hull.mesh import Hull
from marinesim.pose import Pose
from marinesim.solver.footprint import Placement
from marinesim.solver.local import LocalSolver, SolverConfig
from marinesim.solver.spectral import SUBPIXEL

log = logging.getLogger("marinesim.solver")


class GpuSolver(LocalSolver):
    """The local solver in OpenGL compute shaders, on ``ctx`` (a new headless context if None)."""

    def __init__(self, config: SolverConfig, hull: Hull | None = None, pose: Pose | None = None,
                 obstacles: tuple[np.ndarray, ...] = (), ctx: moderngl.Context | None = None) -> None:
        self.ctx = ctx or standalone_context()
        super().__init__(config, hull, pose, obstacles)

    def _setup(self) -> None:
        ctx, n = self.ctx, self.config.size
        self._fft = GpuFFT(ctx, n, normalised=True, variants=("ADD_DEPTH", "FINISH"))
        self._rotate = Program.from_files(ctx, "solver_rotate", compute=True, SIZE=f"{n}u")
        self._shift_cs = Program.from_files(ctx, "solver_shift", compute=True, SIZE=n)
        self._raster = Program.from_files(ctx, "hull_depth", SUBPIXEL=SUBPIXEL)
        self._raster["size"] = float(n)
        bits = int(ctx.info.get("GL_SUBPIXEL_BITS", 0))
        if 1 << bits < SUBPIXEL:
            log.info("the GPU snaps vertices to 1/%d of a cell, not 1/%d: the hull's depth may differ from the "
                     "NumPy reference in cells its edges touch", 1 << bits, SUBPIXEL)

        cells = n * n
        self._state = ctx.buffer(reserve=cells * 8)
        self._work = [ctx.buffer(reserve=cells * 8), ctx.buffer(reserve=cells * 8)]
        for buffer in (self._state, *self._work):
            buffer.clear()
        a, b = self.coefficients
        coefficients = np.stack([a.real, a.imag, b.real, b.imag], axis=-1).astype(np.float32)
        self._coefficients = ctx.buffer(coefficients.tobytes())
        self._keep = ctx.buffer(reserve=cells * 4)
        self._counter = ctx.buffer(reserve=4)
        self._counter.clear()

        self._depth = ctx.texture((n, n), 1, dtype="f4")
        self._depth_fbo = ctx.framebuffer(color_attachments=[self._depth])
        self._depth_fbo.clear(0.0, 0.0, 0.0, 0.0)
        self.height_texture = ctx.texture((n, n), 1, dtype="f4")
        self.height_texture.write(np.zeros((n, n), np.float32).tobytes())
        self._vertices = self._indices = self._hull = None
        if self.hull is not None:  # the mesh goes up once; each sub-step sets only its placements' maps
            self._vertices = ctx.buffer(np.ascontiguousarray(self.hull.vertices, dtype=np.float64).tobytes())
            self._indices = ctx.buffer(np.ascontiguousarray(self.hull.faces, dtype=np.uint32).tobytes())
            self._hull = ctx.vertex_array(self._raster.gl, [(self._vertices, "3f8", "in_body")], self._indices,
                                          index_element_size=4)

    # --- passes -----------------------------------------------------------------------------
    def _set_keep(self, keep: np.ndarray) -> None:
        self._keep.write(keep.astype(np.float32).tobytes())

    def _draw_depth(self, placements: list[Placement] | None) -> None:
        with self.ctx.scope(self._depth_fbo, enable_only=moderngl.BLEND):
            self._depth_fbo.viewport = (0, 0, self.config.size, self.config.size)
            self._depth_fbo.clear(0.0, 0.0, 0.0, 0.0)
            if placements is None:
                return
            self.ctx.blend_func = moderngl.ONE, moderngl.ONE
            self.ctx.blend_equation = moderngl.FUNC_ADD
            for matrix, weight in placements:
                self._raster["to_grid"] = np.ascontiguousarray(matrix.T, dtype=np.float64).tobytes()
                self._raster["weight_in"] = weight
                self._hull.render(moderngl.TRIANGLES)
            self.ctx.blend_func = moderngl.DEFAULT_BLENDING

    def _advance(self, placements: list[Placement] | None) -> None:
        n = self.config.size
        first, second = self._work
        self._draw_depth(placements)
        self._depth.bind_to_image(0, read=True, write=False)
        self._fft.lines(self._state, first, rows=True, variant="ADD_DEPTH")
        self._fft.lines(first, second, rows=False)
        second.bind_to_storage_buffer(0)
        first.bind_to_storage_buffer(1)
        self._coefficients.bind_to_storage_buffer(2)
        self._rotate.run(n // GROUP, n // GROUP)
        self.ctx.memory_barrier()
        self._fft.lines(first, second, rows=False, inverse=True)
        self._keep.bind_to_storage_buffer(3)
        self._counter.bind_to_storage_buffer(4)
        self.height_texture.bind_to_image(1, read=False, write=True)
        self._fft.lines(second, self._state, rows=True, inverse=True, variant="FINISH")

    def _start_at_rest(self, placements: list[Placement]) -> None:
        self._draw_depth(placements)
        depth = np.frombuffer(self._depth.read(), dtype=np.float32).reshape(self.config.size, -1)
        keep = np.frombuffer(self._keep.read(), dtype=np.float32).reshape(depth.shape)
        self._write(-depth * keep, np.zeros_like(depth))

    def _shift(self, shift: tuple[int, int]) -> None:
        n = self.config.size
        self._state.bind_to_storage_buffer(0)
        self._work[0].bind_to_storage_buffer(1)
        self._shift_cs["shift"] = shift
        self._shift_cs.run(n // GROUP, n // GROUP)
        self.ctx.memory_barrier()
        self._state, self._work[0] = self._work[0], self._state

    def _clear(self) -> None:
        self._state.clear()
        self.height_texture.write(np.zeros((self.config.size,) * 2, np.float32).tobytes())

    def _write(self, h: np.ndarray, phi: np.ndarray) -> None:
        self._state.write(np.stack([h, phi], axis=-1).astype(np.float32).tobytes())
        self.height_texture.write(h.astype(np.float32).tobytes())

    def _take_nonfinite(self) -> int:
        bad = int(np.frombuffer(self._counter.read(), dtype=np.uint32)[0])
        if bad:
            self._counter.clear()
        return bad

    def fields(self) -> tuple[np.ndarray, np.ndarray]:
        n = self.config.size
        state = np.frombuffer(self._state.read(), dtype=np.float32).reshape(n, n, 2).astype(float)
        return state[..., 0].copy(), state[..., 1].copy()

    @property
    def depth(self) -> np.ndarray:
        """Displaced depth of the last sub-step (m), read back from the GPU."""
        return np.frombuffer(self._depth.read(), dtype=np.float32).reshape(self.config.size, -1).astype(float)

    def release(self) -> None:
        """Free the GPU objects (the context stays)."""
        for thing in (self._fft, self._rotate, self._shift_cs, self._raster,
                      self._state, *self._work, self._coefficients, self._keep, self._counter,
                      self._depth_fbo, self._depth, self.height_texture, self._hull, self._vertices, self._indices):
            if thing is not None:
                thing.release()
