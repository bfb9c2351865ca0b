"""No visible tiling at 1 km: the cascades' periods do not show in a picture of the sea.

Each cascade is periodic with its tile. The measure is the share of the picture that repeats
with a tile: the correlation of the picture's luminance at sea points (x, y) and (x + L, y)
(and (x, y + L)), L the tile's size, over every pair inside the view. A sea drawn on one tile
repeats entirely (correlation about 1). Four cascades with irrational size ratios, the largest
spanning at least 1 km, and foam placed by the surface's Jacobian instead of each tile's own,
leave each tile a quarter to a half of what the eye sees, the rest changing from one repeat to
the next: the repeating part must not dominate. The view: straight down from 700 m,
1.16 x 0.65 km of sea on 640 x 360 pixels.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from conftest import DEFAULT, luminance, offscreen
from marinesim.render.camera import FreeCamera
from marinesim.scenario import load_scenario

SIZE = (640, 360)
REPEATING_LIMIT = 0.6
"""Most of the picture's variance that may repeat with any one tile (one tile alone: 0.84)."""


def short_sea(tmp_path: Path, tiles: int, hs_m: float = 1.5, tp_s: float = 4.0, resolution: int = 256) -> Path:
    """A steep wind chop (by default Hs 1.5 m, Tp 4 s: its natural largest tile would be 450 m)."""
    path = tmp_path / f"chop_{tiles}_{resolution}.toml"
    path.write_text(f"""
[ocean]
tiles = {tiles}
resolution = {resolution}
[[sea]]
type = "jonswap"
hs_m = {hs_m}
tp_s = {tp_s}
from_deg = 290.0
spreading_s = 12.0
[run]
duration_s = 60.0
dt_s = 0.1
seed = 1
""")
    return path


def repeating_share(scenario_path: Path) -> dict[float, float]:
    """For each tile that fits in the view twice and spans ten pixels or more: the correlation of
    the picture with itself shifted by the tile's size along x or y (the larger of the two).
    Shorter shifts measure the picture's smoothness, not a repeat."""
    scenario = load_scenario(scenario_path)
    with offscreen(scenario, SIZE) as view:
        view.scene.cameras["free"] = FreeCamera(position=(0.0, 0.0, 700.0), yaw_deg=90.0, pitch_deg=-89.9)
        view.scene.camera_name = "free"
        view.go_to(10.0)
        picture = luminance(view.frame(hud=False))
        eye = view.scene.camera.eye(view.scene.sim.pose())
        x, y = (a.ravel() for a in np.meshgrid(np.arange(-700.0, 700.0, 2.0), np.arange(-400.0, 400.0, 2.0)))

        def seen(dx: float, dy: float) -> np.ndarray:
            """Luminance at the sea points shifted by (dx, dy) m; NaN outside the picture."""
            pixels = np.floor(eye.project(np.c_[x + dx, y + dy, np.zeros_like(x)], SIZE)[:, :2]).astype(int)
            inside = (pixels >= 0).all(axis=1) & (pixels[:, 0] < SIZE[0]) & (pixels[:, 1] < SIZE[1])
            values = np.full(x.size, np.nan)
            values[inside] = picture[pixels[inside, 1], pixels[inside, 0]]
            return values

        here = seen(0.0, 0.0)
        share = {}
        ends = eye.project(np.array([[-50.0, 0.0, 0.0], [50.0, 0.0, 0.0]]), SIZE)
        metres_per_pixel = 100.0 / abs(ends[1, 0] - ends[0, 0])
        for tile in view.scene.sim.ocean.tiles:
            if tile.size < 10.0 * metres_per_pixel:
                continue
            shares = []
            for shift in ((tile.size, 0.0), (0.0, tile.size)):
                there = seen(*shift)
                both = np.isfinite(here) & np.isfinite(there)
                if both.sum() > 0.1 * x.size:
                    shares.append(np.corrcoef(here[both], there[both])[0, 1])
            if shares:
                share[tile.size] = max(shares)
    return share


def test_one_tile_repeats_visibly(tmp_path):
    """The negative control: a harbour chop (Hs 0.5 m, Tp 2.5 s) on one 180 m tile repeats
    visibly (else the measure is blind)."""
    share = repeating_share(short_sea(tmp_path, tiles=1, hs_m=0.5, tp_s=2.5))
    assert len(share) == 1 and 150.0 < next(iter(share)) < 200.0
    assert min(share.values()) > 0.75, f"a single tile should repeat almost entirely: {share}"


@pytest.mark.parametrize("name", ["chop", "harbour chop at 512^2", "default"])
def test_no_tile_period_shows_in_a_kilometre_of_sea(tmp_path, name):
    """The chop on four cascades (the largest stretched to 1 km), a harbour chop of Tp 3 s on
    512^2 cascades (at 256^2 its peak would leave a 1 km tile's band, so the stretch stops at
    560 m) and the default North Sea state: no cascade's period dominates the picture, foam
    included."""
    path = {"chop": lambda: short_sea(tmp_path, tiles=4),
            "harbour chop at 512^2": lambda: short_sea(tmp_path, tiles=4, hs_m=0.8, tp_s=3.0, resolution=512),
            "default": lambda: DEFAULT}[name]()
    share = repeating_share(path)
    assert len(share) >= 2, f"fewer than two tiles fit the view: the test measures little ({share})"
    worst = max(share, key=share.get)
    assert share[worst] < REPEATING_LIMIT, (
        f"{share[worst]:.0%} of the picture repeats with the {worst:.1f} m tile: {share}")
