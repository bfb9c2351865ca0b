"""The registry of file formats: RAO tables and hull/visual meshes, each read by one module.

A :class:`Format` names its reader (and its optional content sniffer) as ``"module:function"``
strings imported on first use, so listing the formats imports no reader and none of their
dependencies. The built-in formats are declared in the table at the end of this module; a new
format is one reader module plus one ``register`` line there.

Reader contracts: an RAO reader is ``reader(path: Path, **options) -> RaoTable`` taking the
keyword options its format declares; a mesh reader is ``reader(path: Path) -> trimesh.Trimesh``
in the file's own units and axes. A sniffer is ``sniffer(head: bytes) -> bool`` on the first
:data:`HEAD_BYTES` bytes of the file.
"""

from __future__ import annotations

import importlib
import os
import stat
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from marinesim.atomic import note_input
from marinesim.errors import FileFormatError, ParameterError

KINDS = {"rao": "RAO", "mesh": "mesh", "drift": "mean drift"}  # kind -> what the messages call a file of that kind
HEAD_BYTES = 4096


@dataclass(frozen=True)
class Format:
    """One file format: what it is, how it is recognised and which function reads it."""

    name: str
    kind: str  # a key of KINDS
    description: str
    extensions: tuple[str, ...]  # lower case, with the dot
    reader: str  # "module:function"
    sniffer: str | None = None  # "module:function" on the file's head bytes; None: by extension only
    options: tuple[str, ...] = ()  # keyword options the reader accepts


_REGISTRY: dict[str, Format] = {}


def register(fmt: Format) -> Format:
    """Add ``fmt``; a name already registered is refused, and within its kind an extension already registered
    unless both formats have a sniffer (their content then tells them apart)."""
    if fmt.kind not in KINDS:
        raise ValueError(f"format {fmt.name!r}: kind must be one of {', '.join(KINDS)}, got {fmt.kind!r}")
    if fmt.name in _REGISTRY:
        raise ValueError(f"format {fmt.name!r} is already registered")
    for other in formats(fmt.kind):
        shared = set(fmt.extensions) & set(other.extensions)
        if shared and not (fmt.sniffer and other.sniffer):
            raise ValueError(f"format {fmt.name!r}: {', '.join(sorted(shared))} already read as {other.name!r} "
                             f"(an extension may be shared only by formats that both sniff their content)")
    _REGISTRY[fmt.name] = fmt
    return fmt


def formats(kind: str | None = None) -> tuple[Format, ...]:
    """The registered formats of ``kind`` (all when None), in registration order."""
    return tuple(f for f in _REGISTRY.values() if kind is None or f.kind == kind)


def extensions(kind: str) -> tuple[str, ...]:
    """Every file extension a format of ``kind`` is recognised by, in registration order."""
    return tuple(extension for f in formats(kind) for extension in f.extensions)


def get(name: str, kind: str) -> Format:
    """The format of ``kind`` called ``name``; :class:`ParameterError` listing the known ones otherwise."""
    fmt = _REGISTRY.get(name)
    if fmt is None or fmt.kind != kind:
        raise ParameterError(f"unknown {KINDS[kind]} format {name!r}; supported: "
                             + ", ".join(f.name for f in formats(kind)))
    return fmt


def detect(path: Path, kind: str, what: str | None = None) -> Format:
    """The format of the file ``path``: by its extension (the sniffers deciding between the formats that share
    it), else by the sniffers on its first bytes.

    :class:`FileFormatError` lists the supported formats when neither decides; ``what`` names the
    file in that message (default: the kind's name, e.g. "RAO"). A path that is not a regular file is
    refused first (:func:`check_file`).
    """
    check_file(path)
    candidates = formats(kind)
    suffix = "".join(path.suffixes[-2:]).lower() if path.suffix.lower() == ".gz" else path.suffix.lower()
    by_extension = [fmt for fmt in candidates if suffix in fmt.extensions]
    if len(by_extension) == 1:
        return by_extension[0]
    if by_extension:
        head = _head(path)
        for fmt in by_extension:
            if _function(fmt.sniffer)(head):
                return fmt
        raise FileFormatError(path, None, f"a {path.suffix} file, but none of "
                              + ", ".join(f"{f.name} ({f.description})" for f in by_extension))
    sniffable = [f for f in candidates if f.sniffer]
    if sniffable:
        head = _head(path)
        for fmt in sniffable:
            if _function(fmt.sniffer)(head):
                return fmt
    tried = " (nor does its content match one)" if sniffable else ""
    raise FileFormatError(path, None, f"unknown {what or KINDS[kind]} format {path.suffix!r}{tried}; supported: "
                          + "; ".join(f"{f.name} ({f.description})" for f in candidates))


