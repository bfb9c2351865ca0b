"""HAMS panel meshes (``.pnl``) -> triangles in the body frame.

Layout (HAMS's ``HullMesh.pnl``, as its CertTest inputs are written): a title line; a comment; the line
``NPANELS NNODES XSYM YSYM``; then between ``#Start Definition of Node Coordinates`` and ``#End ...`` one
node per line ``ID X Y Z``; then between ``#Start Definition of Node Relations`` and ``#End ...`` one panel
per line ``ID NVERT V1 V2 V3 [V4]`` (node IDs). ``XSYM = 1`` means only one half about the plane x = 0 is
given, ``YSYM = 1`` the same about y = 0: the missing halves are mirrored here with the vertex order
reversed, so that the normals keep their sense. Like WAMIT's ``.gdf``, a hull mesh describes the wetted
surface, open at the waterline, in the body frame (x forward, z up, the waterline at z = 0), in metres.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from marinesim.errors import FileFormatError
from marinesim.hull.trimesh_held import trimesh
from marinesim.tokens import parse_float, parse_int, read_text

MAX_ITEMS = 2_000_000
"""Most nodes or panels a file may declare (checked before anything is allocated)."""


def read_pnl(path: str | Path) -> tuple[np.ndarray, np.ndarray]:
    """Vertices ``(n, 3)`` and triangles ``(m, 3)`` of the whole (mirrored) surface of a HAMS ``.pnl`` file."""
    path = Path(path)
    lines = read_text(path).splitlines()
    counts = _counts(path, lines)
    panels, nodes, xsym, ysym = counts
    node_lines = _section(path, lines, "NODECOORDINATES", nodes, "node")
    panel_lines = _section(path, lines, "NODERELATIONS", panels, "panel")
    index: dict[int, int] = {}
    vertices = np.empty((nodes, 3))
    for i, (number, parts) in enumerate(node_lines):
        if len(parts) < 4:
            raise FileFormatError(path, number, "expected a node: ID X Y Z")
        node = parse_int(path, number, parts[0], "node ID")
        if node in index:
            raise FileFormatError(path, number, f"node {node} is defined twice")
        index[node] = i
        vertices[i] = [parse_float(path, number, text, name) for text, name in zip(parts[1:4], "XYZ")]
    corners = np.empty((panels, 4), dtype=np.int64)
    for p, (number, parts) in enumerate(panel_lines):
        count = parse_int(path, number, parts[1], "number of vertices (3 or 4)") if len(parts) > 1 else 0
        if count not in (3, 4) or len(parts) < 2 + count:
            raise FileFormatError(path, number, "expected a panel: ID NVERT (3 or 4) and that many node IDs")
        ids = [parse_int(path, number, text, "node ID") for text in parts[2:2 + count]]
        missing = [node for node in ids if node not in index]
        if missing:
            raise FileFormatError(path, number, f"panel uses node {missing[0]}, which the file does not define")
        rows = [index[node] for node in ids]
        corners[p] = rows + rows[-1:] * (4 - count)  # a triangle repeats its last vertex
    for flag, axis in ((xsym, 0), (ysym, 1)):
        if flag:
            image = vertices.copy()
            image[:, axis] *= -1.0
            corners = np.concatenate([corners, corners[:, [0, 3, 2, 1]] + len(vertices)])
            vertices = np.concatenate([vertices, image])
    faces = np.concatenate([corners[:, [0, 1, 2]], corners[:, [0, 2, 3]]])
    return vertices, faces


def read_pnl_mesh(path: Path) -> trimesh.Trimesh:
    """The whole (mirrored) surface of a ``.pnl`` file as a mesh (degenerate triangles are dropped when the
    hull is assembled)."""
    vertices, faces = read_pnl(path)
    return trimesh.Trimesh(vertices, faces, process=False)


def sniff(head: bytes) -> bool:
    """Whether the file's first bytes look like a HAMS mesh."""
    text = head.decode("utf-8", errors="replace")
    return "Mesh File" in text and "Number of Panels" in text


def _squeezed(line: str) -> str:
    return "".join(line.upper().split())


def _counts(path: Path, lines: list[str]) -> tuple[int, int, int, int]:
    """``NPANELS NNODES XSYM YSYM`` from the first line after the ``# Number of Panels`` comment."""
    for number, line in enumerate(lines, 1):
        if _squeezed(line).startswith("#NUMBEROFPANELS"):
            parts = lines[number].split() if number < len(lines) else []
            if len(parts) < 4:
                raise FileFormatError(path, number + 1, "expected NPANELS NNODES XSYM YSYM")
            names = ("number of panels", "number of nodes", "X-symmetry (0 or 1)", "Y-symmetry (0 or 1)")
            panels, nodes, xsym, ysym = (parse_int(path, number + 1, t, n) for t, n in zip(parts, names))
            if not (0 < panels <= MAX_ITEMS and 0 < nodes <= MAX_ITEMS):
                raise FileFormatError(path, number + 1, f"panels and nodes must be 1..{MAX_ITEMS:,}, got "
                                                        f"{panels} and {nodes}")
            if xsym not in (0, 1) or ysym not in (0, 1):
                raise FileFormatError(path, number + 1, f"the symmetry flags must be 0 or 1, got {xsym} {ysym}")
            return panels, nodes, xsym, ysym
    raise FileFormatError(path, None, "no '# Number of Panels, Nodes, X-Symmetry and Y-Symmetry' line")


def _section(path: Path, lines: list[str], name: str, count: int, what: str) -> list[tuple[int, list[str]]]:
    """The ``count`` data lines (line number, fields) between ``#Start Definition of <name>`` and its end."""
    start = next((i for i, line in enumerate(lines) if _squeezed(line).startswith(f"#STARTDEFINITIONOF{name}")),
                 None)
    if start is None:
        raise FileFormatError(path, None, f"no '#Start Definition of {name.title()}' section")
    rows = []
    for number in range(start + 2, len(lines) + 1):
        text = lines[number - 1]
        if _squeezed(text).startswith("#END"):
            break
        if text.strip():
            rows.append((number, text.split()))
        if len(rows) > count:
            raise FileFormatError(path, number, f"more {what}s than the {count} the header declares")
    else:
        raise FileFormatError(path, len(lines), f"the file ends inside the {what} section (no '#End Definition')")
    if len(rows) != count:
        raise FileFormatError(path, number, f"{len(rows)} {what}s where the header declares {count}")
    return rows
