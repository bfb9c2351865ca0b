"""What a sea state is, from its spectrum and as measured on the synthesised surface.

The surface figures are what a wave buoy would report: Hs from the elevation variance, Tz from
the variances of elevation and its time derivative, Tp from the periodogram of the height
fields, and the mean direction from the cross-correlation of dh/dt with the slopes (a
pitch-roll buoy: for ``eta = A cos(w t - k.x)``, ``<eta_t grad eta> = -A^2 w k / 2``, so the
travel direction is ``-<eta_t grad eta>``; it weights each component by ``w |k|``).
"""

from __future__ import annotations

import math

import numpy as np

from marinesim.angles import wave_compass_from_beta
from marinesim.errors import require_within
from marinesim.sea.dispersion import omega_from_k
from marinesim.sea.kinds import MAX_TIME_S
from marinesim.sea.ocean import Ocean

TIME_STEP = 1e-3
"""Half-step (s) of the central difference for d eta / dt on the surface."""


def spectrum_summary(ocean: Ocean) -> dict:
    """Hs, Tp, Tz (m, s) and mean 'coming from' direction (compass deg) of the sea state."""
    sea = ocean.sea
    return {
        "hs_spectrum_m": sea.hs,
        "tp_spectrum_s": sea.tp,
        "tz_spectrum_s": sea.tz,
        "mean_from_deg_spectrum": wave_compass_from_beta(sea.mean_beta),
    }


def surface_summary(ocean: Ocean, t: float = 0.0) -> dict:
    """Hs, Tp, Tz and mean direction measured on the FFT fields at time ``t`` (s, |t| <= :data:`MAX_TIME_S`), by
    numpy.fft: the same bits whatever the FFTW plans saved in the cache."""
    require_within("time", t, -MAX_TIME_S, MAX_TIME_S, "s")
    before = [f.height.copy() for f in ocean.fields(t - TIME_STEP, reproducible=True)]
    after = [f.height.copy() for f in ocean.fields(t + TIME_STEP, reproducible=True)]
    fields = ocean.fields(t, reproducible=True)
    var_eta = var_rate = 0.0
    flux = np.zeros(2)
    omega_all, power_all = [], []
    for f, b, a in zip(fields, before, after):
        rate = (a.astype(float) - b) / (2.0 * TIME_STEP)
        var_eta += float(np.mean(f.height.astype(float) ** 2))
        var_rate += float(np.mean(rate**2))
        flux += [np.mean(rate * f.slope_x), np.mean(rate * f.slope_y)]
        qx, qy = f.tile.wavenumbers()
        spectrum = np.fft.fft2(f.height.astype(float)) / f.height.size
        omega_all.append(omega_from_k(np.hypot(qx, qy), ocean.sea.depth, ocean.sea.g).ravel())
        power_all.append(np.abs(spectrum.ravel()) ** 2)
    return {
        "hs_surface_m": 4.0 * math.sqrt(var_eta),
        "tp_surface_s": _periodogram_peak_period(np.concatenate(omega_all), np.concatenate(power_all)),
        "tz_surface_s": 2.0 * math.pi * math.sqrt(var_eta / var_rate),
        "mean_from_deg_surface": wave_compass_from_beta(math.atan2(-flux[1], -flux[0])),
    }


def _periodogram_peak_period(omega: np.ndarray, power: np.ndarray, bins: int = 80) -> float:
    """Peak period (s) of the variance per unit frequency, binned on log-spaced frequencies."""
    live = power > 1e-12 * power.max()
    edges = np.geomspace(omega[live].min() * 0.999, omega[live].max() * 1.001, bins + 1)
    energy, _ = np.histogram(omega[live], bins=edges, weights=power[live])
    density = energy / np.diff(edges)
    i = int(np.argmax(density))
    return 2.0 * math.pi / math.sqrt(edges[i] * edges[i + 1])


def summary(ocean: Ocean, t: float = 0.0) -> dict:
    """Everything ``marinesim sea`` reports, as one JSON-ready dict."""
    return {
        **spectrum_summary(ocean),
        **surface_summary(ocean, t),
        "m0_fraction": ocean.m0_fraction,
        "components": len(ocean.components(t)),
        "depth_m": None if math.isinf(ocean.sea.depth) else ocean.sea.depth,
        "seed": ocean.seed,
        "time_s": t,
        "tiles": [tile.as_dict() for tile in ocean.tiles],
    }
