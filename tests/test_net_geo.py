"""The exercise's place on the earth (marinesim.net.geo): flat earth frame -> WGS84, ECEF, DIS Euler angles."""

import math

import numpy as np
import pytest

from marinesim.errors import ParameterError
from marinesim.net import geo

A = 6378137.0
B = A * (1.0 - 1.0 / 298.257223563)  # WGS84 semi-minor axis from its defining constants
OFFSETS = [(20e3, 0.0), (0.0, 20e3), (14142.0, 14142.0), (-14142.0, 14142.0), (-3000.0, -4000.0), (1.0, -2.0)]


def textbook_ecef(lat_deg: float, lon_deg: float, h: float = 0.0) -> np.ndarray:
    """ECEF (m) of a geodetic point (deg, m) in the textbook semi-axes form, written out here:
    N = a^2 / sqrt(a^2 cos^2 lat + b^2 sin^2 lat), x, y = (N + h) cos lat (cos lon, sin lon),
    z = (N b^2 / a^2 + h) sin lat."""
    lat, lon = math.radians(lat_deg), math.radians(lon_deg)
    n = A * A / math.sqrt((A * math.cos(lat)) ** 2 + (B * math.sin(lat)) ** 2)
    return np.array([(n + h) * math.cos(lat) * math.cos(lon), (n + h) * math.cos(lat) * math.sin(lon),
                     (n * B * B / (A * A) + h) * math.sin(lat)])


def chord(p: tuple[float, float], q: tuple[float, float]) -> float:
    """Straight-line ECEF distance (m) of two geodetic points (deg) on the ellipsoid."""
    return float(np.linalg.norm(textbook_ecef(*p) - textbook_ecef(*q)))


@pytest.mark.parametrize("lat0, lon0", [(0.0, 0.0), (45.0, 10.0), (60.0, -5.0), (-33.9, 151.2)])
@pytest.mark.parametrize("north, east", OFFSETS)
def test_position_is_the_tangent_plane_point_projected_along_the_normal(lat0, lon0, north, east):
    """The point must lie on the ellipsoid normal through the origin's tangent-plane point P = O + north n + east e
    (n = (-sin lat cos lon, -sin lat sin lon, cos lat), e = (-sin lon, cos lon, 0) written out by hand), within
    1 mm, and below P by about d^2 / 2R (31 m at 20 km); otherwise the ship is misplaced or off the surface."""
    la, lo = math.radians(lat0), math.radians(lon0)
    n_axis = np.array([-math.sin(la) * math.cos(lo), -math.sin(la) * math.sin(lo), math.cos(la)])
    e_axis = np.array([-math.sin(lo), math.cos(lo), 0.0])
    plane_point = textbook_ecef(lat0, lon0) + north * n_axis + east * e_axis
    lat, lon = geo.position(geo.Origin(lat0, lon0), north, east)
    drop = textbook_ecef(lat, lon) - plane_point
    up = np.array([math.cos(math.radians(lat)) * math.cos(math.radians(lon)),
                   math.cos(math.radians(lat)) * math.sin(math.radians(lon)), math.sin(math.radians(lat))])
    assert np.linalg.norm(np.cross(drop, up)) < 1e-3
    assert drop @ up == pytest.approx(-(north**2 + east**2) / (2.0 * A), rel=0.02, abs=1e-4)


@pytest.mark.parametrize("lat0", [0.0, 45.0, 60.0, -45.0])
def test_distances_within_20_km_are_kept_well_under_a_metre(lat0):
    """Distances from the origin (up to 20 km) must match the flat frame's within 0.15 m and those between
    two points (up to 37 km apart) within 1e-5 of themselves; a plain lat0 + north/M, lon0 + east/(N cos lat0)
    is 11 m out at 45 deg 20 km from the origin."""
    origin = geo.Origin(lat0, 30.0)
    points = [(n, e, geo.position(origin, n, e)) for n, e in OFFSETS]
    for n, e, p in points:
        assert chord(p, (lat0, 30.0)) == pytest.approx(math.hypot(n, e), abs=0.15)
    for n1, e1, p in points:
        for n2, e2, q in points:
            assert chord(p, q) == pytest.approx(math.hypot(n1 - n2, e1 - e2), rel=1e-5, abs=1e-3)


