"""A disk cache of computed wakes, so that a scenario opens instantly the second time.

The key is a sha256 of everything the field depends on: the hull geometry in the body frame
(so units, axes, draft and trim are in it), the speed, the grid, rho, g, the angular refinement
and CACHE_FORMAT (bumped whenever the numerics change). The folder is ``wake`` in
:func:`~marinesim.cache.cache_root`. Entries are written atomically; an unreadable entry is
recomputed and replaced.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Iterable


from marinesim.cache import cache_root
from marinesim.constants import RHO_SEAWATER, G
from marinesim.errors import FileFormatError
from marinesim.hull import Hull
from marinesim.progress import task
from marinesim.wake.compute import Wake, WakeGrid, compute_wake

CACHE_FORMAT = 2


def cache_dir() -> Path:
    return cache_root() / "wake"


def cache_key(hull: Hull, speed_m_s: float, grid: WakeGrid, rho: float, g: float, refinement: float) -> str:
    parts = {"format": CACHE_FORMAT, "hull": hull.content_hash(), "speed_m_s": float(speed_m_s),
             "grid": [grid.nx, grid.ny, grid.spacing_m, grid.front_m], "rho": float(rho), "g": float(g),
             "refinement": float(refinement)}
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()


def cached_wake(hull: Hull, speed_m_s: float, grid: WakeGrid = WakeGrid(), *, rho: float = RHO_SEAWATER,
                g: float = G, refinement: float = 1.0, folder: Path | None = None) -> tuple[Wake, bool]:
    """The wake from the cache, or computed and stored; and whether it came from the cache."""
    path = (folder or cache_dir()) / f"{cache_key(hull, speed_m_s, grid, rho, g, refinement)}.npz"
    if path.is_file():
        try:
            wake = Wake.load(path)
            wake.info["hull_source"] = hull.source  # the same geometry may come from another file
            return wake, True
        except FileFormatError:
            pass  # a damaged entry: recompute it below
    wake = compute_wake(hull, speed_m_s, grid, rho=rho, g=g, refinement=refinement)
    path.parent.mkdir(parents=True, exist_ok=True)
    wake.save(path)
    return wake, False


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
