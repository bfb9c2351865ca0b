"""The resources that travel with marinesim: ``shaders``, ``configs``, ``hulls`` and ``rao``.

In a checkout they are the top-level folders (the product card fixes them there); a wheel carries
them inside the package (pyproject's package-dir mapping), where :mod:`importlib.resources` finds
them. The scenarios in ``configs`` name their RAO and hull files as ``../rao/...`` and
``../hulls/...``, which holds in both layouts.
"""

from __future__ import annotations

from importlib.resources import files
from pathlib import Path

KINDS = ("shaders", "configs", "hulls", "rao")


def resource_dir(kind: str) -> Path:
    """The folder of the ``kind`` resources (one of :data:`KINDS`)."""
    if kind not in KINDS:
        raise ValueError(f"unknown resource kind {kind!r} (known: {', '.join(KINDS)})")
    packaged = Path(str(files("marinesim").joinpath(kind)))
    if packaged.is_dir():
        return packaged
    return Path(__file__).resolve().parents[1] / kind


def default_scenario() -> Path:
    """The scenario ``marinesim run`` opens without an argument."""
    return resource_dir("configs") / "default.toml"
