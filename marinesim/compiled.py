"""The one way loops over components and time steps, and the few small functions a run calls a million times (a
ship's accelerations, a point's rotation, the DP computer's cycle), are compiled: numba, the GIL released, the machine
code cached on disk beside the module (or, where numba finds no writable place for it, compiled afresh in every
process)."""

from __future__ import annotations

from collections.abc import Callable

import numba
import numpy as np


def compiled(function: Callable | None = None, *, parallel: bool = False) -> Callable:
    """``function`` compiled (``@compiled``, or ``@compiled(parallel=True)`` for a ``numba.prange`` loop on every
    core)."""
    if function is None:
        return lambda f: compiled(f, parallel=parallel)
    try:
        return numba.njit(nogil=True, cache=True, parallel=parallel)(function)
    except RuntimeError:
        return numba.njit(nogil=True, parallel=parallel)(function)


def read_only(*arrays: np.ndarray) -> tuple[np.ndarray, ...]:
    """``arrays``, made read-only: the constants a compiled function is handed, each of one type (numba compiles a
    function once per read-only-ness of its arrays)."""
    for array in arrays:
        array.flags.writeable = False
    return arrays
