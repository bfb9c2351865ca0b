"""The names users give wave spectra and directional spreading (CLI options, scenario keys), which
parameters each kind of wave system takes, and the ranges a real sea has.

Kept apart from the builders, which import scipy, so that the command line lists them at once. The
ranges are the one source of the scenario model's bounds and of :func:`marinesim.sea.build.wave_system`'s
(which the ``sea`` command's options go through).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

from marinesim.constants import G

SPECTRUM_TYPES = ("jonswap", "pm", "tma", "regular")
SPREADING_TYPES = ("cos2s", "mitsuyasu", "cos2n-halfplane", "long-crested")
SPECTRA = ("jonswap", "pm", "tma")

MAX_HS_M = 30.0
"""Significant wave height (m): the highest measured are near 20 m."""
PERIOD_RANGE_S = (1.0, 40.0)
"""Peak or regular wave period (s): a 1 s wave is 1.6 m long (a tank's), swell rarely exceeds 25 s."""
MAX_WAVE_HEIGHT_M = 30.0
"""Regular wave height (m): the highest single waves measured are near 30 m."""
MAX_U10_M_S = 60.0
"""Wind speed at 10 m (m/s): above the strongest sustained hurricane winds."""
MAX_FETCH_KM = 5000.0
"""Fetch (km): an ocean basin."""
CHOPPINESS_RANGE = (0.0, 2.0)
"""Horizontal displacement factor: 1 is Gerstner's; beyond 2 every wave folds over itself."""
MAX_DEPTH_M = 11000.0
"""Water depth (m): the deepest ocean trench."""
BREAKING_DEPTH_RATIO = 0.78
"""The highest wave water of depth h holds, H / h (McCowan's solitary wave; in the surf zone irregular seas saturate
lower, near Hs / h = 0.6): a sea's Hs above it in that depth has broken."""
FETCH_LIMITED = (1.0, 2.2e4)
"""Dimensionless fetch g F / U10^2 over which JONSWAP's fetch-limited growth (Hasselmann et al. 1973) holds: below
1 the fetch is a few wave lengths; beyond 2.2e4 the sea is fully developed and grows no more, so a longer fetch
counts as 2.2e4 (:func:`fetch_limited`)."""
MAX_WAVE_SYSTEMS = 10
"""Wave systems in one sea: a wind sea and its swells (partitioned buoy spectra hold a handful)."""
BREAKING_STEEPNESS = 1.0 / 7.0
"""The steepest a sea can be, Hs / Lp with Lp = g Tp^2 / (2 pi) the deep-water length of its peak: a single wave
breaks at H / L = 1/7 (Michell 1893), and a sea's significant steepness stays well below it."""
MAX_RESOLUTION = 4096
"""Samples per tile side: 4096^2 cells already take gigabytes per tile."""
MAX_TIME_S = 1e6
"""Time of a surface sample (s, 11.6 days): later, float32 phases lose the wave's shape."""

RANGES = {"hs": (0.0, MAX_HS_M, "m"), "tp": (*PERIOD_RANGE_S, "s"), "height": (0.0, MAX_WAVE_HEIGHT_M, "m"),
          "period": (*PERIOD_RANGE_S, "s"), "u10": (0.0, MAX_U10_M_S, "m/s"), "fetch_km": (0.0, MAX_FETCH_KM, "km")}
"""Wave-system parameter -> (low, high, unit): the range :func:`~marinesim.sea.build.wave_system` accepts."""
APPLIES_TO = {"hs": SPECTRA, "tp": SPECTRA, "gamma": ("jonswap", "tma"), "u10": ("jonswap",),
              "fetch_km": ("jonswap",), "spreading": SPECTRA, "spreading_s": SPECTRA,
              "height": ("regular",), "period": ("regular",), "phase_deg": ("regular",)}
"""Wave-system parameter -> the kinds of wave system that take it."""
FROM_WIND = ("hs", "tp", "gamma")
"""Parameters a JONSWAP from wind (u10 and fetch_km) sets itself."""


def fetch_limited(u10: float, fetch_m: float, g: float = G) -> tuple[float, float]:
    """(dimensionless fetch x = g F / U10^2, at most :data:`FETCH_LIMITED`'s fully developed end; the JONSWAP peak
    frequency wp = 22 (g / U10) x^(-1/3), rad/s) of a wind ``u10`` (m/s) over ``fetch_m`` (m)."""
    x = FETCH_LIMITED[1] if g * fetch_m >= FETCH_LIMITED[1] * u10**2 else g * fetch_m / u10**2
    return x, 22.0 * g / u10 * x ** (-1.0 / 3.0)


def wind_sea_refusal(u10: float, fetch_km: float, names: tuple[str, str] = ("u10", "fetch_km")) -> str | None:
    """Why a JONSWAP from wind ``u10`` (m/s, > 0) over ``fetch_km`` (km, > 0) has no meaning (a fetch of a few
    wave lengths, below :data:`FETCH_LIMITED`, or a peak period outside :data:`PERIOD_RANGE_S`); None if it has.
    ``names`` are the two keys as the caller's user gives them."""
    fetch = 1000.0 * fetch_km
    if G * fetch < FETCH_LIMITED[0] * u10**2:
        return (f"{names[0]} {u10:g} m/s over {names[1]} {fetch_km:g} km is a fetch of a few wave lengths, where "
                f"JONSWAP's fetch-limited growth does not hold (g F / U10^2 at least {FETCH_LIMITED[0]:g}: "
                f"{names[0]} at most {math.sqrt(G * fetch / FETCH_LIMITED[0]):.3g} m/s at that fetch)")
    tp = 2.0 * math.pi / fetch_limited(u10, fetch)[1]
    if not PERIOD_RANGE_S[0] <= tp <= PERIOD_RANGE_S[1]:
        return (f"{names[0]} {u10:g} m/s over {names[1]} {fetch_km:g} km gives a peak period of {tp:.3g} s, "
                f"outside {PERIOD_RANGE_S[0]:g}..{PERIOD_RANGE_S[1]:g} s")
    return None


def refusal(kind: str, name: str, given: Iterable[str]) -> str | None:
    """Why the parameter ``name`` may not be given to a ``kind`` wave system along with ``given``; None if it may."""
    if kind not in APPLIES_TO[name]:
        return f"does not apply to a {kind} wave system (only to {', '.join(APPLIES_TO[name])})"
    if name in FROM_WIND and "u10" in given:
        return "does not apply with u10 (the wind speed and fetch give the spectrum)"
    if name == "fetch_km" and "u10" not in given:
        return "applies only with u10 (a JONSWAP from wind speed and fetch)"
    return None


def misplaced(kind: str, given: Iterable[str]) -> tuple[str, str] | None:
    """The first of the ``given`` parameters that a ``kind`` wave system does not take, and why; None if all fit."""
    given = list(given)
    return next(((name, why) for name in given if (why := refusal(kind, name, given)) is not None), None)
