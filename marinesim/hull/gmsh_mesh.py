"""gmsh meshes (``.msh``: MSH 2.2 and 4.1, ASCII or binary) -> triangles in the file's own numbers, read with
meshio (a well-kept reader of both versions, so none is written here).

A hull from gmsh is its surface: the file's triangles and quadrangles (each quadrangle split along its
first diagonal); points and lines are left out, and a file with only volume elements (tetrahedra,
hexahedra) is refused, naming what it holds. Units, axes and the waterline are as for any hull mesh
(:mod:`marinesim.hull.mesh`).
"""

from __future__ import annotations

import contextlib
import io
import warnings
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.formats import check_file
from marinesim.hull.trimesh_held import trimesh

SURFACE = {"triangle": [[0, 1, 2]], "quad": [[0, 1, 2], [0, 2, 3]]}
"""Surface element types and the triangles of each."""


def read_gmsh_mesh(path: Path) -> trimesh.Trimesh:
    """The surface of a gmsh file as one mesh (vertices as written, faces from its triangles and quads)."""
    import meshio

    path = Path(path)
    check_file(path, "gmsh mesh")
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
            warnings.simplefilter("ignore")
            mesh = meshio.read(path, file_format="gmsh")
    except (Exception, SystemExit) as error:  # meshio raises many types, and exits on some unreadable files
        why = "" if isinstance(error, SystemExit) else str(error).strip() or type(error).__name__
        raise FileFormatError(path, None, "cannot read the gmsh mesh" + (f": {why}" if why else "")) from None
    faces = [block.data[:, split].reshape(-1, 3) for block in mesh.cells if block.type in SURFACE
             for split in [np.array(SURFACE[block.type])]]
    if not faces or not sum(len(f) for f in faces):
        held = ", ".join(sorted({f"{block.type} ({len(block.data)})" for block in mesh.cells})) or "no elements"
        raise FileFormatError(path, None, f"no surface elements (triangles or quadrangles): the file holds {held}; "
                                          "export the hull's surface mesh (gmsh: Mesh > 2D)")
    points = np.asarray(mesh.points, float)
    if points.ndim != 2 or points.shape[1] < 3:
        raise FileFormatError(path, None, "the nodes must have x, y and z")
    faces_all = np.concatenate(faces).astype(np.int64)
    if faces_all.min() < 0 or faces_all.max() >= len(points) or not np.isfinite(points).all():
        raise FileFormatError(path, None, "an element refers to a node the file does not define, or a node is not "
                                          "finite")
    return trimesh.Trimesh(points[:, :3], faces_all, process=False)
