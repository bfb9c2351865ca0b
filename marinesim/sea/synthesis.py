"""One lane of the ocean's per-frame synthesis: a run of tiles, their spectra, FFTs and Jacobians.

The ocean splits its tiles into lanes, one per worker thread (:func:`lane_workers`), so that the
lanes run at the same time on different CPUs. A lane owns its FFT buffers: the lanes never write
the same memory, so the fields do not depend on the threads' timing.

Packing per tile (see :data:`~marinesim.sea.ocean.FIELD_PAIRS`): transform 0 holds the height
and ``dDx/dy``, transform 3 holds ``1 + dDx/dx`` and ``1 + dDy/dy``; the ones come from the
constant ``1 + i`` in its DC cell, which no wave uses, so the Jacobian is
``J = (1 + dDx/dx)(1 + dDy/dy) - (dDx/dy)^2`` of two transforms' outputs.

The work around the FFT is two compiled loops (numba, GIL released): :func:`_pack_cells` turns
the cosine and sine of every cell's phase into its four packed spectra, written straight into
the FFT's input, and :func:`_jacobian` reads the Jacobian off the outputs in one pass. The
cosines and sines stay numpy's, which are vectorised.
"""

from __future__ import annotations

import contextlib
import math
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from marinesim.compiled import compiled
from marinesim.sea.fft import InverseFFT2, available_cpus


@compiled
def _pack_cells(even: np.ndarray, odd: np.ndarray, cos: np.ndarray, sin: np.ndarray, multipliers: np.ndarray,
                index: np.ndarray, plane: int, flat_input: np.ndarray) -> None:
    """``C[q] = even cos(wt) + odd sin(wt)`` for the ``h`` representatives, ``C[-q] = conj(C[q])``
    for their mirrors, each times its four ``multipliers`` (4, 2h) and written at ``index``
    (2h, the cell in transform 0) ``+ j plane`` of ``flat_input``."""
    h = even.size
    for c in range(h):
        spectrum = even[c] * cos[c] + odd[c] * sin[c]
        mirrored = np.conj(spectrum)
        here, there = index[c], index[h + c]
        for j in range(4):
            flat_input[here + j * plane] = multipliers[j, c] * spectrum
            flat_input[there + j * plane] = multipliers[j, h + c] * mirrored


@compiled
def _jacobian(out: np.ndarray, jacobian: np.ndarray) -> None:
    """``J = Re(out3) Im(out3) - Im(out0)^2`` per tile of the FFT outputs ``(tiles, 4, N, N)``."""
    for t in range(out.shape[0]):
        for iy in range(out.shape[2]):
            for ix in range(out.shape[3]):
                stretch = out[t, 3, iy, ix]
                shear = out[t, 0, iy, ix].imag
                jacobian[t, iy, ix] = stretch.real * stretch.imag - shear * shear


class Lane:
    """The tiles ``first .. first + count - 1`` of ``resolution``^2, synthesised by one thread.

    The FFT is planned once; :meth:`set_cells` gives the lane its wave cells (again when a
    sea-state ramp adds cells) and :meth:`set_multipliers` new packing multipliers.
    """

    def __init__(self, first: int, count: int, resolution: int, fft_backend: str, threads: int) -> None:
        n = resolution
        self.first, self.count, self._n = first, count, n
        self._fft = InverseFFT2((count, 4, n, n), fft_backend, threads)
        self._flat_input = self._fft.input.reshape(-1)  # a view: the FFT reads what is written here
        self._jacobian = np.empty((count, n, n), dtype=np.float32)

    def set_cells(self, omega: np.ndarray, multipliers: np.ndarray, tile: np.ndarray, offsets: np.ndarray) -> None:
        """The lane's cells: representatives ``q`` (their ``omega``, rad/s), then their mirrors
        ``-q`` in the same order; for all of them the packing ``multipliers`` (4, cells), the tile
        relative to ``first`` and the flat index into the tile's ``N x N`` field."""
        n = self._n
        outside = (tile < 0) | (tile >= self.count) | (offsets < 0) | (offsets >= n * n)
        if tile.size != 2 * omega.size or outside.any():
            raise ValueError("lane cells outside the lane's tiles")  # _pack_cells does not check its writes
        self._omega = omega
        self.set_multipliers(multipliers)
        self._index = tile * 4 * n * n + offsets
        self._fft.input[...] = 0.0
        self._fft.input[:, 3, 0, 0] = 1.0 + 1.0j  # the ones of (1 + dDx/dx) + i (1 + dDy/dy)
        self._phase = np.empty(omega.size)
        self._cos = np.empty(omega.size, dtype=np.float32)
        self._sin = np.empty(omega.size, dtype=np.float32)

    def set_multipliers(self, multipliers: np.ndarray) -> None:
        """New packing multipliers (4, cells), as in :meth:`set_cells` (a new choppiness)."""
        cells = 2 * self._omega.size
        if multipliers.shape != (4, cells):
            raise ValueError(f"expected packing multipliers of shape (4, {cells}), got {multipliers.shape}")
        self._multipliers = np.ascontiguousarray(multipliers, dtype=np.complex64)  # one compiled layout

    def run(self, t: float, even: np.ndarray, odd: np.ndarray,
            reproducible: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """The FFT outputs ``(count, 4, N, N)`` and Jacobians ``(count, N, N)`` at ``t`` (s).

        ``even`` and ``odd`` are ``(a[-q] + conj(a[q])) / 2`` and ``i (a[-q] - conj(a[q])) / 2`` of
        the lane's cells, so that ``C[q] = even cos(wt) + odd sin(wt)``. ``reproducible``: by
        numpy.fft (:meth:`InverseFFT2.reproducible`), the same bits whatever the cache and the CPUs.
        """
        phase = np.multiply(self._omega, t, out=self._phase)
        phase -= np.floor(phase * (0.5 / math.pi)) * (2.0 * math.pi)  # keeps float32 trig exact
        phase32 = phase.astype(np.float32)
        _pack_cells(even, odd, np.cos(phase32, out=self._cos), np.sin(phase32, out=self._sin), self._multipliers,
                    self._index, self._n**2, self._flat_input)
        out = self._fft.reproducible() if reproducible else self._fft()
        _jacobian(out, self._jacobian)
        return out, self._jacobian


def lane_workers(count: int) -> list[ThreadPoolExecutor]:
    """One single-thread executor per lane, each pinned where the OS allows: to a block of CPUs
    of its own (its FFT's threads inherit it), or round robin if there are more lanes than CPUs.

    Unpinned, the lanes run one after the other in most frames: a viewer asks for the fields
    once per frame, the workers sleep in between, and on a 2-CPU machine the scheduler wakes
    both lanes' threads on one CPU and leaves the other idle for milliseconds (in a 60 Hz loop,
    5.8-6.3 ms an update unpinned against 3.7 ms pinned: benchmarks/RESULTS.md). The blocks
    are the same for every ocean: two oceans updating at the same time share them.
    """
    cpus = available_cpus()
    if count <= len(cpus):
        blocks = [{int(cpu) for cpu in block} for block in np.array_split(cpus, count)]
    else:
        blocks = [{cpus[i % len(cpus)]} for i in range(count)]
    return [ThreadPoolExecutor(1, thread_name_prefix=f"ocean-lane-{i}", initializer=_pin_to, initargs=(block,))
            for i, block in enumerate(blocks)]


def _pin_to(cpus: set[int]) -> None:
    """Pin the calling thread to ``cpus`` (nothing where the OS does not allow it)."""
    with contextlib.suppress(AttributeError, OSError):
        os.sched_setaffinity(0, cpus)
