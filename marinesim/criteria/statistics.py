"""Short-term statistics of a sampled motion record (REFERENCES section 8).

A linear response in a stationary sea is a zero-mean Gaussian process: its RMS is sigma = sqrt(m0),
its zero-upcrossings come every Tz = 2 pi sqrt(m0/m2) on average (Rice), and the amplitude of one
oscillation of a narrow-band response is Rayleigh distributed, so the probability per oscillation
that it exceeds h is exp(-h^2 / (2 sigma^2)) (Ochi 1964: the NORDFORSK 1987 deck wetness probability, and the
emergence that their slamming probability also asks a relative velocity of). Records are 1-D arrays sampled
every ``dt`` s.
"""

from __future__ import annotations

import math

import numpy as np


def rms(x: np.ndarray) -> float:
    """Root mean square about zero (a linear response has zero mean), in the record's unit."""
    x = np.asarray(x, float)
    return float(np.sqrt(np.mean(x * x))) if x.size else math.nan


def max_abs(x: np.ndarray) -> float:
    """The largest |x| of the record."""
    x = np.asarray(x, float)
    return float(np.max(np.abs(x))) if x.size else math.nan


def zero_upcrossings(x: np.ndarray, dt: float) -> np.ndarray:
    """Times (s from the first sample) where ``x`` crosses zero upward, interpolated linearly."""
    x = np.asarray(x, float)
    i = np.flatnonzero((x[:-1] < 0.0) & (x[1:] >= 0.0))
    return (i + x[i] / (x[i] - x[i + 1])) * dt


def mean_upcrossing_period(x: np.ndarray, dt: float) -> float:
    """Mean zero-upcrossing period Tz (s): the span of the upcrossings over their number less one;
    NaN with fewer than two."""
    times = zero_upcrossings(x, dt)
    return float((times[-1] - times[0]) / (times.size - 1)) if times.size >= 2 else math.nan


def rayleigh_exceedance(sigma: float, threshold: float) -> float:
    """Probability per oscillation that the amplitude of a narrow-band Gaussian response of standard
    deviation ``sigma`` exceeds ``threshold`` (same unit): ``exp(-threshold^2 / (2 sigma^2))``."""
    if not sigma > 0.0:
        return 0.0 if sigma == 0.0 else math.nan
    return math.exp(-threshold * threshold / (2.0 * sigma * sigma))


def inclination_deg(roll_deg: np.ndarray, pitch_deg: np.ndarray) -> np.ndarray:
    """Angle between the deck normal and the vertical (deg): ``arccos(cos(roll) cos(pitch))``, the
    z component of ``R e_z`` for ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (yaw does not tilt the deck)."""
    c = np.cos(np.radians(roll_deg)) * np.cos(np.radians(pitch_deg))
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))
