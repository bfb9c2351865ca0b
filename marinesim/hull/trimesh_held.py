"""trimesh, imported with SIGINT and SIGTERM held (:func:`~marinesim.atomic.signals_held`).

trimesh imports its optional modules in ``try/except BaseException``: a Ctrl-C or SIGTERM arriving then was
swallowed and the command ran on; held, it waits until the import is done. The package's modules import
trimesh from here, so that whichever of them is imported first imports it so.
"""

from marinesim.atomic import signals_held

with signals_held():
    import trimesh

__all__ = ["trimesh"]
