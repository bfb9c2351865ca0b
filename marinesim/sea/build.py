"""Wave systems from the words users give (CLI options, scenario keys): one builder for both.

Directions come in as compass degrees the waves come *from* and are converted here, once
(docs/CONVENTIONS.md).
"""

from __future__ import annotations

import math

from marinesim.angles import wave_beta_from_compass
from marinesim.constants import G
from marinesim.errors import ParameterError, require_finite, require_positive, require_within
from marinesim.sea.kinds import RANGES, SPECTRUM_TYPES, SPREADING_TYPES, misplaced, wind_sea_refusal
from marinesim.sea.seastate import RegularWave, WaveSystem
from marinesim.sea.spectra import Jonswap, JonswapFetch, PiersonMoskowitz, Tma
from marinesim.sea.spreading import Cos2s, HalfPlaneCos2n, LongCrested, Mitsuyasu, Spreading


def wave_system(
    kind: str,
    *,
    from_deg: float,
    hs: float | None = None,
    tp: float | None = None,
    gamma: float | None = None,
    u10: float | None = None,
    fetch_km: float | None = None,
    height: float | None = None,
    period: float | None = None,
    phase_deg: float | None = None,
    spreading: str | None = None,
    spreading_s: float | None = None,
    depth: float = math.inf,
) -> WaveSystem | RegularWave:
    """One wave system. ``spreading`` defaults to cos2s when ``spreading_s`` is given, else none.

    ``u10`` (m/s, with ``fetch_km``) gives a JONSWAP spectrum from wind and fetch instead of
    (hs, tp). ``depth`` (m) is needed by ``tma``. A parameter the kind does not take
    (:data:`~marinesim.sea.kinds.APPLIES_TO`) or outside its :data:`~marinesim.sea.kinds.RANGES` is refused.
    """
    if kind not in SPECTRUM_TYPES:
        raise ParameterError(f"wave type must be one of {', '.join(SPECTRUM_TYPES)}, got {kind!r}")
    given = {name: value for name, value in (
        ("hs", hs), ("tp", tp), ("gamma", gamma), ("u10", u10), ("fetch_km", fetch_km), ("height", height),
        ("period", period), ("phase_deg", phase_deg), ("spreading", spreading), ("spreading_s", spreading_s))
        if value is not None}
    wrong = misplaced(kind, given)
    if wrong is not None:
        raise ParameterError(f"{wrong[0]} {wrong[1]}")
    for name, value in given.items():
        if name in RANGES:
            require_within(name, value, *RANGES[name])
    if u10 is not None and fetch_km is not None and (why := wind_sea_refusal(u10, fetch_km)) is not None:
        raise ParameterError(why)
    beta = wave_beta_from_compass(require_finite("from_deg", from_deg))
    if kind == "regular":
        return RegularWave(_given("height", height), _given("period", period), beta,
                           math.radians(require_finite("phase_deg", phase_deg or 0.0)))
    if u10 is not None:
        if kind != "jonswap":
            raise ParameterError(f"wind speed u10 gives a JONSWAP spectrum, not {kind}")
        spectrum = JonswapFetch(u10, 1000.0 * require_positive("fetch_km", _given("fetch_km", fetch_km)))
    elif kind == "pm":
        spectrum = PiersonMoskowitz(_given("hs", hs), _given("tp", tp))
    elif kind == "tma":
        if math.isinf(depth):
            raise ParameterError("a TMA spectrum needs a finite water depth")
        spectrum = Tma(_given("hs", hs), _given("tp", tp), gamma, depth=depth)
    else:
        spectrum = Jonswap(_given("hs", hs), _given("tp", tp), gamma)
    return WaveSystem(spectrum, beta, _spreading(spreading, spreading_s, spectrum.tp, u10))


def _given(name: str, value: float | None) -> float:
    if value is None:
        raise ParameterError(f"{name} is required for this wave type")
    return value


def _spreading(kind: str | None, s: float | None, tp: float, u10: float | None) -> Spreading:
    kind = kind or ("cos2s" if s is not None else "long-crested")
    if kind not in SPREADING_TYPES:
        raise ParameterError(f"spreading must be one of {', '.join(SPREADING_TYPES)}, got {kind!r}")
    if kind == "long-crested":
        return LongCrested()
    omega_peak = 2.0 * math.pi / tp
    if kind == "mitsuyasu" and s is None and u10 is not None:
        return Mitsuyasu.from_wind(u10, omega_peak, G)
    if s is None:
        raise ParameterError(f"spreading {kind} needs spreading-s")
    if kind == "cos2s":
        return Cos2s(s)
    if kind == "mitsuyasu":
        return Mitsuyasu(s, omega_peak)
    return HalfPlaneCos2n(s)
