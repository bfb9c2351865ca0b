"""The NumPy reference of the local solver: the numerics of the GPU shaders, in float64 (the transforms scipy.fft's).

Each sub-step: ``u = h + d``; ``Z = FFT(u + i phi)``; ``Z' = A Z + B conj Z(-k)``;
``u + i phi = IFFT Z'``; ``h = u - d``; both fields times the sponge/obstacle factor; non-finite
values zeroed and counted (spectral.py, footprint.py, local.py).
"""

from __future__ import annotations

import numpy as np
import scipy.fft

from marinesim.sea.fft import mirrored
from marinesim.solver.footprint import Placement, displaced_depth, hull_triangles
from marinesim.solver.local import LocalSolver


class ReferenceSolver(LocalSolver):
    """The local solver on the CPU (slow; the definition the GPU solver is tested against)."""

    def _setup(self) -> None:
        n = self.config.size
        self._z = np.zeros((n, n), dtype=complex)     # h + i phi
        self._depth = np.zeros((n, n))
        self._nonfinite = 0

    def _set_keep(self, keep: np.ndarray) -> None:
        self._keep = keep

    def _depth_of(self, placements: list[Placement] | None) -> np.ndarray:
        if placements is None:
            return np.zeros_like(self._depth)
        return displaced_depth(hull_triangles(self.hull, placements), self.config.size)

    def _start_at_rest(self, placements: list[Placement]) -> None:
        self._depth = self._depth_of(placements)
        self._z = -self._depth * self._keep + 0j

    def _advance(self, placements: list[Placement] | None) -> None:
        a, b = self.coefficients
        self._depth = self._depth_of(placements)
        spectrum = scipy.fft.fft2(self._z + self._depth)
        z = scipy.fft.ifft2(a * spectrum + b * np.conj(mirrored(spectrum)))
        z = (z - self._depth) * self._keep
        bad = ~np.isfinite(z)  # a complex value is finite where both its parts are
        if bad.any():
            z[bad] = 0.0
            self._nonfinite += int(bad.sum())
        self._z = z

    def _shift(self, shift: tuple[int, int]) -> None:
        di, dj = shift
        n = self.config.size
        moved = np.zeros_like(self._z)
        rows, cols = slice(max(0, -dj), min(n, n - dj)), slice(max(0, -di), min(n, n - di))
        moved[rows, cols] = self._z[rows.start + dj:rows.stop + dj, cols.start + di:cols.stop + di]
        self._z = moved

    def _clear(self) -> None:
        self._z[:] = 0.0

    def _write(self, h: np.ndarray, phi: np.ndarray) -> None:
        self._z = h + 1j * phi

    def _take_nonfinite(self) -> int:
        bad, self._nonfinite = self._nonfinite, 0
        return bad

    def fields(self) -> tuple[np.ndarray, np.ndarray]:
        return self._z.real.copy(), self._z.imag.copy()

    @property
    def depth(self) -> np.ndarray:
        """Displaced depth of the last sub-step (m)."""
        return self._depth.copy()
