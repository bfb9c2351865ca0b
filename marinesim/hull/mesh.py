"""Hull meshes in the body frame: loading, units, axes, draft and trim, and the checks.

A :class:`Hull` is a triangle mesh in metres in the body frame of CONVENTIONS (x forward,
y to port, z up) with the waterline at z = 0 and normals pointing out of the hull. Meshes carry
no units and often another axis convention, so :func:`load_hull` takes them as options and
refuses what cannot be a vessel: an empty or non-finite mesh, nothing below the waterline, a
length no ship has (millimetres read as metres), a hull open below the waterline. What it can
repair (winding that disagrees between faces, normals pointing inwards) it repairs and says so
in ``notes``. Reading a mesh file in any mesh format of :mod:`marinesim.formats` (:func:`load_mesh`) and
placing it in the body frame (:func:`to_body_frame`) are shared with the visual meshes of
:mod:`marinesim.hull.visual`; :func:`read_mesh` is the reader of the formats trimesh reads.
"""

from __future__ import annotations

import contextlib
import gzip
import hashlib
import io
import logging
import math
import warnings
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator

import numpy as np

from marinesim import formats
from marinesim.errors import FileFormatError, ParameterError, require_finite, require_positive
from marinesim.hull.trimesh_held import trimesh
from marinesim.hull.wetted import Surface, wetted_surface
from marinesim.pose import rotation_y

UNITS = {"m": 1.0, "cm": 0.01, "mm": 0.001, "ft": 0.3048, "in": 0.0254}
LENGTH_LIMITS_M = (0.5, 600.0)  # no vessel, model or full scale, lies outside these
MAX_GUNZIPPED_BYTES = 1 << 30
"""Largest mesh a gzipped file may decompress to (bytes)."""
CLOSURE_TOLERANCE = 1e-4  # of the wetted area: about a quarter of one panel of the WAMIT tanker
VOLUME_SPREAD = 1e-3
"""Largest relative difference between the volumes by x, y and z (divergence theorem) of a closed wetted surface:
warped quadrilaterals split into triangles make them differ, as WAMIT's own VOLX and VOLZ do (0.08 % for the
IEA-15 MW semisubmersible's panels, 0.074 % for HAMS's DeepCwind mesh)."""
MODEL_SCALE_BELOW_M = 10.0  # shorter than this: say that it may be a model-scale mesh


@dataclass(frozen=True)
class Hull:
    """A closed (or wetted-surface-only) triangle mesh in the body frame, waterline at z = 0."""

    vertices: np.ndarray  # (n, 3) m
    faces: np.ndarray  # (m, 3) vertex indices, counter-clockwise seen from outside
    source: str
    notes: tuple[str, ...] = ()

    def wetted(self) -> Surface:
        """The wetted surface (z < 0), cut at the waterline."""
        return wetted_surface(self.vertices, self.faces)

    def content_hash(self) -> str:
        """sha256 of the geometry in the body frame (what any result computed from it depends on)."""
        digest = hashlib.sha256()
        digest.update(np.ascontiguousarray(self.vertices, dtype="<f8").tobytes())
        digest.update(np.ascontiguousarray(self.faces, dtype="<i8").tobytes())
        return digest.hexdigest()

    @property
    def overall_length_m(self) -> float:
        return float(np.ptp(self.vertices[:, 0]))


