"""The names users give wave spectra and directional spreading (CLI options, scenario keys), which
parameters each kind of wave system takes, and the ranges a real sea has.

Kept apart from the builders, which import scipy, so that the command line lists them at once. The
ranges are the one source of the scenario model's bounds and of :func:`marinesim.sea.build.wave_system`'s
(which the ``sea`` command's options go through).
"""

from __future__ import annotations

from collections.abc import Iterable

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
