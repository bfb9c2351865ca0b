"""How a Kelvin wake looks on the water: its elevation capped at breaking, its slopes and its foam.

Pure NumPy (no GL context): the wake layer (:mod:`marinesim.render.layers.wake`) uploads the
result as a texture.
"""

from __future__ import annotations

import numpy as np

from marinesim.wake.compute import Wake

BREAKING_SLOPE = 0.3
"""Steepest wake slope drawn (a Stokes wave breaks at a slope of about 0.45; groups break earlier)."""
WAKE_SLOPE_FOAM = (0.2, 0.3)
"""Wake slopes where the wake's own foam starts and is full (breaking diverging waves)."""


def wake_appearance(wake: Wake) -> np.ndarray:
    """The wake as drawn, on the wake's grid: (ny, nx, 4) float32 of elevation (m), its
    d/dx and d/dy (vessel frame: x forward, y to port) and foam (0..1): the waves and the local flow about the
    hull (the bow's and stern's rise, the shoulders' trough), which no breaking caps (Bernoulli bounds it) but
    which foams where it is as steep as a breaking wave (the bow wave against the stem).

    Thin-ship theory overpredicts the waves of full hulls, up to slopes no water wave survives: a
    field whose steepest waves (99.9th percentile of the slope) pass ``BREAKING_SLOPE`` is scaled
    down to it, as breaking would cap them. Foam: where the diverging waves or the local flow are near
    breaking (slope ``WAKE_SLOPE_FOAM``). The turbulent wash astern and the foam against the hull are drawn by the
    ocean at any speed (``shaders/ocean.frag``), wake or not.
    """
    h = np.asarray(wake.elevation, np.float64)
    spacing = float(wake.x[1] - wake.x[0])
    dhdy, dhdx = np.gradient(h, spacing)
    slope = np.hypot(dhdx, dhdy)
    limit = BREAKING_SLOPE / max(float(np.percentile(slope, 99.9)), BREAKING_SLOPE)
    h, dhdx, dhdy, slope = h * limit, dhdx * limit, dhdy * limit, slope * limit
    local = np.asarray(wake.local, np.float64)
    ldy, ldx = np.gradient(local, spacing)
    lo, hi = WAKE_SLOPE_FOAM
    foam = np.clip((np.maximum(slope, np.hypot(ldx, ldy)) - lo) / (hi - lo), 0.0, 1.0)
    return np.stack([h + local, dhdx + ldx, dhdy + ldy, foam], axis=-1).astype(np.float32)
