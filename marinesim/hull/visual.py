"""Visual meshes: what is drawn of the vessel when it is not the hydrodynamic hull.

A visual mesh (a CAD model with its superstructure and colours) is placed in the body frame of
CONVENTIONS (x forward, y to port, z up, m) like a hull, by its units, scale and axes, and then
moved by an offset: where the mesh's origin lies in the body frame. It is never used for
hydrodynamics, so it is not checked as a hull: it may be open, self-intersecting or lie mostly
above the waterline. What cannot be a vessel is still refused (no file, an unknown format, no
faces, a non-finite vertex, a length no vessel has). Faces are drawn one-sided, counter-clockwise
seen from outside (the glTF convention).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.errors import ParameterError, require_finite
from marinesim.hull.mesh import load_mesh, to_body_frame
from marinesim.hull.trimesh_held import trimesh


@dataclass(frozen=True)
class VisualMesh:
    """A triangle mesh to draw, in the body frame (m), with its own colours if the file has any."""

    vertices: np.ndarray  # (n, 3) m, body frame
    faces: np.ndarray  # (m, 3) vertex indices, counter-clockwise seen from outside
    colours: np.ndarray | None  # (m, 3, 3) RGB 0..1 per face corner; None: the file has no colours
    source: str


def load_visual_mesh(path: str | Path, *, units: str = "m", scale: float = 1.0, axes: str = "x,y,z",
                     offset: Sequence[float] = (0.0, 0.0, 0.0)) -> VisualMesh:
    """Read a visual mesh in any mesh format of :mod:`marinesim.formats` (glTF, STL, OBJ, ...) into the body frame.

    ``units``, ``scale`` and ``axes`` mean what they mean for :func:`~marinesim.hull.load_hull`;
    ``offset`` (m) is where the mesh's origin lies in the body frame after them.
    """
    shift = np.array([require_finite("offset", value) for value in offset])
    if shift.shape != (3,):
        raise ParameterError(f"offset must be [x, y, z] in metres (body frame), got {list(offset)!r}")
    path, mesh = load_mesh(path, "visual mesh")
    vertices, faces = to_body_frame(np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64), path,
                                    units=units, scale=scale, axes=axes, what="visual mesh")
    return VisualMesh(vertices + shift, faces, _corner_colours(mesh.visual, faces), str(path))


def _corner_colours(visual: trimesh.visual.ColorVisuals | trimesh.visual.TextureVisuals,
                    faces: np.ndarray) -> np.ndarray | None:
    """RGB 0..1 per corner of ``faces`` (m, 3, 3): the file's vertex or face colours, or its material's
    (the texture at each vertex, else the main colour); None when the file has no colours."""
    if visual.kind == "texture":
        visual = visual.to_color()
    if visual.kind == "vertex":
        rgba = np.asarray(visual.vertex_colors)[faces]
    elif visual.kind == "face":
        rgba = np.repeat(np.asarray(visual.face_colors)[:, None, :], 3, axis=1)
    else:
        return None
    return rgba[..., :3] / 255.0
