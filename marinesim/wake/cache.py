"""A disk cache of computed wakes, so that a scenario opens instantly the second time.

The key is a sha256 of everything the field depends on: the hull geometry in the body frame
(so units, axes, draft and trim are in it), the speed, the grid, rho, g, the angular refinement
and WAKE_FORMAT (bumped whenever the numerics change). The folder is ``wake`` in
:func:`~marinesim.cache.cache_root`. Entries are written atomically. An entry is used only if it
is the wake its key names (format, hull, speed, rho, g, refinement, grid, array shapes and axes):
an unreadable or mismatched one is recomputed and replaced. A cache that cannot be written is
warned about once and done without (:func:`~marinesim.cache.store`); the wakes it could not take are kept in the
process instead (the newest :data:`UNSTORED_KEPT`, read-only), so that a command asking twice (a run's pictures, then
its video) computes each once. A kept wake is not offered to the cache again (a disk freed meanwhile stays unused
until the next process), and two threads asking for the same new wake at once both compute it.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import threading
from pathlib import Path
from typing import Iterable

import numpy as np

from marinesim.cache import cache_root, store
from marinesim.constants import RHO_SEAWATER, G
from marinesim.errors import FileFormatError
from marinesim.hull import Hull
from marinesim.progress import task
from marinesim.recent import Newest
from marinesim.wake.compute import WAKE_FORMAT, Wake, WakeGrid, compute_wake


UNSTORED_KEPT = 2
"""Wakes kept in the process where the cache could not store them (about 17 MB each on the default grid: two
2048 x 1024 float32 fields)."""
_unstored: Newest[Path, Wake] = Newest(UNSTORED_KEPT)
"""By the file the cache could not write."""
_unstored_lock = threading.Lock()  # a simulation asks for its wakes on a worker thread


def cache_dir() -> Path:
    return cache_root() / "wake"


def cache_key(hull: Hull, speed_m_s: float, grid: WakeGrid, rho: float, g: float, refinement: float) -> str:
    parts = {"format": WAKE_FORMAT, "hull": hull.content_hash(), "speed_m_s": float(speed_m_s),
             "grid": [grid.nx, grid.ny, grid.spacing_m, grid.front_m], "rho": float(rho), "g": float(g),
             "refinement": float(refinement)}
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()


def cached_wake(hull: Hull, speed_m_s: float, grid: WakeGrid = WakeGrid(), *, rho: float = RHO_SEAWATER,
                g: float = G, refinement: float = 1.0, folder: Path | None = None) -> tuple[Wake, bool]:
    """The wake from the cache (or kept in the process where the cache could not store it), or computed and stored;
    and whether it came from either."""
    path = (folder or cache_dir()) / f"{cache_key(hull, speed_m_s, grid, rho, g, refinement)}.npz"
    with _unstored_lock:
        kept = _unstored.get(path, lambda: None) if path in _unstored else None
    if kept is not None:
        return dataclasses.replace(kept, info={**kept.info, "hull_source": hull.source}, timings={}), True
    if path.is_file():
        try:
            wake = Wake.load(path)
        except FileFormatError:
            wake = None  # a damaged entry: recomputed below
        if wake is not None and _is_entry_of(wake, hull, speed_m_s, grid, rho, g, refinement):
            wake.info["hull_source"] = hull.source  # the same geometry may come from another file
            return wake, True
    wake = compute_wake(hull, speed_m_s, grid, rho=rho, g=g, refinement=refinement)
    if not store(path, wake.save):
        with _unstored_lock:
            _unstored.get(path, lambda: _read_only_copy(wake))
    return wake, False


def _read_only_copy(wake: Wake) -> Wake:
    """``wake`` with copies of its arrays that cannot be written and of its info, and no timings: what the process
    keeps, shared by every later request for it."""
    arrays = {name: getattr(wake, name).copy() for name in ("elevation", "local", "x", "y", "sec", "amplitude")}
    for array in arrays.values():
        array.flags.writeable = False
    return dataclasses.replace(wake, **arrays, info=dict(wake.info), timings={})


def _is_entry_of(wake: Wake, hull: Hull, speed_m_s: float, grid: WakeGrid, rho: float, g: float,
                 refinement: float) -> bool:
    """Whether a loaded entry is the wake of its key: not a damaged file, nor one of another format or input."""
    info = wake.info
    try:
        stored = WakeGrid(**info["grid"])
        if not (info["wake_format"] == WAKE_FORMAT and info["hull_sha256"] == hull.content_hash()
                and info["speed_m_s"] == float(speed_m_s) and info["rho_kg_m3"] == float(rho)
                and info["g_m_s2"] == float(g) and info["refinement"] == float(refinement)
                and (stored.nx, stored.ny) == (int(grid.nx), int(grid.ny))
                and grid.spacing_m in (None, stored.spacing_m) and grid.front_m in (None, stored.front_m)):
            return False
        x, y = stored.axes()
    except (KeyError, TypeError, ValueError):
        return False
    return (wake.elevation.shape == wake.local.shape == (stored.ny, stored.nx)
            and wake.elevation.dtype == wake.local.dtype == np.float32
            and np.array_equal(wake.x, x) and np.array_equal(wake.y, y)
            and wake.sec.ndim == 1 and wake.sec.shape == wake.amplitude.shape
            and bool(np.isfinite(wake.elevation).all()) and bool(np.isfinite(wake.local).all()))


def precompute_wakes(hull: Hull, speeds_m_s: Iterable[float], grid: WakeGrid = WakeGrid(), *,
                     rho: float = RHO_SEAWATER, g: float = G, folder: Path | None = None) -> list[tuple[Wake, bool]]:
    """The wakes of ``hull`` at each speed (m/s), from the cache or computed and stored."""
    speeds = list(speeds_m_s)
    wakes = []
    with task("wakes", len(speeds), "speed") as bar:
        for speed in speeds:
            wakes.append(cached_wake(hull, speed, grid, rho=rho, g=g, folder=folder))
            bar.update(1)
    return wakes
