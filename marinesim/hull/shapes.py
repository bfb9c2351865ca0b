"""Parametric hulls for validation and as samples: the Wigley hull and a box barge.

Wigley hull (Wigley 1934; the standard thin-ship test case): half-breadth

    y = +-Y(x, z),  Y = (B/2) (1 - (2x/L)^2) (1 - (z/T)^2),  -L/2 <= x <= L/2,  -T <= z <= 0,

wall-sided above the waterline up to a freeboard, closed by a flat deck. Its analytic
hydrostatics: V = 4 L B T / 9, A_wp = 2 L B / 3, z_B = -3 T / 8. The sample in ``hulls/`` has
L/B = 10 and B/T = 1.6 (the classic proportions). Both sides are triangulated on the same
(x, z) grid, so the mesh is closed and symmetric.
"""

from __future__ import annotations

import numpy as np

from marinesim.errors import ParameterError, require_at_least, require_positive
from marinesim.hull.mesh import Hull, make_hull
from marinesim.hull.trimesh_held import trimesh


def wigley_half_breadth(x: np.ndarray, z: np.ndarray, length: float, beam: float, draft: float) -> np.ndarray:
    """Y(x, z) of the Wigley hull below the waterline, m (zero outside the hull)."""
    fore_aft = np.clip(1.0 - (2.0 * np.asarray(x) / length) ** 2, 0.0, None)
    vertical = np.clip(1.0 - (np.asarray(z) / draft) ** 2, 0.0, None)
    return 0.5 * beam * fore_aft * vertical


def wigley_hull(length: float = 100.0, beam: float = 10.0, draft: float = 6.25, *, nx: int = 80,
                nz: int = 16, freeboard: float | None = None) -> Hull:
    """A closed Wigley hull: ``nx`` panels along the length, ``nz`` over the draft on each side,
    wall-sided up to ``freeboard`` (default draft / 2) and a deck; quadrilaterals split in two."""
    length, beam, draft = (require_positive(n, v) for n, v in (("length", length), ("beam", beam), ("draft", draft)))
    nx, nz = int(require_at_least("nx", nx, 2)), int(require_at_least("nz", nz, 1))
    freeboard = require_positive("freeboard", draft / 2.0 if freeboard is None else freeboard)
    above = max(1, round(nz * freeboard / draft))
    x = np.linspace(-length / 2.0, length / 2.0, nx + 1)
    z = np.concatenate([np.linspace(-draft, 0.0, nz + 1), np.linspace(0.0, freeboard, above + 1)[1:]])
    X, Z = np.meshgrid(x, z, indexing="ij")
    Y = wigley_half_breadth(X, np.minimum(Z, 0.0), length, beam, draft)
    port = np.stack([X, Y, Z], axis=-1)
    starboard = port * [1.0, -1.0, 1.0]
    rows = len(z)
    index = np.arange((nx + 1) * rows).reshape(nx + 1, rows)
    i, j = index[:-1, :-1].ravel(), index[:-1, 1:].ravel()  # (x_i, z_j) and (x_i, z_j+1)
    k, m = index[1:, 1:].ravel(), index[1:, :-1].ravel()  # (x_i+1, z_j+1) and (x_i+1, z_j)
    offset = index.size
    quads = [np.stack([i, j, k, m], axis=1),  # port: z then x, normal +y
             offset + np.stack([i, m, k, j], axis=1)]  # starboard: x then z, normal -y
    top_port, top_starboard = index[:, -1], offset + index[:, -1]
    quads.append(np.stack([top_starboard[:-1], top_starboard[1:], top_port[1:], top_port[:-1]], axis=1))  # deck, +z
    quads = np.concatenate(quads)
    # split along the diagonal 0-2 aft of midship and 1-3 forward of it: the mesh is then
    # symmetric fore and aft as well as port and starboard (the sides are not planar)
    forward = np.concatenate([np.tile(np.arange(nx)[:, None] >= nx / 2, (1, rows - 1)).ravel()] * 2
                             + [np.arange(nx) >= nx / 2])
    split = np.where(forward[:, None, None], [[0, 1, 3], [1, 2, 3]], [[0, 1, 2], [0, 2, 3]])
    faces = np.take_along_axis(quads[:, None, :], split, axis=2).reshape(-1, 3)
    vertices = np.concatenate([port.reshape(-1, 3), starboard.reshape(-1, 3)])
    return make_hull(vertices, faces, f"wigley L={length:g} B={beam:g} T={draft:g} nx={nx} nz={nz}")


def box_hull(length: float = 100.0, beam: float = 20.0, draft: float = 5.0, depth: float | None = None) -> Hull:
    """A rectangular barge ``length`` x ``beam``, hull ``depth`` deep (default 2 x draft), floating at ``draft``."""
    length, beam, draft = (require_positive(n, v) for n, v in (("length", length), ("beam", beam), ("draft", draft)))
    depth = require_positive("depth", 2.0 * draft if depth is None else depth)
    if depth <= draft:
        raise ParameterError(f"depth must exceed the draft (a freeboard), got depth {depth:g} m, draft {draft:g} m")
    box = trimesh.creation.box(extents=(length, beam, depth))
    vertices = np.asarray(box.vertices) + [0.0, 0.0, depth / 2.0 - draft]
    return make_hull(vertices, np.asarray(box.faces), f"box L={length:g} B={beam:g} T={draft:g} D={depth:g}")
