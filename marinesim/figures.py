"""How every plot of the package is made and written: one resolution, one metadata policy.

A plot is a :class:`matplotlib.figure.Figure` built by :func:`figure` (never pyplot, never ``matplotlib.use``: a
notebook's backend and its list of open figures are left alone) and written by :func:`save` or :func:`png` at
:data:`DPI`, so a figure ``w`` x ``h`` inches is ``DPI w`` x ``DPI h`` pixels. The files carry no matplotlib version
and no date: the same plot gives the same bytes on any day and any matplotlib that draws it alike.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

if TYPE_CHECKING:
    from matplotlib.figure import Figure

DPI = 100
"""Pixels per inch of every plot written (px/in)."""

METADATA: dict[str, dict[str, None]] = {
    "png": {"Software": None},
    "pdf": {"Creator": None, "Producer": None, "CreationDate": None},
    "svg": {"Creator": None, "Date": None},
}
"""Per format, the metadata matplotlib writes by default that is left out: its version (PNG ``Software``, PDF
``Creator`` and ``Producer``, SVG ``Creator``) and the time of writing (PDF ``CreationDate``, SVG ``Date``)."""

SVG_HASH_SALT = "marinesim"
"""Salt of the ids in an SVG (matplotlib salts them with a random UUID unless one is given)."""

PNG_OPTIONS = {"compress_level": 6}
"""Passed to Pillow's PNG writer: zlib's default level. Its ``optimize`` (every filter at level 9) saves about 6 % of
a plot's bytes and takes three times as long to write."""


def figure(width_in: float, height_in: float, **options: Any) -> Figure:
    """A new figure ``width_in`` x ``height_in`` (in) at :data:`DPI`; ``options`` go to :class:`Figure`
    (``layout``, ``facecolor``, ...)."""
    from matplotlib.figure import Figure  # loaded with the first plot: the package imports fast

    return Figure(figsize=(width_in, height_in), dpi=DPI, **options)


def save(plot: Figure, target: str | Path | IO[bytes], file_format: str = "png") -> None:
    """Write ``plot`` to ``target`` (a path or a binary file) as ``file_format`` (png, pdf or svg) at :data:`DPI`,
    without version or date (:data:`METADATA`). The format is given, not read from the name: files are written
    to temporary names first."""
    if file_format not in METADATA:
        raise ValueError(f"plots are written as {', '.join(METADATA)}, not {file_format!r}")
    options: dict[str, Any] = {"format": file_format, "dpi": DPI, "metadata": METADATA[file_format]}
    if file_format == "png":
        options["pil_kwargs"] = dict(PNG_OPTIONS)
    if file_format == "svg":
        import matplotlib

        with matplotlib.rc_context({"svg.hashsalt": SVG_HASH_SALT}):
            plot.savefig(target, **options)
        return
    plot.savefig(target, **options)


def png(plot: Figure) -> bytes:
    """``plot`` as PNG bytes (:func:`save`)."""
    buffer = io.BytesIO()
    save(plot, buffer)
    return buffer.getvalue()
