"""WAMIT low-order geometry files (``.gdf``) -> triangles in the body frame.

Layout (WAMIT User Manual, section 6.1): a title line; ``ULEN GRAV``; ``ISX ISY``; ``NPAN``;
then ``NPAN`` panels of four vertices ``X Y Z`` each, in free format (as meshers write them, possibly
with the panel's number after its fourth vertex, and a closing ``NPAND`` line of 0 dipole panels). Vertices are ordered
counter-clockwise seen from the fluid, so the right-hand normal points out of the body
(CONVENTIONS: x forward, z up, the waterline at z = 0, lengths in the file's units, usually m).
A panel with two equal vertices is a triangle. ``ISX = 1`` means only the half ``x >= 0`` is
given (the plane x = 0 is a plane of symmetry), ``ISY = 1`` the same for ``y = 0``; the missing
halves are mirrored here, with the vertex order reversed so that the normals stay outward.
Low-order ``.gdf`` files describe the wetted surface only: they are open at the waterline.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.hull.trimesh_held import trimesh
from marinesim.hull.wamit_pot import placement
from marinesim.tokens import Tokens, by_content, parse_float, parse_int, read_text


@dataclass(frozen=True)
class GdfHeader:
    ulen: float  # m, WAMIT's length scale (rotational RAOs are per A / ULEN)
    g: float  # m/s^2
    isx: int  # 1: x = 0 is a plane of symmetry
    isy: int  # 1: y = 0 is a plane of symmetry


def read_gdf_header(path: str | Path) -> GdfHeader:
    """ULEN, GRAV, ISX and ISY of a ``.gdf`` file."""
    path = Path(path)
    return _header(path, read_text(path).splitlines())


@by_content
def read_gdf(path: str | Path) -> tuple[GdfHeader, np.ndarray, np.ndarray]:
    """The header, vertices ``(n, 3)`` and triangles ``(m, 3)`` of the whole (mirrored) surface."""
    path = Path(path)
    lines = read_text(path).splitlines()
    header = _header(path, lines)
    count = _leading(path, lines, 4, ["NPAN (number of panels)"], parse_int)[0]
    if count <= 0:
        raise FileFormatError(path, 4, f"NPAN must be > 0, got {count}")
    last = max((i for i, line in enumerate(lines) if line.strip()), default=0)
    if last >= 4 and "NPAND" in lines[last].upper():  # WAMIT v7's closing line: the number of dipole panels
        if parse_int(path, last + 1, lines[last].split()[0], "NPAND (number of dipole panels)") != 0:
            raise FileFormatError(path, last + 1, "NPAND > 0: dipole panels (thin plates) are not read")
        lines = lines[:last]
    tokens = Tokens(path, lines, start=4)
    if 12 * count > tokens.remaining:  # refused before the panels are allocated
        raise FileFormatError(path, 4, f"file ends early: expected {12 * count} numbers for NPAN {count} panels "
                                       f"(X Y Z of 4 vertices each), the file holds {tokens.remaining}")
    numbered = tokens.remaining == 13 * count  # a panel number after each fourth vertex
    corners = np.empty((count, 4, 3))
    for p in range(count):
        for v in range(4):
            for axis, name in enumerate("XYZ"):
                corners[p, v, axis] = tokens.float(f"{name} of vertex {v + 1} of panel {p + 1} (of {count})")
        if numbered:
            tokens.int(f"the number of panel {p + 1}")
    if not tokens.at_end():
        raise FileFormatError(path, tokens.line, f"unexpected data after the {count} panels of NPAN")
    if header.isx:
        corners = np.concatenate([corners, _mirror(corners, axis=0)])
    if header.isy:
        corners = np.concatenate([corners, _mirror(corners, axis=1)])
    # each quadrilateral 0-1-2-3 becomes the triangles 0-1-2 and 0-2-3 (a repeated vertex
    # makes one of them degenerate; those are dropped when the hull is assembled)
    vertices = corners.reshape(-1, 3)
    first = 4 * np.arange(len(corners))[:, None]
    faces = np.concatenate([first + [0, 1, 2], first + [0, 2, 3]])
    return header, vertices, faces


def read_gdf_mesh(path: Path) -> trimesh.Trimesh:
    """The whole (mirrored) surface of a ``.gdf`` file as a mesh, vertices and faces as :func:`read_gdf` gives them,
    moved up by ``ZBODY`` (down where it is negative) where the run's ``.pot`` places the body origin off the free
    surface (:func:`marinesim.hull.wamit_pot.placement`: the ``.pot`` of the same name, or the one that names this
    file among its bodies); its horizontal offset and angle place the body in WAMIT's global frame only, and the
    hull stays in its own."""
    _, vertices, faces = read_gdf(path)
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    placed = placement(path)
    if placed is not None and placed[2].xbody[2] != 0.0:
        pot, n, body = placed
        z = body.xbody[2]
        mesh.vertices = mesh.vertices + [0.0, 0.0, z]
        side, moved = ("below", "lowered") if z < 0.0 else ("above", "raised")
        mesh.metadata["notes"] = (f"{pot.name}: body {n}, ZBODY {z:g} m, the body origin {abs(z):g} m {side} the "
                                  f"free surface: the hull {moved} by {abs(z):g} m, so the free surface is its z = 0",)
    return mesh


def _header(path: Path, lines: list[str]) -> GdfHeader:
    """Lines 2 and 3: ``ULEN GRAV`` and ``ISX ISY``, each possibly followed by a comment."""
    ulen, g = _leading(path, lines, 2, ["ULEN (length scale, m)", "GRAV (m/s^2)"], parse_float)
    if ulen <= 0 or g <= 0:
        raise FileFormatError(path, 2, f"ULEN and GRAV must be > 0, got {ulen:g} {g:g}")
    isx, isy = _leading(path, lines, 3, ["ISX (0 or 1)", "ISY (0 or 1)"], parse_int)
    for name, value in (("ISX", isx), ("ISY", isy)):
        if value not in (0, 1):
            raise FileFormatError(path, 3, f"{name} must be 0 or 1, got {value}")
    return GdfHeader(ulen, g, isx, isy)


def _leading(path: Path, lines: list[str], number: int, names: list[str], parse) -> list:
    """The first ``len(names)`` values on line ``number`` (1-based); the rest of the line is a comment."""
    parts = lines[number - 1].split() if len(lines) >= number else []
    if len(parts) < len(names):
        raise FileFormatError(path, number, "expected " + " ".join(names))
    return [parse(path, number, text, name) for text, name in zip(parts, names)]


def _mirror(corners: np.ndarray, axis: int) -> np.ndarray:
    """Panels reflected in the plane ``axis = 0``, vertex order reversed (normals stay outward)
    as 0-3-2-1, so that a non-planar panel is split along the same diagonal 0-2 as its image."""
    mirrored = corners[:, [0, 3, 2, 1]].copy()
    mirrored[..., axis] *= -1.0
    return mirrored
