"""trimesh, imported when first used, with SIGINT and SIGTERM held (:func:`~marinesim.atomic.signals_held`).

trimesh imports its optional modules in ``try/except BaseException``: a Ctrl-C or SIGTERM arriving then was
swallowed and the command ran on; held, it waits until the import is done. The package's modules use trimesh
through :data:`trimesh` here, so that whichever of them uses it first imports it so. Its import (a third of a
second, with networkx and scipy.spatial) waits for a command that reads or builds a mesh.
"""

from __future__ import annotations

import functools
from types import ModuleType

from marinesim.atomic import signals_held


@functools.cache
def _imported() -> ModuleType:
    with signals_held():
        import trimesh
    return trimesh


class _Trimesh:
    """The trimesh module, imported at the first attribute asked of it."""

    def __getattr__(self, name: str) -> object:
        return getattr(_imported(), name)


trimesh = _Trimesh()

__all__ = ["trimesh"]
