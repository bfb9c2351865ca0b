"""The light a frame is drawn in: the sun and the moon, how bright the sky is, the cloud and the air.

:func:`light_at` turns a scenario's ``[environment]`` (and the live changes to it) into a :class:`Light` at a
time of the run. The sun and the moon come from the date and the position through ``astral`` (NOAA's solar
equations, Meeus's lunar series), or the sun from its fixed bearing and elevation. Everything else is drawn
from a few published laws, stated where they are used:

- the direct sun through the air mass of Kasten & Young (1989), reddened by a per-channel optical depth;
- the brightness of the sky against the sun's elevation, as an eye adapted to it sees it (day, civil, nautical
  and astronomical twilight, night), and the moon's light by its illuminated fraction ``(1 - cos psi) / 2``;
- the global irradiance under ``N`` oktas of cloud, ``1 - 0.75 (N/8)^3.4`` of the clear sky's (Kasten &
  Czeplak 1980), which sets how grey an overcast day is;
- rain by the Marshall & Palmer (1948) drop sizes, ``N(D) = N0 exp(-Lambda D)``, ``N0 = 8000 m^-3 mm^-1``,
  ``Lambda = 4.1 R^-0.21 mm^-1`` for a rate ``R`` (mm/h): the drops large enough to be seen as streaks (over 1 mm)
  number ``N0 / Lambda exp(-Lambda)`` per m^3, which sets how many streaks fall;
- the wind, when the scenario does not give it, from the sea: the first wave system's U10, or the wind of a fully
  developed (Pierson-Moskowitz) sea of its peak period, ``U19.5 = 0.877 g / wp`` and ``U10 = U19.5 / 1.075``.

Vectors are unit vectors towards the body in the E frame (x east, y north, z up).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from datetime import timedelta, timezone

import numpy as np

from marinesim.angles import compass_to_math
from marinesim.scenario.model import EnvironmentOptions, wind_of
from marinesim.sea.seastate import SeaState

EXTINCTION = np.array([0.025, 0.060, 0.150])
"""Vertical optical depth of the air for the sun's red, green and blue (Rayleigh and aerosol, a clear day)."""
ADAPTED_SKY = ((-18.0, -2.6), (-12.0, -2.2), (-6.0, -1.4), (0.0, -0.5), (6.0, -0.12), (12.0, 0.0))
"""log10 of the sky's brightness against a clear day as the adapted eye sees it, at sun elevations (deg): the
real illuminance falls by eight decades from noon to night, the eye's adaptation takes up most of them."""
MARSHALL_PALMER_N0, MARSHALL_PALMER_SLOPE, VISIBLE_DROP_MM = 8000.0, 4.1, 1.0
"""N0 (m^-3 mm^-1), the slope's factor (mm^-1) and the smallest drop seen as a streak (mm)."""
SUN_AT_ZENITH = np.array([1.00, 0.95, 0.88])
"""The sun's direct light from the zenith (linear RGB): the lower the sun, the redder (:data:`EXTINCTION`)."""
MOON_PARALLAX_DEG = 0.9507
"""The moon's mean equatorial horizontal parallax (57.04 arcmin)."""
FULL_MOON = 10 ** -1.6
"""A full moon high in the sky, on the same scale: some 0.3 lux against starlight's 0.002."""


@dataclass(frozen=True)
class Light:
    """What lights the scene at one instant. ``sun``/``moon``: unit vectors (E frame); ``sun_colour`` and
    ``moon_colour``: their direct light on a surface facing them (linear RGB, 0 below the horizon, before clouds);
    ``sky``: the sky's brightness against a clear day; ``cloud``: cloud cover (fraction 0..1); ``visibility_m``;
    ``wind``: the unit vector it blows towards (E frame, x and y) and its speed at 10 m (m/s); ``rain_mm_h``."""

    sun: tuple[float, float, float]
    moon: tuple[float, float, float]
    sun_colour: tuple[float, float, float]
    moon_colour: tuple[float, float, float]
    sky: float
    cloud: float
    visibility_m: float
    wind: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rain_mm_h: float = 0.0

    def uniforms(self) -> dict[str, object]:
        """The uniforms of ``shaders/sky.glsl``."""
        return {"u_sun": self.sun, "u_moon": self.moon, "u_sun_colour": self.sun_colour,
                "u_moon_colour": self.moon_colour, "u_sky": self.sky, "u_cloud": self.cloud,
                "u_visibility": self.visibility_m}


def direction(azimuth_deg: float, elevation_deg: float) -> tuple[float, float, float]:
    """Unit vector (E frame) towards a compass bearing and an elevation (deg)."""
    azimuth, elevation = compass_to_math(azimuth_deg), math.radians(elevation_deg)
    return (math.cos(elevation) * math.cos(azimuth), math.cos(elevation) * math.sin(azimuth), math.sin(elevation))


