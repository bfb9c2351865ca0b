"""The same inputs give the same bytes in every output file, whatever the cache holds: wake files
hold no timings, sidecars no FFTW-plan-dependent figures, headless renders no measured frame times."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from conftest import DEFAULT, ROOT
from marinesim.cli import main
from marinesim.wake.compute import Wake

WAKE = ["wake", str(ROOT / "hulls" / "wigley.stl"), "--speed-kn", "20", "--nx", "256", "--ny", "128", "--quiet"]


def _marinesim(args: list[str], cache, cwd) -> subprocess.CompletedProcess:
    env = {**os.environ, "MARINESIM_CACHE_DIR": str(cache), "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-m", "marinesim", *args], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done


def test_wake_file_is_the_same_bytes_computed_cached_or_uncached(tmp_path, monkeypatch):
    """If this fails, ``wake --out`` writes different bytes for the same inputs: timings in ``info`` (they
    change every run), or a cached wake that differs from a computed one."""
    monkeypatch.setenv("MARINESIM_CACHE_DIR", str(tmp_path / "cache"))
    outputs = [tmp_path / name for name in ("computed.npz", "cached.npz", "uncached.npz")]
    assert main(WAKE + ["--out", str(outputs[0])]) == 0
    assert main(WAKE + ["--out", str(outputs[1])]) == 0
    assert main(WAKE + ["--no-cache", "--out", str(outputs[2])]) == 0
    assert len({path.read_bytes() for path in outputs}) == 1
    assert not [key for key in Wake.load(outputs[0]).info if key.startswith("seconds")]


@pytest.mark.slow
def test_export_is_the_same_bytes_whatever_the_cache(tmp_path):
    """If this fails, the sidecar's sea figures measured on the surface depend on the FFTW plans: a fresh
    cache (plans measured afresh) and a warm one (plans from the saved wisdom) give sidecars that differ
    in the 8th digit, so the same scenario and seed do not give the same files."""
    runs = {"fresh-1": tmp_path / "cache-1", "fresh-2": tmp_path / "cache-2", "warm": tmp_path / "cache-1"}
    for name, cache in runs.items():
        (tmp_path / name).mkdir()
        _marinesim(["export", str(DEFAULT), "--out", str(tmp_path / name / "m.csv"), "--duration", "5", "--quiet"],
                   cache, tmp_path)
    for file in ("m.csv", "m.csv.json"):
        contents = {(tmp_path / name / file).read_bytes() for name in runs}
        assert len(contents) == 1, f"{file} differs between a fresh and a warm cache"
    assert b'"hs_surface_m"' in (tmp_path / "warm" / "m.csv.json").read_bytes()


@pytest.mark.slow
def test_screenshots_are_the_same_bytes_whatever_the_cache(tmp_path):
    """If this fails, two ``render --screenshot`` runs of the same scenario and time give different PNGs:
    the HUD printed measured frame, upload and draw times into the picture, or the ocean's FFTW plans
    (measured afresh with a fresh cache, read from the wisdom with a warm one) changed pixels."""
    runs = {"fresh-1.png": "cache-1", "warm.png": "cache-1", "fresh-2.png": "cache-2"}
    for name, cache in runs.items():
        _marinesim(["render", str(DEFAULT), "--screenshot", str(tmp_path / name), "--time", "3", "--quiet"],
                   tmp_path / cache, tmp_path)
    assert len({(tmp_path / name).read_bytes() for name in runs}) == 1


def test_headless_hud_has_no_clock_time_and_the_window_keeps_it(gl_context):
    """If this fails, a headless frame shows measured times (so no two renders match), or the live viewer
    lost its frame-time line."""
    from marinesim.render.clock import FrameClock
    from marinesim.render.offscreen import Offscreen
    from marinesim.scenario import load_scenario

    with Offscreen(load_scenario(DEFAULT), (64, 64), solver="off") as view:
        view.frame()
        for lines in (view.scene.hud_lines(), view.scene.strip_lines(1280)):
            assert not [line for line in lines if " ms" in line]
        view.scene.clock = FrameClock()  # what the window gives its scene
        view.scene.clock.draw(0.0, 0.0)
        view.scene.clock.draw(0.0167, 0.0167)
        assert "frame  16.7 ms" in view.scene.hud_lines()[-1]
        assert any("frame  16.7 ms" in line for line in view.scene.strip_lines(1280))


def test_the_real_time_factor_of_slow_frames_is_what_the_run_did():
    """Frames 1.5 s apart, each step of the run (0.1 s, the longest a frame may take) drawn twice: the run goes at
    x0.067. Measured over the last two draws alone, a step's two draws, the line read x0.00, as if it had stopped."""
    from marinesim.render.clock import FrameClock

    clock = FrameClock()
    for step in range(8):
        for repeat in range(2):
            clock.draw(1.5 * step + 0.01 * repeat, 0.1 * step)
    assert clock.real_time_factor == pytest.approx(0.1 / 1.5, rel=0.05)
    assert "real time x0.07" in clock.line()


@pytest.mark.parametrize("backend", ["pyfftw", "numpy"])
def test_reproducible_fields_equal_the_frames_to_float32_rounding(north_sea, backend):
    """If this fails, the fields reports are measured on (numpy.fft) are not the fields the viewer draws
    (FFTW), beyond float32 rounding."""
    import numpy as np

    from marinesim.sea import Ocean

    pytest.importorskip(backend)
    ocean = Ocean(north_sea, seed=5, tile_count=2, resolution=64, fft_backend=backend)
    frames = [f.height.copy() for f in ocean.fields(12.5)]
    for frame, report in zip(frames, ocean.fields(12.5, reproducible=True), strict=True):
        np.testing.assert_allclose(report.height, frame, atol=1e-5 * np.abs(frame).max())
