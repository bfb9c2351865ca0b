"""NEMOH meshes (``.dat``, and Capytaine's ``.mar``, the same layout) -> triangles in the body frame.

Layout (NEMOH's solver mesh, as its own verification cases are written): the line ``2 ISYM``; one node per
line ``ID X Y Z`` up to a line ``0 0. 0. 0.``; one panel per line ``N1 N2 N3 N4`` (node IDs; a triangle
repeats a node) up to ``0 0 0 0``. ``ISYM = 1`` means only one half about the plane y = 0 is given: the other
is mirrored here with the vertex order reversed, so that the normals keep their sense. The wetted surface,
open at the waterline, in the body frame (x forward, z up, the waterline at z = 0), in metres.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.hull.trimesh_held import trimesh
from marinesim.tokens import parse_float, parse_int, read_text

MAX_ITEMS = 2_000_000
"""Most nodes or panels a file may hold (a larger file is refused before its arrays are filled)."""


def read_nemoh_mesh(path: str | Path) -> tuple[np.ndarray, np.ndarray]:
    """Vertices ``(n, 3)`` and triangles ``(m, 3)`` of the whole (mirrored) surface of a NEMOH mesh file."""
    path = Path(path)
    lines = read_text(path).splitlines()
    header = lines[0].split() if lines else []
    if len(header) < 2:
        raise FileFormatError(path, 1, "expected '2 ISYM' (a NEMOH mesh's first line)")
    isym = parse_int(path, 1, header[1], "ISYM (0 or 1)")
    if isym not in (0, 1):
        raise FileFormatError(path, 1, f"ISYM must be 0 or 1, got {isym}")
    number = 1
    index: dict[int, int] = {}
    points: list[list[float]] = []
    while True:
        number, parts = _next(path, lines, number, "node (ID X Y Z) or the '0 0. 0. 0.' line ending them")
        node = parse_int(path, number, parts[0], "node ID")
        if node == 0:
            break
        if len(parts) < 4:
            raise FileFormatError(path, number, "expected a node: ID X Y Z")
        if node in index:
            raise FileFormatError(path, number, f"node {node} is defined twice")
        if len(points) >= MAX_ITEMS:
            raise FileFormatError(path, number, f"more than {MAX_ITEMS:,} nodes")
        index[node] = len(points)
        points.append([parse_float(path, number, text, name) for text, name in zip(parts[1:4], "XYZ")])
    panels: list[list[int]] = []
    while True:
        number, parts = _next(path, lines, number, "panel (N1 N2 N3 N4) or the '0 0 0 0' line ending them")
        ids = [parse_int(path, number, text, "node ID") for text in parts[:4]]
        if ids and ids[0] == 0:
            break
        if len(ids) != 4:
            raise FileFormatError(path, number, "expected a panel: four node IDs")
        missing = [node for node in ids if node not in index]
        if missing:
            raise FileFormatError(path, number, f"panel uses node {missing[0]}, which the file does not define")
        if len(panels) >= MAX_ITEMS:
            raise FileFormatError(path, number, f"more than {MAX_ITEMS:,} panels")
        panels.append([index[node] for node in ids])
    if not panels:
        raise FileFormatError(path, number, "no panels")
    vertices, corners = np.array(points), np.array(panels, dtype=np.int64)
    if isym:
        image = vertices.copy()
        image[:, 1] *= -1.0
        corners = np.concatenate([corners, corners[:, [0, 3, 2, 1]] + len(vertices)])
        vertices = np.concatenate([vertices, image])
    return vertices, np.concatenate([corners[:, [0, 1, 2]], corners[:, [0, 2, 3]]])


def read_nemoh_mesh_file(path: Path) -> trimesh.Trimesh:
    """The whole (mirrored) surface of a NEMOH mesh as a mesh (degenerate triangles are dropped when the hull
    is assembled)."""
    vertices, faces = read_nemoh_mesh(path)
    return trimesh.Trimesh(vertices, faces, process=False)


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like a NEMOH mesh: ``2 0|1``, then a node ``1 X Y Z``."""
    lines = head.decode("utf-8", errors="replace").splitlines()
    if len(lines) < 2:
        return False
    first, second = lines[0].split(), lines[1].split()
    return first[:1] == ["2"] and len(first) == 2 and first[1] in ("0", "1") and len(second) == 4 and second[0] == "1"


def _next(path: Path, lines: list[str], number: int, expected: str) -> tuple[int, list[str]]:
    """The next non-blank line after line ``number`` (1-based) and its fields."""
    while number < len(lines):
        number += 1
        parts = lines[number - 1].split()
        if parts:
            return number, parts
    raise FileFormatError(path, number, f"the file ends early: expected a {expected}")
