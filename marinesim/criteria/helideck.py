"""Helideck motion as helideck monitoring systems report it (CAP 437 and the HCA helideck
monitoring standard it calls for), over 20-minute windows of the helideck point's record.

- Significant heave rate: 2 x the RMS of the vertical velocity (m/s), as significant wave height
  is 4 x RMS of elevation for amplitudes.
- Maximum average heave rate (MAHR): the largest heave excursion of one oscillation (max minus min
  between two zero-upcrossings of the heave about its window mean) over half the mean
  zero-upcrossing period (m/s); for a sinusoid of amplitude A and period T, 4A/T, the mean rate of
  a half-cycle (its peak rate is 2 pi A/T).
"""

from __future__ import annotations

import math

import numpy as np

from marinesim.criteria.statistics import rms, zero_upcrossings


def significant_heave_rate(vz: np.ndarray) -> float:
    """2 x RMS of the vertical velocity ``vz`` (m/s)."""
    return 2.0 * rms(vz)


def mahr(heave: np.ndarray, dt: float) -> float:
    """Maximum average heave rate (m/s) of a heave record (m, every ``dt`` s); NaN with fewer than two
    upcrossings."""
    x = np.asarray(heave, float)
    x = x - x.mean() if x.size else x
    crossings = zero_upcrossings(x, dt)
    if crossings.size < 2:
        return math.nan
    starts = np.ceil(crossings / dt - 1e-9).astype(int)   # first sample of each oscillation
    whole = x[:starts[-1]]                                 # complete oscillations only
    heights = np.maximum.reduceat(whole, starts[:-1]) - np.minimum.reduceat(whole, starts[:-1])
    half_period = 0.5 * (crossings[-1] - crossings[0]) / (crossings.size - 1)
    return float(heights.max() / half_period)