@pytest.mark.parametrize("lat0", [0.0, 38.0, -71.0])
def test_small_offsets_follow_the_radii_of_curvature(lat0):
    """10 m north must be 10 m / M of latitude and 10 m east 10 m / (N cos lat) of longitude (the WGS84
    radii of curvature, here from their textbook closed forms); otherwise the scale is wrong."""
    e2 = 1.0 - (B / A) ** 2
    s2 = math.sin(math.radians(lat0)) ** 2
    m = A * (1.0 - e2) / (1.0 - e2 * s2) ** 1.5
    n = A / math.sqrt(1.0 - e2 * s2)
    origin = geo.Origin(lat0, 12.0)
    lat, _ = geo.position(origin, 10.0, 0.0)
    _, lon = geo.position(origin, 0.0, 10.0)
    assert math.radians(lat - lat0) * m == pytest.approx(10.0, rel=1e-5)
    assert math.radians(lon - 12.0) * n * math.cos(math.radians(lat0)) == pytest.approx(10.0, rel=1e-5)


def test_radii_at_the_pole_and_the_equator():
    """At the pole both radii are a^2/b; at the equator N = a and M = b^2/a: otherwise the ellipsoid is wrong."""
    assert geo.radii_of_curvature(90.0) == pytest.approx((A * A / B, A * A / B), rel=1e-12)
    assert geo.radii_of_curvature(0.0) == pytest.approx((B * B / A, A), rel=1e-12)


def test_longitude_wraps_across_the_antimeridian():
    """5 km east of 179.99 E is in the western hemisphere, in [-180, 180), still 5 km away; a missing wrap
    gives a longitude over 180 that no NMEA or DIS reader takes."""
    lat, lon = geo.position(geo.Origin(10.0, 179.99), 0.0, 5000.0)
    assert -180.0 <= lon < -179.9
    assert chord((lat, lon), (10.0, 179.99)) == pytest.approx(5000.0, abs=0.01)
    assert geo.wrap_longitude(180.0) == -180.0 and geo.wrap_longitude(-180.0) == -180.0


def test_ecef_of_known_points_and_round_trip():
    """ECEF must put (0, 0) on +x at a, (0, 90 E) on +y, the pole at z = b, and agree with the semi-axes form
    elsewhere; geodetic() must invert it. A swapped axis or radius would misplace every DIS entity."""
    np.testing.assert_allclose(geo.ecef(0.0, 0.0), [A, 0.0, 0.0], atol=1e-6)
    np.testing.assert_allclose(geo.ecef(0.0, 90.0), [0.0, A, 0.0], atol=1e-6)
    np.testing.assert_allclose(geo.ecef(90.0, 0.0, 100.0), [0.0, 0.0, B + 100.0], atol=1e-6)
    for lat, lon, h in [(37.5, -122.3, 12.0), (-62.0, 170.0, -5.0), (89.9, 45.0, 0.0)]:
        np.testing.assert_allclose(geo.ecef(lat, lon, h), textbook_ecef(lat, lon, h), atol=1e-6)
        assert geo.geodetic(geo.ecef(lat, lon, h)) == pytest.approx((lat, lon, h), abs=1e-9)


def test_dis_angles_of_a_ship_heading_north_at_0_0():
    """At lat 0 lon 0 north is ECEF +z, east +y, down -x: a level ship heading north has body x -> +z,
    y -> +y, z -> -x, i.e. theta = -90 deg (hand-derived); anything else points the ship elsewhere."""
    psi, theta, phi = geo.ecef_orientation(0.0, 0.0, 0.0, 0.0, 0.0)
    assert theta == pytest.approx(-math.pi / 2)
    np.testing.assert_allclose(geo.euler_matrix(psi, theta, phi), [[0, 0, -1], [0, 1, 0], [1, 0, 0]], atol=1e-12)


