"""The ocean's cascades synthesised on the GPU, each frame, straight into the textures the ocean samples.

The same numerics as the CPU synthesis (:mod:`marinesim.sea.synthesis`), in compute shaders:
``cascade_pack.comp`` evolves every cell's spectrum to the frame's time and packs the four
transforms per tile, ``fft.comp`` (the one GPU FFT, :class:`~marinesim.gl.GpuFFT`, shared with the local
solver) inverse-transforms the rows and then the columns of all of them in two dispatches, and
``cascade_unpack.comp`` writes height, displacement, Jacobian and slopes into the
:class:`~marinesim.render.layers.cascades.CascadeLayer`'s texture arrays. Mipmaps and the foam pass follow on
the GPU.

The CPU uploads only what changes: the spectrum of a sea state when the frames first need it (the
start, and each ramp of a live change: :meth:`Ocean.spectrum_state`), and per frame the time, the
ramp's weight and the choppiness as uniforms. The vessel responds to the ocean's components, the
same amplitudes as these spectra, so it moves on exactly the waves that are drawn.
"""

from __future__ import annotations

import moderngl
import numpy as np

from marinesim.gl import GROUP, GpuFFT, Program
from marinesim.render.layers.cascades import CascadeLayer
from marinesim.sea.ocean import Ocean


class CascadeSynthesis:
    """Writes ``ocean``'s fields at a time into ``cascades`` (its ``tiles`` x ``N``^2 texture arrays), on ``ctx``."""

    def __init__(self, ctx: moderngl.Context, ocean: Ocean, cascades: CascadeLayer) -> None:
        self.ctx, self.ocean, self.cascades = ctx, ocean, cascades
        n, tiles = ocean.resolution, len(ocean.tiles)
        self._n, self._tiles = n, tiles
        self._pack = Program.from_files(ctx, "cascade_pack", compute=True, SIZE=f"{n}u", TILES=tiles)
        self._fft = GpuFFT(ctx, n, fields=4 * tiles)  # the ocean's transform is the unnormalised inverse DFT
        self._unpack = Program.from_files(ctx, "cascade_unpack", compute=True, SIZE=f"{n}u")
        cells = tiles * n * n
        self._omega = ctx.buffer(ocean.grid_omega().astype(np.float64).tobytes())
        self._states = [ctx.buffer(reserve=cells * 16), ctx.buffer(reserve=cells * 16)]
        self._held: list[int | None] = [None, None]
        """The sea state (ramps so far) each of the two state buffers holds."""
        self._spectra = ctx.buffer(reserve=cells * 4 * 8)
        self._work = ctx.buffer(reserve=cells * 4 * 8)
        self._pack["u_dk"] = [tile.dk for tile in ocean.tiles] if tiles > 1 else ocean.tiles[0].dk

    def _slot(self, state: int, keep: int | None) -> int:
        """The state buffer holding ``state``, uploading it into the one not holding ``keep`` if needed."""
        if state in self._held:
            return self._held.index(state)
        slot = 1 if self._held[0] == keep and keep is not None else 0
        self._states[slot].write(self.ocean.spectrum_state(state).tobytes())
        self._held[slot] = state
        return slot

    def run(self, t: float) -> None:
        """The cascades' fields at ``t`` (s) into the layer's textures (mipmaps not built)."""
        before, after, weight = self.ocean.blend(t)
        first = self._slot(before, after)
        second = self._slot(after, before)
        self._states[first].bind_to_storage_buffer(0)
        self._states[second].bind_to_storage_buffer(1)
        self._omega.bind_to_storage_buffer(2)
        self._spectra.bind_to_storage_buffer(3)
        self._pack.update({"u_time": float(t), "u_weight": weight, "u_choppiness": self.ocean.choppiness})
        groups = self._n // GROUP
        self._pack.run(groups, groups, self._tiles)
        self.ctx.memory_barrier()
        self._fft.lines(self._spectra, self._work, rows=True, inverse=True)
        self._fft.lines(self._work, self._spectra, rows=False, inverse=True)
        self._spectra.bind_to_storage_buffer(0)
        self.cascades.fields.bind_to_image(0, read=False, write=True)
        self.cascades.slopes.bind_to_image(1, read=False, write=True)
        self._unpack.run(groups, groups, self._tiles)
        self.ctx.memory_barrier()

    def release(self) -> None:
        for thing in (self._pack, self._fft, self._unpack, self._omega, *self._states, self._spectra, self._work):
            thing.release()
