"""Where the exercise is on the earth: the simulator's flat earth frame placed on the WGS84 ellipsoid.

The simulator's earth frame E (docs/CONVENTIONS.md "Frames and units": x east, y north, z up) is flat.
Here it is the tangent plane of the WGS84 ellipsoid at the scenario's start point (:class:`Origin`):
a ship ``north_m``/``east_m`` from the start sits at that point of the plane, projected along the
ellipsoid normal onto the ellipsoid (height 0). Distances in the plane are kept to a relative error of
about (d / 6400 km)^2, 1e-5 (0.2 m) at 20 km; grid north departs from true north by the meridian
convergence, about (east / 6400 km) tan(latitude) rad (0.18 deg 20 km east at 45 deg latitude).

ECEF (earth-centred, earth-fixed, the DIS world frame of IEEE 1278.1): x through latitude 0 longitude 0,
z through the north pole, y through latitude 0 longitude 90 E; metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from marinesim.errors import require_finite, require_within

WGS84_A = 6378137.0
"""WGS84 semi-major axis (m)."""
WGS84_F = 1.0 / 298.257223563
"""WGS84 flattening."""
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)
"""WGS84 first eccentricity squared."""


@dataclass(frozen=True)
class Origin:
    """The scenario's start point: geodetic latitude and longitude (deg, WGS84; north and east positive)."""

    latitude_deg: float
    longitude_deg: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "latitude_deg", require_within("latitude_deg", self.latitude_deg, -90.0, 90.0,
                                                               "deg"))
        object.__setattr__(self, "longitude_deg", wrap_longitude(require_finite("longitude_deg",
                                                                                self.longitude_deg)))


def wrap_longitude(lon_deg: float) -> float:
    """Longitude (deg) wrapped to [-180, 180)."""
    wrapped = (lon_deg + 180.0) % 360.0 - 180.0
    return -180.0 if wrapped >= 180.0 else wrapped


def radii_of_curvature(lat_deg: float) -> tuple[float, float]:
    """WGS84 meridian radius M and prime-vertical radius N (m) at geodetic latitude ``lat_deg``."""
    s2 = math.sin(math.radians(lat_deg)) ** 2
    w = math.sqrt(1.0 - WGS84_E2 * s2)
    return WGS84_A * (1.0 - WGS84_E2) / w**3, WGS84_A / w


def ecef(lat_deg: float, lon_deg: float, height_m: float = 0.0) -> np.ndarray:
    """ECEF position (3,) in metres of a geodetic latitude, longitude (deg) and ellipsoidal height (m)."""
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    n = radii_of_curvature(lat_deg)[1]
    return np.array([(n + height_m) * math.cos(lat) * math.cos(lon),
                     (n + height_m) * math.cos(lat) * math.sin(lon),
                     (n * (1.0 - WGS84_E2) + height_m) * math.sin(lat)])


def geodetic(point: np.ndarray) -> tuple[float, float, float]:
    """Latitude, longitude (deg, longitude in [-180, 180)) and height (m) of an ECEF point (3,) in metres."""
    x, y, z = (float(c) for c in point)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1.0 - WGS84_E2))
    for _ in range(10):
        sin_lat = math.sin(lat)
        n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * sin_lat**2)
        new = math.atan2(z + WGS84_E2 * n * sin_lat, p)
        done = abs(new - lat) < 1e-15
        lat = new
        if done:
            break
    sin_lat = math.sin(lat)
    height = p * math.cos(lat) + z * sin_lat - WGS84_A * math.sqrt(1.0 - WGS84_E2 * sin_lat**2)
    return math.degrees(lat), wrap_longitude(math.degrees(math.atan2(y, x))), height


def ned_basis(lat_deg: float, lon_deg: float) -> np.ndarray:
    """Local north, east and down unit vectors in ECEF at a geodetic latitude, longitude (deg).

    Returns a (3, 3) matrix whose columns are north, east, down: it turns NED components into ECEF ones.
    """
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
    return np.array([[-sl * co, -so, -cl * co],
                     [-sl * so, co, -cl * so],
                     [cl, 0.0, -sl]])


def position(origin: Origin, north_m: float, east_m: float) -> tuple[float, float]:
    """Latitude, longitude (deg, longitude in [-180, 180)) of the point ``north_m``, ``east_m`` (m) from ``origin``.

    The point of the origin's tangent plane, projected along the ellipsoid normal. To first order this is
    lat0 + north / M, lon0 + east / (N cos lat0) with the WGS84 radii of curvature M, N at the origin;
    that first-order form alone misplaces a point 14 km north and 14 km east by 11 m at 45 deg latitude
    (it stretches east distances by cos lat0 / cos lat), which this form avoids. Non-finite offsets give NaN.
    """
    if not (math.isfinite(north_m) and math.isfinite(east_m)):
        return math.nan, math.nan
    basis = ned_basis(origin.latitude_deg, origin.longitude_deg)
    point = ecef(origin.latitude_deg, origin.longitude_deg) + basis @ np.array([north_m, east_m, 0.0])
    lat, lon, _ = geodetic(point)
    return lat, lon


def ecef_orientation(lat_deg: float, lon_deg: float, heading_rad: float, pitch_rad: float,
                     roll_rad: float) -> tuple[float, float, float]:
    """DIS Euler angles (psi, theta, phi) in radians of a vessel at a geodetic latitude, longitude (deg).

    ``heading_rad`` is the compass heading (clockwise from true north), ``pitch_rad`` the pitch with the bow
    UP positive and ``roll_rad`` the roll with starboard DOWN positive (the NED/aeronautical convention: body
    axes x forward, y starboard, z down; rotations z-y-x from north-east-down). The result rotates the same
    body axes from the ECEF axes by psi about z, then theta about the new y, then phi about the new x
    (IEEE 1278.1 Euler angles): body -> ECEF = Rz(psi) Ry(theta) Rx(phi). psi, phi in [-pi, pi],
    theta in [-pi/2, pi/2]; where theta is +-pi/2 (body x along the earth's axis) phi is set to 0.
    """
    body_to_ned = _rz(heading_rad) @ _ry(pitch_rad) @ _rx(roll_rad)
    r = ned_basis(lat_deg, lon_deg) @ body_to_ned
    horizontal = math.hypot(r[0, 0], r[1, 0])
    theta = math.atan2(-r[2, 0], horizontal)
    if horizontal < 1e-12:
        return math.atan2(-r[0, 1], r[1, 1]), theta, 0.0
    return math.atan2(r[1, 0], r[0, 0]), theta, math.atan2(r[2, 1], r[2, 2])


def euler_matrix(psi: float, theta: float, phi: float) -> np.ndarray:
    """Body -> world rotation (3, 3) Rz(psi) Ry(theta) Rx(phi) of z-y-x Euler angles (rad)."""
    return _rz(psi) @ _ry(theta) @ _rx(phi)


def _rx(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _rz(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
