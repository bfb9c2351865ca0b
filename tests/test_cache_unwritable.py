"""A cache that cannot be written (a file where its folder should be, a read-only file system, a full
disk) costs one warning line on stderr; ``marinesim wake`` and ``marinesim run --headless`` go on
and write every output, the same bytes as with a working cache. Staged for real: the read-only and
full file systems are small tmpfs mounts (root only; skipped with the reason otherwise)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import marinesim.cache
import marinesim.wake.cache
from conftest import DEFAULT, HANG_S, ROOT, cli, hang_guard
from marinesim.constants import KNOT
from marinesim.hull import load_hull
from marinesim.recent import Newest
from marinesim.wake.cache import UNSTORED_KEPT, cached_wake
from marinesim.wake.compute import WakeGrid, compute_wake
from staging import tmpfs

WAKE = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "20", "--nx", "256", "--ny", "128", "--quiet"]
HEADLESS_OUTPUTS = {"sea.png", "motions.csv", "motions.csv.json", "motions.png", "rao.png", "wake.png", "video.mp4"}
"""What ``run --headless --video`` writes for a vessel with a hull at a speed whose wake is drawn."""


@pytest.fixture(params=["file in place of the folder", "read-only file system", "full disk"])
def unwritable_cache(request, tmp_path):
    """A cache root that cannot be written, staged three ways."""
    if request.param == "file in place of the folder":
        root = tmp_path / "cache"
        root.write_text("not a folder\n")
        yield root
        return
    with tmpfs("ro" if request.param == "read-only file system" else "rw") as root:
        yield root  # 64 KiB: room for the FFTW wisdom, not for a wake


def _marinesim(args: list[str], cache: Path, cwd: Path) -> subprocess.CompletedProcess:
    """``marinesim *args`` in this process with its cache at ``cache``; a hang fails the test after HANG_S."""
    with hang_guard(f"marinesim {args[0]}"):
        return cli(*args, cwd=cwd, env={**os.environ, "MARINESIM_CACHE_DIR": str(cache)})


def _one_warning(stderr: str) -> None:
    lines = stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("marinesim: warning: "), stderr
    assert "going on without the cache" in lines[0] and ".part" not in lines[0], stderr


def test_wake_command_goes_on_without_the_cache(unwritable_cache, tmp_path):
    """If this fails, ``marinesim wake`` fails (or warns more than once, or writes another file) when its
    cache cannot be written, after computing the wake: the cache is an optimisation, not an output."""
    done = _marinesim(WAKE + ["--out", str(tmp_path / "w.npz")], unwritable_cache, tmp_path)
    assert done.returncode == 0, done.stderr
    _one_warning(done.stderr)
    reference = _marinesim(WAKE + ["--out", str(tmp_path / "ref.npz")], tmp_path / "working-cache", tmp_path)
    assert reference.returncode == 0 and reference.stderr == "", reference.stderr
    assert (tmp_path / "w.npz").read_bytes() == (tmp_path / "ref.npz").read_bytes()


@pytest.mark.slow
def test_headless_run_goes_on_without_the_cache(unwritable_cache, tmp_path, monkeypatch):
    """If this fails, ``marinesim run --headless`` stops when neither the FFTW wisdom nor the wake can be
    cached, leaving only some of its outputs behind; or it computes the wake twice, once for its picture and again
    for its video, where one kept in the process would do."""
    computed = []
    monkeypatch.setattr(marinesim.wake.cache, "compute_wake",
                        lambda *args, **kwargs: computed.append(args[1]) or compute_wake(*args, **kwargs))
    scenario = tmp_path / "small.toml"
    scenario.write_text(DEFAULT.read_text()
                        .replace('"../rao/tanker/tanker.4"', f'"{ROOT / "rao" / "tanker" / "tanker.4"}"')
                        .replace('"../hulls/tanker.gdf"', f'"{ROOT / "hulls" / "wigley.stl"}"')
                        .replace('"../hulls/', f'"{ROOT / "hulls"}/')
                        .replace("speed_kn = 4.0", "speed_kn = 12.0")  # Fn 0.2: a wake to compute and draw
                        .replace("tiles = 4", "tiles = 2").replace("resolution = 256", "resolution = 64"))
    done = _marinesim(["run", str(scenario), "--headless", "--duration", "1", "--out", str(tmp_path / "out"),
                       "--quiet", "--video"], unwritable_cache, tmp_path)
    assert done.returncode == 0, done.stderr
    _one_warning(done.stderr)
    assert {p.name for p in (tmp_path / "out").iterdir()} == HEADLESS_OUTPUTS
    assert computed == [pytest.approx(12.0 * KNOT)], computed


def test_a_wake_the_cache_cannot_take_is_kept_read_only_in_the_process(tmp_path, monkeypatch):
    """If this fails, a wake the cache could not store is computed again for the process's next request, or served
    with arrays one caller could change under the next, or with the first computation's timings as if computed."""
    monkeypatch.setattr(marinesim.wake.cache, "_unstored", Newest(UNSTORED_KEPT))
    monkeypatch.setattr(marinesim.cache, "_warned", False)  # this process's one warning, given back after
    (tmp_path / "cache").write_text("not a folder\n")
    hull, grid = load_hull(ROOT / "hulls" / "wigley.stl"), WakeGrid(64, 32)
    first, hit = cached_wake(hull, 9.0, grid, folder=tmp_path / "cache")
    assert not hit and first.timings
    again, hit = cached_wake(hull, 9.0, grid, folder=tmp_path / "cache")
    assert hit and again.timings == {} and again.info == first.info
    assert np.array_equal(again.elevation, first.elevation) and not again.elevation.flags.writeable
    assert not cached_wake(hull, 10.0, grid, folder=tmp_path / "cache")[1], "another speed is another wake"


def test_fftw_wisdom_that_cannot_be_saved_is_warned_about_once(tmp_path):
    """If this fails, an ocean whose FFTW plans cannot be saved either stops the run or says nothing
    (reruns then silently plan afresh), or says it once per FFT plan instead of once."""
    root = tmp_path / "cache"
    root.write_text("not a folder\n")
    script = ("from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem\n"
              "sea = SeaState((WaveSystem(Jonswap(3.0, 8.0, 3.3), 1.0, Cos2s(10.0)),))\n"
              "Ocean(sea, seed=3, tile_count=2, resolution=64, threads=2).fields(1.0)\n"
              "Ocean(sea, seed=4, tile_count=2, resolution=32, threads=2).fields(1.0)\n")
    env = {**os.environ, "MARINESIM_CACHE_DIR": str(root), "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=HANG_S)
    assert done.returncode == 0, done.stderr
    _one_warning(done.stderr)
    assert str(root) in done.stderr
