"""The registry of file formats (RAO tables, mean drift tables, hull and visual meshes, each read by one module),
and the check every reader makes of a path first (:func:`check_file`, with the size limits of :data:`SIZE_LIMITS`).

A :class:`Format` names its reader (and its optional content sniffer) as ``"module:function"``
strings imported on first use, so listing the formats imports no reader and none of their
dependencies. The formats are registered by the packages that read them, on their import:
:mod:`marinesim.vessel` the RAO and drift formats, :mod:`marinesim.hull` the mesh formats; whoever
looks formats up imports the owning package first. A new format is one reader module plus one
``register`` line in its package.

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
MIB = 2**20

SIZE_LIMITS: dict[str, int] = {
    "RAO file": 64 * MIB,  # OrcaFlex YAML, HydroStar .rao, HAMS: a 360-heading, 1000-frequency table is about 8 MB
    "WAMIT report": 256 * MIB,  # .out: a few hundred periods and headings with drift forces stay far below
    "gmsh mesh": 512 * MIB,  # .msh, held whole in memory by meshio: some ten million elements
    "session log": 64 * MIB,  # a day of a busy session is well under 1 MB
    "session log sidecar": MIB,  # a log's is under 2 kB
    "scenario file": MIB,  # TOML: the longest shipped exercise is under 10 kB
    "manoeuvring file": MIB,  # the scenario's side files (TOML): a few dozen lines each
    "mooring file": MIB,
    "station-keeping file": MIB,
    "wind coefficient file": MIB,  # a few hundred rows
}
"""The largest file (bytes) read of each kind, by the name :func:`check_file` is given for it: each is read
whole into memory, so a bigger file is refused before reading rather than exhausting the memory. Kinds not
listed (scenario files, the other RAO and mesh formats) have no limit here."""


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
    symbolic-link loop, a name with a NUL byte; and one larger than the limit :data:`SIZE_LIMITS` gives for
    ``what``, if any. Every reader calls this first: the file is noted as one of the running command's inputs,
    never to be written over (:func:`~marinesim.atomic.note_input`)."""
    try:
        found = os.stat(path)
    except FileNotFoundError:
        raise FileFormatError(path, None, f"no such {what}") from None
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None
    except ValueError:  # os.stat refuses a NUL byte in the name
        raise FileFormatError(repr(str(path)), None, "a file name cannot contain a NUL byte") from None
    if stat.S_ISDIR(found.st_mode):
        raise FileFormatError(path, None, f"is a folder, not a {what}")
    if not stat.S_ISREG(found.st_mode):
        raise FileFormatError(path, None, f"not a regular file (a FIFO or device): give a {what}")
    if found.st_size > SIZE_LIMITS.get(what, found.st_size):
        raise FileFormatError(path, None, f"{_size_text(found.st_size)} is more than the "
                                          f"{_size_text(SIZE_LIMITS[what])} one {what} may have here")
    note_input(path)


def _size_text(size: int) -> str:
    """``size`` (bytes) in words, e.g. ``"70.3 MiB (73,715,302 bytes)"`` (bytes only below 1 MiB)."""
    return f"{size / MIB:.3g} MiB ({size:,} bytes)" if size >= MIB else f"{size:,} bytes"


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
