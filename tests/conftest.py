"""What the tests share: the checkout's root, one OpenGL context fixture, sea states (real spectra,
real FFTs, a real EGL context; nothing mocked) and a wake cache of their own."""

import math
from pathlib import Path

import pytest

from marinesim.angles import wave_beta_from_compass
from marinesim.sea import Cos2s, Jonswap, SeaState, WaveSystem

ROOT = Path(__file__).resolve().parents[1]
"""The checkout: its rao/, hulls/, configs/ and shaders/ are the files the tests read."""
DEFAULT = ROOT / "configs" / "default.toml"


@pytest.fixture(scope="module")
def gl_context():
    """A headless OpenGL 4.3 context (EGL: Mesa's llvmpipe without a GPU) for one test module, released
    after it; the module's tests are skipped where no such context can be made."""
    from marinesim.gl import GraphicsError, standalone_context

    try:
        context = standalone_context()
    except GraphicsError as error:
        pytest.skip(str(error))
    yield context
    context.release()


@pytest.fixture(scope="session")
def north_sea() -> SeaState:
    """A North Sea design-ish state: Hs 4 m, Tp 10 s, gamma 3.3, from 030 deg, cos-2s s = 15."""
    return SeaState((WaveSystem(Jonswap(4.0, 10.0, 3.3), wave_beta_from_compass(30.0), Cos2s(15.0)),))


@pytest.fixture(scope="session")
def finite_depth_sea() -> SeaState:
    return SeaState((WaveSystem(Jonswap(3.0, 9.0, 3.3), 0.7, Cos2s(10.0)),), depth=40.0)


def close_angle_deg(a: float, b: float) -> float:
    """Smallest difference of two compass angles (deg)."""
    return abs((a - b + 180.0) % 360.0 - 180.0)


__all__ = ["DEFAULT", "ROOT", "close_angle_deg", "math"]


@pytest.fixture(scope="session", autouse=True)
def wake_cache(tmp_path_factory):
    """Wakes computed by the tests are cached in a temporary folder, never in the user's cache."""
    import os

    folder = tmp_path_factory.mktemp("wake-cache")
    previous = os.environ.get("MARINESIM_CACHE_DIR")
    os.environ["MARINESIM_CACHE_DIR"] = str(folder)
    yield folder
    if previous is None:
        del os.environ["MARINESIM_CACHE_DIR"]
    else:
        os.environ["MARINESIM_CACHE_DIR"] = previous
