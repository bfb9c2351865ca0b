"""The sea: spectra, spreading, sea states and the ocean on FFT cascades (DESIGN.md data flow)."""

from marinesim.sea.cascades import Tile, choose_tiles
from marinesim.sea.ocean import Components, Ocean, PointSample, TileFields
from marinesim.sea.seastate import RegularWave, SeaState, WaveSystem
from marinesim.sea.spectra import Jonswap, JonswapFetch, PiersonMoskowitz, Tma
from marinesim.sea.spreading import Cos2s, HalfPlaneCos2n, LongCrested, Mitsuyasu

__all__ = [
    "Components", "Cos2s", "HalfPlaneCos2n", "Jonswap", "JonswapFetch", "LongCrested",
    "Mitsuyasu", "Ocean", "PiersonMoskowitz", "PointSample", "RegularWave", "SeaState",
    "Tile", "TileFields", "Tma", "WaveSystem", "choose_tiles",
]
