"""Batched 2-D inverse FFTs: planned, multithreaded pyfftw, or numpy.fft when pyfftw is absent.

The transform is the unnormalised inverse DFT, ``f[m] = sum_n F[n] exp(+2 pi i n m / N)``,
so a spectrum of complex amplitudes gives the field directly.

FFTW_MEASURE picks its algorithm by timing candidates, so two runs could pick different ones
and round differently. The plans are therefore kept as FFTW wisdom in
``fftw-wisdom.json`` under :func:`~marinesim.cache.cache_root`: every run after the first
plans exactly as the first did, and the same scenario and seed give the same bits. Where the
cache cannot be written, the plans are made afresh in every run (warned about once).
:meth:`InverseFFT2.reproducible` is the same transform by numpy.fft: the same bits whatever the saved plans
and the number of threads, for what is written to files.
"""

from __future__ import annotations

import contextlib
import functools
import json
import os
from pathlib import Path
from types import ModuleType

import numpy as np

from marinesim.atomic import atomic_path, signals_held
from marinesim.cache import cache_root, store
from marinesim.errors import ParameterError

BACKENDS = ("auto", "pyfftw", "numpy")
_WISDOM_KINDS = ("double", "single", "long double")
_wisdom_read = False


@functools.cache
def _pyfftw() -> ModuleType | None:
    """pyfftw, imported when first planned (it imports dask.array where dask is installed: 0.6 s that a command
    without a CPU-synthesised sea does not wait for) with Ctrl-C held as the command's first imports are, or None
    where it is not installed."""
    try:
        with signals_held():
            import pyfftw
    except ImportError:  # pragma: no cover - exercised by the numpy-fallback benchmark
        return None
    return pyfftw


def _wisdom_file() -> Path:
    return cache_root() / "fftw-wisdom.json"


def _read_wisdom() -> None:
    """Import the saved plans once per process (an unreadable file is ignored and replaced)."""
    global _wisdom_read
    if _wisdom_read:
        return
    _wisdom_read = True
    with contextlib.suppress(OSError, ValueError, KeyError, TypeError):
        saved = json.loads(_wisdom_file().read_text())
        _pyfftw().import_wisdom(tuple(saved[kind].encode("ascii") for kind in _WISDOM_KINDS))


def _save_wisdom() -> None:
    """Store the plans made so far if they differ from the saved ones (atomically; warned about if unwritable)."""
    wisdom = {kind: blob.decode("ascii") for kind, blob in zip(_WISDOM_KINDS, _pyfftw().export_wisdom(), strict=True)}
    path = _wisdom_file()
    with contextlib.suppress(OSError, ValueError):
        if json.loads(path.read_text()) == wisdom:
            return

    def save(path: Path) -> None:
        with atomic_path(path) as temp:
            temp.write_text(json.dumps(wisdom))
    store(path, save)


def available_cpus() -> list[int]:
    """The CPUs this process may run on (all of them where the OS cannot say)."""
    if hasattr(os, "sched_getaffinity"):
        return sorted(os.sched_getaffinity(0))
    return list(range(os.cpu_count() or 1))


class InverseFFT2:
    """Inverse 2-D FFT over the last two axes of a fixed-shape complex64 batch.

    Write the spectra into ``.input`` and call the object; the fields are in ``.output``.
    """

    def __init__(self, shape: tuple[int, ...], backend: str = "auto", threads: int | None = None):
        if backend not in BACKENDS:
            raise ParameterError(f"fft backend must be one of {', '.join(BACKENDS)}, got {backend!r}")
        pyfftw = None if backend == "numpy" else _pyfftw()
        if backend == "pyfftw" and pyfftw is None:
            raise ParameterError("fft backend 'pyfftw' requested but pyfftw is not installed")
        self.backend = "numpy" if pyfftw is None else "pyfftw"
        axes = self._axes = (len(shape) - 2, len(shape) - 1)
        if self.backend == "pyfftw":
            self.input = pyfftw.empty_aligned(shape, dtype=np.complex64)
            self.output = pyfftw.empty_aligned(shape, dtype=np.complex64)
            _read_wisdom()
            self._plan = pyfftw.FFTW(
                self.input, self.output, axes=axes, direction="FFTW_BACKWARD",
                flags=("FFTW_MEASURE",), threads=threads or len(available_cpus()),
            )
            _save_wisdom()
        else:
            self.input = np.empty(shape, dtype=np.complex64)
            self.output = np.empty(shape, dtype=np.complex64)
        self.input[...] = 0  # after planning: FFTW_MEASURE overwrites the input

    def __call__(self) -> np.ndarray:
        if self.backend == "pyfftw":
            self._plan.execute()  # raw FFTW: no 1/N^2 normalisation
            return self.output
        return self.reproducible()

    def reproducible(self) -> np.ndarray:
        """The transform by numpy.fft, into ``.output``: the same bits on every run, slower than FFTW."""
        np.fft.ifftn(self.input, axes=self._axes, norm="forward", out=self.output)
        return self.output


def mirrored(field: np.ndarray) -> np.ndarray:
    """``field(-k)`` for fields in FFT index order on their last two axes (index ``-i`` is ``(n - i) % n``: index 0
    stays, the others reversed)."""
    out = np.empty_like(field)
    out[..., :1, :1] = field[..., :1, :1]
    out[..., :1, 1:] = field[..., :1, :0:-1]
    out[..., 1:, :1] = field[..., :0:-1, :1]
    out[..., 1:, 1:] = field[..., :0:-1, :0:-1]
    return out