def load_hull(path: str | Path, *, units: str = "m", scale: float = 1.0, axes: str = "x,y,z",
              draft: float | None = None, trim_deg: float = 0.0) -> Hull:
    """Read a hull in any mesh format of :mod:`marinesim.formats` (WAMIT ``.gdf``, STL, OBJ, ...) into the
    body frame.

    ``units`` are the mesh's length units (m, cm, mm, ft, in); ``scale`` the geometric scale of a
    model mesh (50 for a 1:50 model); ``axes`` says which mesh axes become body x, y, z, e.g.
    ``"x,-z,y"`` for a y-up mesh; ``draft`` (m) puts the lowest point of the hull at z = -draft
    (default: the mesh's own z = 0 is the waterline); ``trim_deg`` then rotates the hull about
    the y axis through the origin, bow down positive.
    """
    path, mesh = load_mesh(path, "hull")
    reader_notes = tuple(mesh.metadata.get("notes", ()))
    vertices, faces = np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64)
    vertices, faces = to_body_frame(vertices, faces, path, units=units, scale=scale, axes=axes, what="hull")
    height = float(np.ptp(vertices[:, 2]))  # keel to the top of the mesh
    if draft is not None:
        draft = require_positive("draft", draft)
        if draft > height:
            raise ParameterError(f"draft must be at most the hull's height, keel to top ({height:.4g} m): deeper, "
                                 f"the whole hull is under water; got {draft!r}")
        vertices = vertices - [0.0, 0.0, vertices[:, 2].min() + draft]
    trim = math.radians(require_finite("trim", trim_deg))
    if abs(trim) >= math.radians(30.0):
        raise ParameterError(f"trim must be within +-30 deg, got {trim_deg!r}")
    if trim:
        vertices = vertices @ rotation_y(trim).T
        deepest = -float(vertices[:, 2].min())
        if deepest > height:
            raise ParameterError(f"trim {trim_deg:g} deg puts the keel {deepest:.4g} m deep, deeper than the hull is "
                                 f"high ({height:.4g} m, keel to top): that end's deck would be under water")
    return make_hull(vertices, faces, str(path), reader_notes)


def make_hull(vertices: np.ndarray, faces: np.ndarray, source: str, notes: tuple[str, ...] = ()) -> Hull:
    """Merge duplicate vertices, drop degenerate faces, check and repair; the checked :class:`Hull`."""
    mesh = trimesh.Trimesh(np.asarray(vertices, float), np.asarray(faces, np.int64), process=True)
    mesh.update_faces(mesh.nondegenerate_faces())
    mesh.remove_unreferenced_vertices()
    notes = list(notes)
    if len(mesh.faces) == 0:
        raise FileFormatError(source, None, "the mesh has no faces of non-zero area")
    notes += _shape_notes(mesh)
    if not mesh.is_winding_consistent:
        trimesh.repair.fix_winding(mesh)
        if not mesh.is_winding_consistent:
            raise FileFormatError(source, None, "inconsistent normals that cannot be repaired (faces "
                                  "shared by more than two neighbours or a non-orientable surface)")
        notes.append("faces with winding opposite to their neighbours were flipped")
    zmin, zmax = float(mesh.vertices[:, 2].min()), float(mesh.vertices[:, 2].max())
    if zmin >= 0.0:
        raise ParameterError(f"{source}: nothing below the waterline (z from {zmin:.4g} to {zmax:.4g} m): "
                             "give the draft")
    wet = wetted_surface(mesh.vertices, mesh.faces)
    _check_closed_below_water(wet, source)
    if _displaced_volume(wet) < 0.0:
        mesh.invert()
        notes.append("normals pointed into the hull: all faces were flipped")
    return Hull(np.array(mesh.vertices), np.array(mesh.faces), source, tuple(notes))


def load_mesh(path: str | Path, what: str) -> tuple[Path, trimesh.Trimesh]:
    """``path`` as a :class:`Path` and its mesh, read by the reader of its registered mesh format, in the
    file's own numbers and axes; :class:`FileFormatError` if there is no such file or its format is unknown
    (``what`` names the kind of mesh in the message)."""
    path = Path(path)
    return path, formats.reader(formats.detect(path, "mesh", what))(path)


def read_mesh(path: Path) -> trimesh.Trimesh:
    """The triangles of a file in a format trimesh reads (STL, OBJ, PLY, glTF, OFF; STL, OBJ and PLY also
    gzipped, ``.stl.gz``) as one mesh, in the file's own numbers and axes, with its colours or materials
    (``visual``); scene transforms applied, nothing merged."""
    gzipped = path.suffix.lower() == ".gz"
    source = io.BytesIO(_gunzip(path)) if gzipped else path
    inner = {"file_type": Path(path.stem).suffix.lower().lstrip(".")} if gzipped else {}
    try:
        with _trimesh_quiet():
            mesh = trimesh.load(source, force="mesh", process=False, **inner)
    except Exception as error:  # trimesh raises many types for unreadable files
        raise FileFormatError(path, None, f"cannot read the mesh: {error}") from None
    if not isinstance(mesh, trimesh.Trimesh):
        raise FileFormatError(path, None, "the file holds no triangle mesh")
    return mesh


