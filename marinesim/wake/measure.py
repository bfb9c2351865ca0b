"""Geometry measured from a computed wake field: the cusp-line half-angle and the transverse wavelength.

These measure the field, not the theory, so they can fail: a non-dispersive or mis-scaled wake
gives another angle or wavelength than Kelvin's 19.47 deg and 2 pi U^2 / g.

- Half-angle: the wave energy envelope (zeta^2 averaged over ENVELOPE_ALONG wavelengths along the
  track and ENVELOPE_ACROSS across) has its outermost lobe (the last run above half its maximum)
  just inside the cusp line, in an Airy-function profile;
  the cusp line itself (the caustic) is where Ai^2 has fallen to Ai(0)^2 / max Ai^2 = 0.439 of
  that peak, on the outside. That edge is found in each column from two hull lengths behind the
  bow to where the wedge leaves the grid, and a straight line fitted through the edges. Where
  the edges scatter about that line by more than FIT_SCATTER wavelengths (rms) the lobes of the
  bow and stern systems interfere (a long hull at low Fn, a few lengths behind it) and nothing is
  reported. At Fn above about 0.6 the largest waves stand on rays inside the cusp (Rabaud &
  Moisy, J. Fluid Mech. 2013): what is measured there is that narrower apparent wake angle.
- Transverse wavelength: the peak of the windowed spectrum of the centreline profile over the
  same range, refined by a parabola through the log-spectrum.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.ndimage import uniform_filter

from marinesim.errors import MarinesimError

AIRY_EDGE = (0.355028053887817 / 0.535656656015700) ** 2  # Ai(0)^2 / Ai(-1.0188)^2
ENVELOPE_ALONG = 4.0  # transverse wavelengths
ENVELOPE_ACROSS = 0.5
FIT_SCATTER = 0.2  # transverse wavelengths, rms
KELVIN_HALF_ANGLE_DEG = math.degrees(math.asin(1.0 / 3.0))


def kelvin_half_angle_deg(elevation: np.ndarray, x: np.ndarray, y: np.ndarray, wavelength: float,
                          hull_length: float, bow_x: float, along: float = ENVELOPE_ALONG) -> float:
    """Half-angle (deg) of the cusp lines of ``elevation`` (rows y, columns x; vessel frame, x forward).

    ``along``: envelope window along the track, in transverse wavelengths (shorter for a compact
    source seen over a few wavelengths, whose cusp moves sideways across a long window)."""
    spacing = x[1] - x[0]
    upper = y > 0
    energy = uniform_filter(elevation[upper] ** 2, size=(max(1, round(ENVELOPE_ACROSS * wavelength / spacing)),
                                                        max(1, round(along * wavelength / spacing))))
    eta = y[upper]
    xi = bow_x - x  # distance behind the bow
    reach = 0.8 * eta[-1] / math.tan(math.radians(KELVIN_HALF_ANGLE_DEG))
    columns = np.flatnonzero((xi > 2.0 * hull_length) & (xi < reach))
    if len(columns) < 8:
        raise MarinesimError("the wake grid is too small to measure the Kelvin angle: it must reach "
                             f"more than two hull lengths behind the hull inside the wedge ({reach:.0f} m)")
    edges = []
    for column in columns:
        profile = energy[:, column]
        # the cusp is the outermost lobe: the last run of the profile above half its maximum
        strong = profile >= 0.5 * profile.max()
        last = int(np.flatnonzero(strong)[-1])
        weak_before = np.flatnonzero(~strong[:last])
        first = int(weak_before[-1]) + 1 if len(weak_before) else 0
        peak = first + int(np.argmax(profile[first:last + 1]))
        level = AIRY_EDGE * profile[peak]
        beyond = np.flatnonzero(profile[peak:] < level)
        if len(beyond) == 0:
            edges.append(np.nan)
            continue
        q = peak + beyond[0]
        t = (profile[q - 1] - level) / (profile[q - 1] - profile[q])
        edges.append(eta[q - 1] + t * (eta[q] - eta[q - 1]))
    edges = np.array(edges)
    valid = np.isfinite(edges)
    fit = np.polyfit(xi[columns][valid], edges[valid], 1)
    scatter = np.sqrt(np.mean((edges[valid] - np.polyval(fit, xi[columns][valid])) ** 2))
    if scatter > FIT_SCATTER * wavelength:
        raise MarinesimError(f"the cusp edges scatter by {scatter / wavelength:.2f} wavelengths about a line "
                             "(bow and stern waves interfere this close to the hull): no Kelvin angle measured")
    return math.degrees(math.atan(fit[0]))


def transverse_wavelength(elevation: np.ndarray, x: np.ndarray, y: np.ndarray, hull_length: float) -> float:
    """Wavelength (m) of the dominant waves along the track line, two hull lengths behind the hull on."""
    row = elevation[int(np.argmin(np.abs(y)))]
    behind = x < x.max() - 2.0 * hull_length
    if behind.sum() < 64:
        raise MarinesimError("the wake grid is too short to measure the transverse wavelength: it must reach "
                             "well beyond two hull lengths behind the hull")
    profile = row[behind] * np.hanning(int(behind.sum()))
    pad = 16 * len(profile)
    power = np.abs(np.fft.rfft(profile, pad)) ** 2
    k = int(np.argmax(power[1:-1])) + 1
    a, b, c = np.log(power[k - 1:k + 2])
    offset = 0.5 * (a - c) / (a - 2.0 * b + c)
    spacing = x[1] - x[0]
    return pad * spacing / (k + offset)