def check_file(path: Path, what: str = "file") -> None:
    """Refuse (:class:`FileFormatError`, ``what`` naming the kind of file) a path that is not a regular file
    (after symbolic links): a missing file, a folder, a FIFO or device (reading it could block for ever), a
    symbolic-link loop, a name with a NUL byte. Every reader calls this first: the file is noted as one of
    the running command's inputs, never to be written over (:func:`~marinesim.atomic.note_input`)."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        raise FileFormatError(path, None, f"no such {what}") from None
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None
    except ValueError:  # os.stat refuses a NUL byte in the name
        raise FileFormatError(repr(str(path)), None, "a file name cannot contain a NUL byte") from None
    if stat.S_ISDIR(mode):
        raise FileFormatError(path, None, f"is a folder, not a {what}")
    if not stat.S_ISREG(mode):
        raise FileFormatError(path, None, f"not a regular file (a FIFO or device): give a {what}")
    note_input(path)


def reader(fmt: Format | str) -> Callable:
    """The function that reads files of ``fmt`` (a :class:`Format` or a registered name), imported now."""
    if isinstance(fmt, str):
        fmt = _REGISTRY[fmt]
    return _function(fmt.reader)


def _function(spec: str) -> Callable:
    module, _, name = spec.partition(":")
    return getattr(importlib.import_module(module), name)


def _head(path: Path) -> bytes:
    try:
        with path.open("rb") as handle:
            return handle.read(HEAD_BYTES)
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None


register(Format("wamit", "rao", "WAMIT .4 motion RAOs (numeric output)", (".4",),
                "marinesim.vessel.wamit:read_wamit", "marinesim.vessel.wamit:sniff", options=("ulen", "body")))
register(Format("veres", "rao", "VERES/ShipX .re1 motion transfer functions", (".re1",),
                "marinesim.vessel.veres:read_veres", "marinesim.vessel.veres:sniff"))
register(Format("capytaine", "rao", "Capytaine NetCDF dataset (.nc) with hydrodynamic coefficients", (".nc",),
                "marinesim.vessel.capytaine:read_capytaine", "marinesim.vessel.capytaine:sniff",
                options=("roll_damping", "body", "rigid_body")))
register(Format("native", "rao", "marinesim table (.csv, .txt, .rao; see marinesim/vessel/native.py)",
                (".csv", ".txt", ".rao"), "marinesim.vessel.native:read_native", "marinesim.vessel.native:sniff"))
register(Format("wamit-forces", "rao", "WAMIT .1, .3, .hst and .frc side by side: RAOs solved from forces and mass",
                (".3", ".1", ".hst", ".frc"), "marinesim.vessel.wamit_forces:read_wamit_forces",
                "marinesim.vessel.wamit_forces:sniff", options=("ulen", "rigid_body", "body")))
register(Format("wamit-out", "rao", "WAMIT report (.out, or any name: found by its banner, as other programs "
                "write .out too): its motions, or RAOs solved from its forces and the scenario's mass", (),
                "marinesim.vessel.wamit_out:read_wamit_out",
                "marinesim.vessel.wamit_out:sniff", options=("ulen", "rigid_body")))
register(Format("hydrostar", "rao", "HydroStar/HAMS .rao motion RAOs (one DOF per file, the six side by side)",
                (".rao",), "marinesim.vessel.hydrostar:read_hydrostar", "marinesim.vessel.hydrostar:sniff"))
register(Format("orcaflex", "rao", "OrcaFlex vessel type displacement RAOs (.yml, .yaml)", (".yml", ".yaml"),
                "marinesim.vessel.orcaflex:read_orcaflex", "marinesim.vessel.orcaflex:sniff"))
register(Format("aqwa", "rao", "ANSYS AQWA listing (.lis): position RAOs of structure 1", (".lis",),
                "marinesim.vessel.aqwa:read_aqwa", "marinesim.vessel.aqwa:sniff"))
register(Format("nemoh", "rao", "NEMOH v2/v3 project, given by its Nemoh.cal: Motion/RAO.dat, or RAOs solved from "
                "its forces, coefficients and mass", (".cal",), "marinesim.vessel.nemoh:read_nemoh",
                "marinesim.vessel.nemoh:sniff", options=("rigid_body",)))
register(Format("wamit-drift", "drift", "WAMIT .8 (momentum) or .9 (pressure) mean drift", (".8", ".9"),
                "marinesim.vessel.wamit_drift:read_drift", options=("ulen",)))
register(Format("aqwa-drift", "drift", "ANSYS AQWA listing (.lis): its wave-drift loads of structure 1", (".lis",),
                "marinesim.vessel.aqwa_drift:read_aqwa_drift", options=("axisymmetric",)))
register(Format("nemoh-drift", "drift", "NEMOH v3 QTF module's OUT_QTFM_N.dat (its diagonal)", (".dat",),
                "marinesim.vessel.nemoh_drift:read_nemoh_drift", options=("axisymmetric",)))
register(Format("gdf", "mesh", "WAMIT low-order panels, .gdf", (".gdf",), "marinesim.hull.gdf:read_gdf_mesh"))
register(Format("pnl", "mesh", "HAMS panel mesh, .pnl", (".pnl",), "marinesim.hull.pnl:read_pnl_mesh"))
register(Format("nemoh-mesh", "mesh", "NEMOH mesh, .dat (or Capytaine's .mar)", (".dat", ".mar"),
                "marinesim.hull.nemoh_mesh:read_nemoh_mesh_file", "marinesim.hull.nemoh_mesh:sniff"))
register(Format("gmsh", "mesh", "gmsh mesh, .msh (MSH 2.2 or 4.1): its triangles and quadrangles", (".msh",),
                "marinesim.hull.gmsh_mesh:read_gmsh_mesh"))
register(Format("stl", "mesh", "STL, .stl (or gzipped, .stl.gz)", (".stl", ".stl.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("obj", "mesh", "Wavefront OBJ, .obj (or .obj.gz)", (".obj", ".obj.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("ply", "mesh", "Stanford PLY, .ply (or .ply.gz)", (".ply", ".ply.gz"),
                "marinesim.hull.mesh:read_mesh"))
register(Format("gltf", "mesh", "glTF 2.0, .glb or .gltf", (".glb", ".gltf"), "marinesim.hull.mesh:read_mesh"))
register(Format("off", "mesh", "Object File Format, .off", (".off",), "marinesim.hull.mesh:read_mesh"))
