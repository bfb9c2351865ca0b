"""Pictures of a wake: the field with the Kelvin lines, and |A(theta)|."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from marinesim.figures import figure, save
from marinesim.wake.compute import Wake
from marinesim.wake.measure import KELVIN_HALF_ANGLE_DEG


FIELD_PIXELS = 800
"""About the width of the elevation map in the picture (px): the field is filtered down to it before it is drawn."""


def low_pass(field: np.ndarray, factor: int) -> np.ndarray:
    """``field`` (ny, nx) seen through pixels ``factor`` cells wide: Gaussian-filtered (sigma one pixel, which
    leaves a wave of lambda pixels exp(-2 pi^2 / lambda^2) of its height: under 1 % of those two pixels long, 58 %
    at six, 95 % at twenty) and then sampled every ``factor`` cells. Waves shorter than two pixels would otherwise
    beat with the pixel grid (moire)."""
    from scipy.ndimage import gaussian_filter

    return gaussian_filter(field, float(factor), mode="nearest")[::factor, ::factor] if factor > 1 else field


def plot_wake(wake: Wake, path: str | Path) -> None:
    """Draw the elevation map (vessel frame, bow to the right) and |A(theta)| to a PNG."""
    info = wake.info
    fig = figure(9.9, 7.65, layout="constrained")
    top, bottom = fig.subplots(2, 1, height_ratios=(2.2, 1))
    limit = float(np.percentile(np.abs(wake.elevation), 99.5)) or 1.0
    factor = max(1, -(-wake.elevation.shape[1] // FIELD_PIXELS))
    field = low_pass(np.asarray(wake.elevation, float), factor)
    spacing = float(wake.x[1] - wake.x[0]) * factor
    x0, y0 = wake.x[0] - 0.5 * spacing, wake.y[0] - 0.5 * spacing
    extent = (x0, x0 + field.shape[1] * spacing, y0, y0 + field.shape[0] * spacing)
    image = top.imshow(field, origin="lower", extent=extent, cmap="RdBu_r", vmin=-limit, vmax=limit,
                       interpolation="bilinear", interpolation_stage="data")
    fig.colorbar(image, ax=top, label="elevation [m]", shrink=0.8)
    bow = info["bow_x_m"]
    reach = wake.x[-1] - wake.x[0]
    for sign in (1, -1):
        top.plot([bow, bow - reach], [0.0, sign * reach * math.tan(math.radians(KELVIN_HALF_ANGLE_DEG))], "k--", lw=0.8,
                 label="19.47 deg" if sign > 0 else None)
        measured = info.get("kelvin_half_angle_deg")
        if measured:
            top.plot([bow, bow - reach], [0.0, sign * reach * math.tan(math.radians(measured))], "g:", lw=1.0,
                     label=f"measured {measured:.2f} deg" if sign > 0 else None)
    top.set_xlim(extent[0], extent[1])
    top.set_ylim(extent[2], extent[3])
    top.set_xlabel("x (forward) [m]")
    top.set_ylabel("y (to port) [m]")
    top.legend(loc="upper left", fontsize=8)
    top.set_title(f"Kelvin wake at {info['speed_kn']:.1f} kn (Fn {info['froude']:.3f}), wave resistance "
                  f"{info['wave_resistance_N'] / 1e3:,.1f} kN; {Path(info['hull_source']).name}")
    theta = np.degrees(np.arccos(1.0 / wake.sec))
    bottom.plot(theta, np.abs(wake.amplitude), lw=1.0)
    bottom.set_xlabel("wave direction theta [deg] (0 = transverse waves)")
    bottom.set_ylabel("|A(theta)| [m]")
    bottom.set_xlim(0, 90)
    bottom.grid(alpha=0.3)
    save(fig, path)
