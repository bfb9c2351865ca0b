"""The cascades synthesised on the GPU (compute shaders, here Mesa's llvmpipe) against the CPU's (pyfftw) and
against the direct sum of the wave components that the vessel responds to.

Both syntheses are float32 FFTs of float32 spectra: they differ by rounding, measured at 3e-7 of a
field's range at 64^2 and 256^2. The tolerance, 1e-5 of the range, is 30x that and 50x below the
error a float32 phase ``w t`` would make after an hour (5e-4 rad), the first thing a GPU port gets wrong.
"""

from __future__ import annotations

import numpy as np
import pytest

from conftest import DEFAULT
from marinesim.render.layers.cascades import CascadeLayer
from marinesim.render.layers.synthesis import CascadeSynthesis
from marinesim.sea import Cos2s, Jonswap, Ocean, SeaState, WaveSystem

TOLERANCE = 1e-5
"""Of a field's largest magnitude (float32 rounding measured at 3e-7)."""


def gpu_fields(layer: CascadeLayer, tiles: int, n: int) -> dict[str, np.ndarray]:
    """The layer's textures read back as (tiles, n, n) arrays by field name."""
    fields = np.frombuffer(layer.fields.read(), np.float32).reshape(tiles, n, n, 4)
    slopes = np.frombuffer(layer.slopes.read(), np.float32).reshape(tiles, n, n, 2)
    return {"displacement_x": fields[..., 0], "displacement_y": fields[..., 1], "height": fields[..., 2],
            "jacobian": fields[..., 3], "slope_x": slopes[..., 0], "slope_y": slopes[..., 1]}


def assert_same_fields(ocean: Ocean, got: dict[str, np.ndarray], t: float) -> None:
    for i, reference in enumerate(ocean.fields(t, reproducible=True)):
        for name, field in got.items():
            expected = getattr(reference, name)
            scale = np.abs(expected).max()
            np.testing.assert_allclose(field[i], expected, rtol=0, atol=TOLERANCE * scale,
                                       err_msg=f"{name} of tile {i} at t = {t} s")


@pytest.fixture(scope="module")
def crossing_sea() -> SeaState:
    """A wind sea and a swell from different directions, so both x and y terms of every field are exercised."""
    return SeaState((WaveSystem(Jonswap(3.0, 8.0, 3.3), 0.6, Cos2s(10.0)),
                     WaveSystem(Jonswap(2.0, 13.0, 5.0), 2.4, Cos2s(40.0))))


def test_gpu_cascades_are_the_cpu_fields_at_any_time_and_through_a_ramp(gl_context, crossing_sea):
    """If this fails, the GPU draws another sea than the CPU's reference: a wrong packing multiplier or
    sign (displacement, slopes or Jacobian off), a wrong FFT batch stride (tiles mixed), the ramp's blend,
    the choppiness, or a float32 phase (t = 3600.7 s)."""
    ocean = Ocean(crossing_sea, seed=3, resolution=64, choppiness=1.3)
    tiles, n = len(ocean.tiles), ocean.resolution
    layer = CascadeLayer(gl_context, tiles, n)
    gpu = CascadeSynthesis(gl_context, ocean, layer)
    try:
        for t in (0.0, 37.3, 3600.7):
            gpu.run(t)
            assert_same_fields(ocean, gpu_fields(layer, tiles, n), t)
        rougher = SeaState((WaveSystem(Jonswap(5.0, 9.0, 3.3), 1.2, Cos2s(10.0)),))
        ocean.ramp_to(rougher, 4000.0, 30.0)
        ocean.choppiness = 0.8
        for t in (4012.0, 4031.0, 3990.0):  # in the ramp, after it, and back before it (a replay's seek)
            gpu.run(t)
            assert_same_fields(ocean, gpu_fields(layer, tiles, n), t)
    finally:
        gpu.release()
        layer.release()


def test_gpu_cascades_are_the_sum_of_the_components_the_vessel_responds_to(gl_context, crossing_sea):
    """If this fails, what the trainee sees is not the sea the vessel moves in: the GPU's height and slopes
    at grid points differ from the direct sum of the ocean's components (the same amplitudes, frequencies
    and wave numbers the response is built from)."""
    ocean = Ocean(crossing_sea, seed=8, tile_count=2, resolution=32)
    layer = CascadeLayer(gl_context, 2, 32)
    gpu = CascadeSynthesis(gl_context, ocean, layer)
    try:
        t = 123.4
        gpu.run(t)
        got = gpu_fields(layer, 2, 32)
        rng = np.random.default_rng(1)
        for i, tile in enumerate(ocean.tiles):
            iy, ix = rng.integers(0, 32, (2, 12))
            direct = ocean.sample(ix * tile.spacing, iy * tile.spacing, t, tiles=[i])
            for name in ("height", "slope_x", "slope_y"):
                expected = getattr(direct, {"height": "elevation"}.get(name, name))
                scale = np.abs(getattr(ocean.fields(t, reproducible=True)[i], name)).max()
                np.testing.assert_allclose(got[name][i, iy, ix], expected, rtol=0, atol=TOLERANCE * scale,
                                           err_msg=f"{name} of tile {i}")
    finally:
        gpu.release()
        layer.release()


def test_a_frame_drawn_from_gpu_cascades_is_the_frame_drawn_from_the_cpus(gl_context):
    """If this fails, the renderer's GPU path is wired differently from its CPU path (a texture unbound, the
    mipmaps or the foam pass skipped, the wrong time): the default scenario's frame at t = 3 s must be the
    same picture to within a level of rounding in a few pixels."""
    from marinesim.render.offscreen import Offscreen
    from marinesim.render.renderer import RenderOptions
    from marinesim.scenario import load_scenario

    scenario = load_scenario(DEFAULT)
    frames = {}
    for where in ("cpu", "gpu"):
        options = RenderOptions(cascades=where, reproducible=True)
        with Offscreen(scenario, (160, 90), solver="off", options=options) as view:
            assert (view.scene.renderer.synthesis is not None) == (where == "gpu")
            view.go_to(3.0)
            frames[where] = view.frame(hud=False).astype(int)
    difference = np.abs(frames["gpu"] - frames["cpu"])
    assert difference.max() <= 2 and np.mean(difference > 0) < 0.01, (difference.max(), np.mean(difference > 0))
    assert frames["cpu"].std() > 10  # a picture, not a blank frame