def _gunzip(path: Path) -> bytes:
    """The decompressed bytes of a gzipped mesh, at most :data:`MAX_GUNZIPPED_BYTES` (refused beyond: a small
    file can expand without limit)."""
    try:
        with gzip.open(path, "rb") as handle:
            data = handle.read(MAX_GUNZIPPED_BYTES + 1)
    except (OSError, EOFError, zlib.error) as error:
        raise FileFormatError(path, None, f"cannot decompress: {error}") from None
    if len(data) > MAX_GUNZIPPED_BYTES:
        raise FileFormatError(path, None, f"decompresses to more than {MAX_GUNZIPPED_BYTES // 2**20} MiB")
    return data


@contextlib.contextmanager
def _trimesh_quiet() -> Iterator[None]:
    """trimesh's log records and warnings held back while it reads a file (it logs tracebacks of what it
    tries and gives up on): a file it cannot read is said once, by the error raised."""
    logger = logging.getLogger("trimesh")
    held = logging.NullHandler()
    logger.addHandler(held)
    propagate, logger.propagate = logger.propagate, False
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            yield
    finally:
        logger.propagate = propagate
        logger.removeHandler(held)


def to_body_frame(vertices: np.ndarray, faces: np.ndarray, path: str | Path, *, units: str = "m",
                  scale: float = 1.0, axes: str = "x,y,z", what: str) -> tuple[np.ndarray, np.ndarray]:
    """A mesh's vertices in metres in the body frame and its faces (reversed if ``axes`` mirror, so that
    they keep their outward side); ``units``, ``scale`` and ``axes`` as in :func:`load_hull`.

    Refuses a mesh with no faces or a non-finite vertex (:class:`FileFormatError` naming ``path``) and a
    length along body x that no vessel has (:class:`ParameterError` naming the units that would fit).
    """
    if len(faces) == 0:
        raise FileFormatError(path, None, "the mesh has no faces")
    if vertices.ndim != 2 or vertices.shape[1] != 3:
        raise FileFormatError(path, None, f"expected vertices of 3 coordinates (x y z), got an array of shape "
                                          f"{vertices.shape}")
    if faces.ndim != 2 or faces.shape[1] != 3 or faces.min() < 0 or faces.max() >= len(vertices):
        raise FileFormatError(path, None, f"expected triangles of 3 indices into the {len(vertices)} vertices")
    if not np.isfinite(vertices).all():
        bad = int(np.flatnonzero(~np.isfinite(vertices).all(axis=1))[0])
        raise FileFormatError(path, None, f"vertex {bad} is not finite: {vertices[bad].tolist()}")
    factor = UNITS.get(units)
    if factor is None:
        raise ParameterError(f"units must be one of {', '.join(UNITS)}, got {units!r}")
    factor *= require_positive("scale", scale)
    vertices, faces = _remap_axes(vertices * factor, faces, axes)
    _check_length(vertices, str(path), factor, what)
    return vertices, faces


def _remap_axes(vertices: np.ndarray, faces: np.ndarray, axes: str) -> tuple[np.ndarray, np.ndarray]:
    """Body coordinates from mesh axes, e.g. ``"x,-z,y"``: body x = mesh x, y = -mesh z, z = mesh y."""
    parts = [p.strip().lower() for p in axes.split(",")]
    names = [p.lstrip("+-") for p in parts]
    if len(parts) != 3 or sorted(names) != ["x", "y", "z"] or any(len(p) - len(n) > 1 for p, n in zip(parts, names)):
        raise ParameterError(f"axes must name each of x, y, z once with an optional sign, e.g. 'x,-z,y'; got {axes!r}")
    matrix = np.zeros((3, 3))
    for row, (part, name) in enumerate(zip(parts, names)):
        matrix[row, "xyz".index(name)] = -1.0 if part.startswith("-") else 1.0
    if np.linalg.det(matrix) < 0:  # a mirror image: keep the normals outward
        faces = faces[:, ::-1]
    return vertices @ matrix.T, faces


