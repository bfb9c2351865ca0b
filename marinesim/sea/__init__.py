"""The sea: spectra, spreading, sea states and the ocean on FFT cascades (DESIGN.md data flow).

The names below are imported on first use (PEP 562), so that ``marinesim.sea.kinds`` and the
command line's option lists load without scipy and numba.
"""

from __future__ import annotations

import importlib

_EXPORTS = {
    "Tile": "cascades", "choose_tiles": "cascades",
    "Components": "ocean", "Ocean": "ocean", "PointSample": "ocean", "TileFields": "ocean",
    "RegularWave": "seastate", "SeaState": "seastate", "WaveSystem": "seastate",
    "Jonswap": "spectra", "JonswapFetch": "spectra", "PiersonMoskowitz": "spectra", "Tma": "spectra",
    "Cos2s": "spreading", "HalfPlaneCos2n": "spreading", "LongCrested": "spreading", "Mitsuyasu": "spreading",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> object:
    if name not in _EXPORTS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)
