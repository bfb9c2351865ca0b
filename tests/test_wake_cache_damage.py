"""The wake cache serves only the wake its key names: a damaged, foreign or outdated entry that still
loads is recomputed and replaced, by the library and by ``marinesim wake``."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from conftest import ROOT
from marinesim.cli import main
from marinesim.errors import FileFormatError
from marinesim.hull import load_hull
from marinesim.wake.cache import cache_dir, cache_key, cached_wake
from marinesim.wake.compute import Wake, WakeGrid

GRID = WakeGrid(256, 128)
SPEED = 9.0  # m/s


@pytest.fixture(scope="module")
def wigley():
    return load_hull(ROOT / "hulls" / "wigley.stl")


def _damaged(wake: Wake) -> dict[str, Wake]:
    """Loadable entries that are not the wake of their key, by what is wrong with them."""
    info = wake.info
    return {
        "3x3 elevation": dataclasses.replace(wake, elevation=np.zeros((3, 3), np.float32)),
        "short x axis": dataclasses.replace(wake, x=wake.x[:-1]),
        "shifted x axis": dataclasses.replace(wake, x=wake.x + 1.0),
        "short y axis": dataclasses.replace(wake, y=wake.y[1:]),
        "NaN in the field": dataclasses.replace(wake, elevation=np.full_like(wake.elevation, math.nan)),
        "another speed": dataclasses.replace(wake, info=info | {"speed_m_s": SPEED + 1.0}),
        "another hull": dataclasses.replace(wake, info=info | {"hull_sha256": "0" * 64}),
        "older format": dataclasses.replace(wake, info={k: v for k, v in info.items() if k != "wake_format"}),
        "format 2": dataclasses.replace(wake, info=info | {"wake_format": 2}),
        "another grid": dataclasses.replace(wake, info=info | {"grid": info["grid"] | {"nx": 128}}),
        "info not a mapping": dataclasses.replace(wake, info=[1, 2]),
        "A(theta) cut": dataclasses.replace(wake, amplitude=wake.amplitude[:3]),
    }


@pytest.mark.slow
def test_a_loadable_but_wrong_entry_is_recomputed_and_replaced(tmp_path, wigley):
    """If this fails, a cache entry that loads but is not the wake of its key (another grid, speed, hull or
    format, a cut axis, NaNs) is served as if it were: wrong fields drawn, plotted and written."""
    fresh, hit = cached_wake(wigley, SPEED, GRID, folder=tmp_path)
    assert not hit
    entry = tmp_path / f"{cache_key(wigley, SPEED, GRID, 1025.0, 9.80665, 1.0)}.npz"
    assert entry.is_file()
    for what, damaged in _damaged(fresh).items():
        damaged.save(entry)
        served, hit = cached_wake(wigley, SPEED, GRID, folder=tmp_path)
        assert not hit, f"an entry with {what} was served from the cache"
        assert served.elevation.shape == (128, 256) and np.array_equal(served.elevation, fresh.elevation), what
        assert cached_wake(wigley, SPEED, GRID, folder=tmp_path)[1], f"an entry with {what} was not replaced"


def test_an_entry_with_flipped_bytes_is_recomputed(tmp_path, wigley):
    """If this fails, bit rot inside a cache entry's compressed data (zlib's error, not a zip error) stops
    the run with a traceback instead of the entry being recomputed."""
    fresh, _ = cached_wake(wigley, SPEED, GRID, folder=tmp_path)
    (entry,) = tmp_path.glob("*.npz")
    data = entry.read_bytes()
    refused = []
    for where in range(200, len(data), len(data) // 40):
        entry.write_bytes(data[:where] + bytes([data[where] ^ 0x55]) + data[where + 1:])
        try:
            Wake.load(entry)
        except FileFormatError:
            refused.append(where)
    assert refused, "no flipped byte was noticed"
    entry.write_bytes(data[:refused[0]] + bytes([data[refused[0]] ^ 0x55]) + data[refused[0] + 1:])
    served, hit = cached_wake(wigley, SPEED, GRID, folder=tmp_path)
    assert not hit and np.array_equal(served.elevation, fresh.elevation)


def test_wake_command_recomputes_a_damaged_entry(tmp_path, monkeypatch, wigley):
    """If this fails, ``marinesim wake --out`` copies a damaged cache entry (a 3x3 field) to the user's file
    and exits 0: the bug this guards against."""
    monkeypatch.setenv("MARINESIM_CACHE_DIR", str(tmp_path / "cache"))
    args = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "20", "--nx", "256", "--ny", "128", "--quiet"]
    assert main(args + ["--out", str(tmp_path / "first.npz")]) == 0
    (entry,) = cache_dir().glob("*.npz")
    wake = Wake.load(entry)
    dataclasses.replace(wake, elevation=np.zeros((3, 3), np.float32)).save(entry)
    assert main(args + ["--out", str(tmp_path / "again.npz")]) == 0
    assert Wake.load(tmp_path / "again.npz").elevation.shape == (128, 256)
    assert (tmp_path / "again.npz").read_bytes() == (tmp_path / "first.npz").read_bytes()
    assert Wake.load(entry).elevation.shape == (128, 256), "the damaged entry was not replaced"