def _check_length(vertices: np.ndarray, source: str, factor: float, what: str) -> None:
    """Refuse lengths no vessel has, naming the units (or axes) that would give a plausible one.

    ``factor`` converted the mesh's numbers to metres (units x scale); ``what`` names the mesh (hull, visual mesh).
    """
    extent = np.ptp(vertices, axis=0)
    length = float(extent[0])
    low, high = LENGTH_LIMITS_M
    if low <= length <= high:
        if extent.max() > high:
            raise ParameterError(f"{source}: a {what} {extent.max():.4g} m along body {'xyz'[int(np.argmax(extent))]} "
                                 f"is not a vessel (expected <= {high:g} m)")
        return
    hints = [f"units='{unit}' gives {length / factor * to_m:.4g} m" for unit, to_m in UNITS.items()
             if to_m != factor and MODEL_SCALE_BELOW_M <= length / factor * to_m <= 500.0]
    longest = int(np.argmax(extent))
    if longest != 0 and low <= extent[longest] <= high:
        hints.append(f"the longest side is along body {'xyz'[longest]}: the axes option maps it to x")
    raise ParameterError(f"{source}: a {what} {length:.4g} m long (x) is not a vessel (expected {low:g}..{high:g} m)"
                         + ("; " + "; ".join(hints) if hints else ""))


def _shape_notes(mesh: trimesh.Trimesh) -> list[str]:
    """Warnings for a model-scale mesh and for axes that look swapped."""
    extent = np.ptp(mesh.vertices, axis=0)
    length = float(extent[0])
    notes = []
    if length < MODEL_SCALE_BELOW_M:
        notes.append(f"the hull is {length:.3g} m long: if it is a model, give its scale (e.g. 50 for 1:50)")
    if extent[1] > length or extent[2] > length:
        notes.append(f"the hull is wider ({extent[1]:.3g} m) or deeper ({extent[2]:.3g} m) than it is long "
                     f"({length:.3g} m): is x forward and z up? (axes option)")
    return notes


def _check_closed_below_water(wet: Surface, source: str) -> None:
    """The wetted surface may be open only along the waterline: refuse a hole below it.

    Checked geometrically, so that panel meshes with hanging nodes (common in ``.gdf`` files)
    pass: closed by the waterplane lid, the surface's vector area has no x or y component, and
    the volume by the divergence theorem is the same along each axis (int x n_x = int y n_y =
    int z n_z dS; the lid adds nothing to any of them).
    """
    if len(wet) == 0:
        raise ParameterError(f"{source}: nothing below the waterline: give the draft")
    area = float(wet.areas.sum())
    unbalanced = np.abs(wet.vector_areas.sum(axis=0)[:2])
    volumes = [wet.integral(lambda p, k=k: p[..., k], normal=k) for k in range(3)]
    spread = (max(volumes) - min(volumes)) / max(abs(volumes[2]), 1e-300)
    if unbalanced.max() > CLOSURE_TOLERANCE * area or spread > VOLUME_SPREAD:
        raise FileFormatError(source, None, "the hull is not closed below the waterline (a hole in the mesh, "
                              "or a draft deeper than a wetted-surface-only mesh reaches): the wetted surface's "
                              f"vector area is off by ({unbalanced[0]:.3g}, {unbalanced[1]:.3g}) m^2 in x, y "
                              f"and its volume is {volumes[0]:.4g}, {volumes[1]:.4g}, {volumes[2]:.4g} m^3 "
                              "by x, y, z")


def _displaced_volume(wet: Surface) -> float:
    """Divergence theorem with the waterplane lid at z = 0: V = integral of z n_z dS (exact)."""
    return wet.integral(lambda p: p[..., 2], normal=2)
