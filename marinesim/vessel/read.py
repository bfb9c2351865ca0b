"""One entry point for RAO files: the format from the extension, else from the content."""

from __future__ import annotations

from pathlib import Path

from marinesim.errors import FileFormatError, ParameterError
from marinesim.vessel.capytaine import read_capytaine
from marinesim.vessel.native import read_native
from marinesim.vessel.rao import RaoTable
from marinesim.vessel.veres import MAGIC, read_veres
from marinesim.vessel.wamit import read_wamit

FORMATS = {
    "wamit": "WAMIT .4 motion RAOs (numeric output)",
    "veres": "VERES/ShipX .re1 motion transfer functions",
    "capytaine": "Capytaine NetCDF dataset (.nc) with hydrodynamic coefficients",
    "native": "marinesim table (.csv, .txt, .rao; see marinesim/vessel/native.py)",
}
EXTENSIONS = {".4": "wamit", ".re1": "veres", ".nc": "capytaine", ".csv": "native", ".txt": "native",
              ".rao": "native"}


def detect_format(path: Path) -> str:
    """The format of ``path``: by extension, else by sniffing its first bytes."""
    by_extension = EXTENSIONS.get(path.suffix.lower())
    if by_extension:
        return by_extension
    try:
        with path.open("rb") as handle:
            head = handle.read(4096)
    except FileNotFoundError:
        raise FileFormatError(path, None, "no such file") from None
    except OSError as error:
        raise FileFormatError(path, None, f"cannot read: {error.strerror}") from None
    if head.startswith((b"\x89HDF", b"CDF")):
        return "capytaine"
    text = head.decode("utf-8", errors="replace")
    if MAGIC in text.upper():
        return "veres"
    first = next((line for line in text.splitlines() if line.strip()), "")
    if len(first.split()) == 7 and _numbers(first.split()):
        return "wamit"
    if any("heading_deg" in line and "_phase_deg" in line for line in text.splitlines()):
        return "native"
    raise FileFormatError(path, None, "unknown RAO format; supported: "
                          + "; ".join(f"{name} ({what})" for name, what in FORMATS.items()))


def read_rao(path: str | Path, *, ulen: float | None = None, roll_damping: float = 0.0,
             file_format: str | None = None) -> RaoTable:
    """Read any supported RAO file into the internal convention (docs/CONVENTIONS.md).

    ``ulen`` overrides WAMIT's length scale; ``roll_damping`` (fraction of critical) applies to
    Capytaine datasets, whose RAOs are solved here.
    """
    path = Path(path)
    kind = file_format or detect_format(path)
    if kind not in FORMATS:
        raise ParameterError(f"unknown RAO format {kind!r}; supported: {', '.join(FORMATS)}")
    if ulen is not None and kind != "wamit":
        raise ParameterError(f"ULEN applies to WAMIT files only, not {kind}")
    if roll_damping and kind != "capytaine":
        raise ParameterError(f"extra roll damping applies to Capytaine datasets only (their RAOs are solved "
                             f"here), not {kind}")
    if kind == "wamit":
        return read_wamit(path, ulen=ulen)
    if kind == "veres":
        return read_veres(path)
    if kind == "capytaine":
        return read_capytaine(path, roll_damping=roll_damping)
    return read_native(path)


def _numbers(parts: list[str]) -> bool:
    try:
        [float(p) for p in parts]
    except ValueError:
        return False
    return True
