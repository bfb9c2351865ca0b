"""The wake picture (marinesim/wake/plot.py) without moire: waves shorter than a pixel of the picture average out
to the mean level instead of beating with the pixel grid into bands that are not in the field."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from marinesim.wake.compute import Wake
from marinesim.wake.plot import low_pass, plot_wake

SPACING_M = 0.5


def field_of_waves(length_cells: float, shape=(1024, 2048)) -> np.ndarray:
    """Unit waves ``length_cells`` long travelling obliquely across a grid of ``shape``."""
    y, x = np.indices(shape)
    return np.cos(2.0 * np.pi * (0.8 * x + 0.6 * y) / length_cells)


@pytest.mark.parametrize("length_pixels, kept", [(0.7, (0.0, 1e-6)), (2.0, (0.0, 0.01)), (6.0, (0.5, 0.65)),
                                                 (20.0, (0.93, 1.0))])
def test_waves_shorter_than_two_pixels_vanish_and_longer_ones_stay(length_pixels, kept):
    """At 3 cells a pixel: a wave of under two pixels would alias (a false longer wave); one of six is drawn at over
    half its height, one of twenty almost whole (the Gaussian's exp(-2 pi^2 / lambda^2))."""
    factor = 3
    smoothed = low_pass(field_of_waves(length_pixels * factor), factor)
    amplitude = np.abs(smoothed[20:-20, 20:-20]).max()
    assert kept[0] <= amplitude <= kept[1]


def test_the_picture_of_unresolvable_waves_is_the_colour_of_the_mean_level(tmp_path):
    """Waves 2.1 cells long over a 2048-cell grid drawn 800 px wide: every pixel of the map is near the colour map's
    white, none red or blue (before, they beat into bands of colour)."""
    short = field_of_waves(2.1).astype(np.float32)
    nx, ny = short.shape[1], short.shape[0]
    wake = Wake(short, np.zeros_like(short), np.arange(nx) * SPACING_M - 700.0,
                (np.arange(ny) - ny / 2) * SPACING_M,
                np.linspace(1.0, 3.0, 20), np.ones(20, complex),
                {"bow_x_m": 100.0, "speed_kn": 10.0, "froude": 0.2, "wave_resistance_N": 1e5, "hull_source": "x.stl"})
    plot_wake(wake, tmp_path / "wake.png")
    image = np.asarray(Image.open(tmp_path / "wake.png").convert("RGB"), int)
    height, width, _ = image.shape
    top = image[: int(0.55 * height), : int(0.85 * width)]  # the map, without the colour bar
    coloured = np.abs(top[..., 0] - top[..., 2]) > 60
    assert coloured.mean() < 0.001, f"{coloured.mean():.1%} of the map is red or blue"
    assert np.median(top.mean(axis=-1)) > 220, "the map is not the white of the mean level (colours mixed instead)"