@pytest.mark.parametrize("lat, lon, heading, expected", [
    (0.0, 0.0, 90.0, (90.0, 0.0, -90.0)),  # body x -> +y (east), y -> -z (south), z -> -x (down)
    (0.0, 90.0, 90.0, (180.0, 0.0, -90.0)),  # at 90 E east is -x, down is -y
    (0.0, 0.0, 270.0, (-90.0, 0.0, 90.0)),  # heading west: x -> -y, y (starboard) -> +z (north)
])
def test_dis_angles_of_level_ships_on_the_equator(lat, lon, heading, expected):
    """Hand-derived DIS angles (deg) of level ships: a wrong axis order or sign turns the ship around."""
    psi, theta, phi = geo.ecef_orientation(lat, lon, math.radians(heading), 0.0, 0.0)
    assert abs(math.degrees(psi) - expected[0]) % 360.0 == pytest.approx(0.0, abs=1e-9)
    assert math.degrees(theta) == pytest.approx(expected[1], abs=1e-9)
    assert math.degrees(phi) == pytest.approx(expected[2], abs=1e-9)


@pytest.mark.parametrize("lat, lon, heading, pitch, roll", [
    (45.0, 10.0, 30.0, 5.0, 10.0), (-33.9, 151.2, 200.0, -4.0, -25.0), (60.0, -5.0, 359.0, 0.0, 30.0),
    (0.0, 0.0, 0.0, 3.0, 2.0), (89.0, 100.0, 123.0, 45.0, -60.0),
])
def test_dis_angles_rebuild_the_body_axes_in_ned(lat, lon, heading, pitch, roll):
    """Rz(psi) Ry(theta) Rx(phi) must turn the body x axis to (cos h cos p, sin h cos p, -sin p) in NED
    (bow up for pitch > 0) and the starboard axis to one with down component cos p sin r (starboard down for
    roll > 0), written out by hand."""
    h, p, r = (math.radians(v) for v in (heading, pitch, roll))
    basis = geo.ned_basis(lat, lon)
    x_ned = [math.cos(h) * math.cos(p), math.sin(h) * math.cos(p), -math.sin(p)]
    y_ned = [math.cos(h) * math.sin(p) * math.sin(r) - math.sin(h) * math.cos(r),
             math.sin(h) * math.sin(p) * math.sin(r) + math.cos(h) * math.cos(r), math.cos(p) * math.sin(r)]
    matrix = geo.euler_matrix(*geo.ecef_orientation(lat, lon, h, p, r))
    np.testing.assert_allclose(matrix[:, 0], basis @ x_ned, atol=1e-12)
    np.testing.assert_allclose(matrix[:, 1], basis @ y_ned, atol=1e-12)
    np.testing.assert_allclose(matrix[:, 2], np.cross(basis @ x_ned, basis @ y_ned), atol=1e-12)


def test_ned_basis_is_right_handed_and_down_points_into_the_earth():
    """North x east = down, and down must point from the surface towards the earth's centre."""
    basis = geo.ned_basis(52.0, 4.0)
    np.testing.assert_allclose(np.cross(basis[:, 0], basis[:, 1]), basis[:, 2], atol=1e-12)
    assert basis[:, 2] @ geo.ecef(52.0, 4.0) < -0.99 * np.linalg.norm(geo.ecef(52.0, 4.0))


@pytest.mark.parametrize("lat, lon", [(95.0, 0.0), (float("nan"), 0.0), (0.0, float("inf"))])
def test_bad_origin_is_refused_in_one_line(lat, lon):
    """An origin off the earth must be refused naming the field, not produce NaN sentences later."""
    with pytest.raises(ParameterError, match="latitude_deg|longitude_deg") as caught:
        geo.Origin(lat, lon)
    assert "\n" not in str(caught.value)