def air_mass(elevation_deg: float) -> float:
    """Relative optical air mass at an apparent elevation (deg), Kasten & Young (1989); 1 at the zenith."""
    h = max(elevation_deg, -0.5)
    return 1.0 / (math.sin(math.radians(h)) + 0.50572 * (h + 6.07995) ** -1.6364)


def direct_colour(elevation_deg: float, strength: float = 1.0) -> tuple[float, float, float]:
    """The direct light of a body at ``elevation_deg`` through the air (linear RGB), 0 once it has set."""
    if elevation_deg <= -0.5:
        return (0.0, 0.0, 0.0)
    above = min((elevation_deg + 0.5) / 1.0, 1.0)  # its disc sinks below the horizon over about a degree
    colour = strength * above * SUN_AT_ZENITH * np.exp(-EXTINCTION * (air_mass(elevation_deg) - 1.0))
    return tuple(float(c) for c in colour)


def sky_brightness(sun_elevation_deg: float) -> float:
    """The sky's brightness against a clear day's, as the adapted eye sees it (:data:`ADAPTED_SKY`)."""
    elevations, logs = zip(*ADAPTED_SKY)
    return float(10.0 ** np.interp(sun_elevation_deg, elevations, logs))


def cloud_light(oktas: float) -> float:
    """Global irradiance under ``oktas`` of cloud against a clear sky's (Kasten & Czeplak 1980)."""
    return 1.0 - 0.75 * (oktas / 8.0) ** 3.4


def illuminated_fraction(sun: tuple[float, float, float], moon: tuple[float, float, float]) -> float:
    """The moon's lit fraction from its elongation psi from the sun: (1 - cos psi) / 2 (the sun's distance,
    400 times the moon's, makes the phase angle 180 deg - psi)."""
    return 0.5 * (1.0 - float(np.dot(sun, moon)))


def bodies_at(environment: EnvironmentOptions, t_s: float) -> tuple[tuple[float, float, float], ...]:
    """Unit vectors towards the sun and the moon (E frame) ``t_s`` seconds into the run: from the date and the
    position (the moon at the nadir without one, so that it gives no light)."""
    if environment.time_utc is None:
        return direction(environment.sun_azimuth_deg, environment.sun_elevation_deg), (0.0, 0.0, -1.0)
    import astral
    import astral.moon
    import astral.sun

    when = (environment.time_utc + timedelta(seconds=t_s)).astimezone(timezone.utc)  # astral's moon reads the clock
    observer = astral.Observer(environment.latitude_deg, environment.longitude_deg)
    # astral's sun elevation includes refraction; its moon is geocentric: seen from the Earth's surface it stands
    # lower by the parallax, the mean horizontal parallax times the cosine of its elevation
    sun = direction(astral.sun.azimuth(observer, when), astral.sun.elevation(observer, when))
    geocentric = astral.moon.elevation(observer, when)
    moon = direction(astral.moon.azimuth(observer, when),
                     geocentric - MOON_PARALLAX_DEG * math.cos(math.radians(geocentric)))
    return sun, moon


def visible_drops_m3(rain_mm_h: float) -> float:
    """Drops over 1 mm across per m^3 of air in rain of ``rain_mm_h`` (Marshall & Palmer 1948); 0 without rain."""
    if rain_mm_h <= 0.0:
        return 0.0
    slope = MARSHALL_PALMER_SLOPE * rain_mm_h ** -0.21  # Lambda, per mm
    return MARSHALL_PALMER_N0 / slope * math.exp(-slope * VISIBLE_DROP_MM)


def light_at(environment: EnvironmentOptions, t_s: float = 0.0, sea: SeaState | None = None) -> Light:
    """The light ``t_s`` seconds into a run under ``environment``, the wind from ``sea`` where it gives none."""
    sun, moon = bodies_at(environment, t_s)
    sun_elevation = math.degrees(math.asin(sun[2]))
    moon_elevation = math.degrees(math.asin(moon[2]))
    lit = illuminated_fraction(sun, moon)
    clouds = cloud_light(environment.cloud_cover_oktas)
    moon_sky = FULL_MOON * lit * max(math.sin(math.radians(moon_elevation)), 0.0) ** 0.5
    return Light(sun=sun, moon=moon, sun_colour=direct_colour(sun_elevation),
                 moon_colour=direct_colour(moon_elevation, 2.0 * FULL_MOON * lit),
                 sky=clouds * (sky_brightness(sun_elevation) + moon_sky),
                 cloud=environment.cloud_cover_oktas / 8.0, visibility_m=environment.visibility_m,
                 wind=wind_of(environment, sea), rain_mm_h=environment.rain_mm_h)
