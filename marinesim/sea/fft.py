"""Batched 2-D inverse FFTs: planned, multithreaded pyfftw, or numpy.fft when pyfftw is absent.

The transform is the unnormalised inverse DFT, ``f[m] = sum_n F[n] exp(+2 pi i n m / N)``,
so a spectrum of complex amplitudes gives the field directly.
"""

from __future__ import annotations

import os

import numpy as np

from marinesim.errors import ParameterError

try:
    import pyfftw
except ImportError:  # pragma: no cover - exercised by the numpy-fallback benchmark
    pyfftw = None

BACKENDS = ("auto", "pyfftw", "numpy")


class InverseFFT2:
    """Inverse 2-D FFT over the last two axes of a fixed-shape complex64 batch.

    Write the spectra into ``.input`` and call the object; the fields are in ``.output``.
    """

    def __init__(self, shape: tuple[int, ...], backend: str = "auto", threads: int | None = None):
        if backend not in BACKENDS:
            raise ParameterError(f"fft backend must be one of {', '.join(BACKENDS)}, got {backend!r}")
        if backend == "pyfftw" and pyfftw is None:
            raise ParameterError("fft backend 'pyfftw' requested but pyfftw is not installed")
        self.backend = "numpy" if backend == "numpy" or pyfftw is None else "pyfftw"
        axes = (len(shape) - 2, len(shape) - 1)
        if self.backend == "pyfftw":
            self.input = pyfftw.empty_aligned(shape, dtype=np.complex64)
            self.output = pyfftw.empty_aligned(shape, dtype=np.complex64)
            self._plan = pyfftw.FFTW(
                self.input, self.output, axes=axes, direction="FFTW_BACKWARD",
                flags=("FFTW_MEASURE",), threads=threads or os.cpu_count() or 1,
            )
        else:
            self.input = np.empty(shape, dtype=np.complex64)
            self.output = np.empty(shape, dtype=np.complex64)
            self._axes = axes
        self.input[...] = 0  # after planning: FFTW_MEASURE overwrites the input

    def __call__(self) -> np.ndarray:
        if self.backend == "pyfftw":
            self._plan.execute()  # raw FFTW: no 1/N^2 normalisation
        else:
            np.fft.ifftn(self.input, axes=self._axes, norm="forward", out=self.output)
        return self.output
