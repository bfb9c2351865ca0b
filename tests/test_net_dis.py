"""Own ship's DIS Entity State PDU (marinesim.net.dis), checked against a PDU written by Open-DIS and read back."""

import math
from pathlib import Path

import numpy as np
import pytest

from marinesim.errors import ParameterError
from marinesim.net import dis, geo

ORIGIN = geo.Origin(50.5, -1.25)
KNOT = 1852.0 / 3600.0
OPEN_DIS_PDU = Path(__file__).parent / "data" / "dis" / "EntityStatePdu-26.raw"


def make_row(**changes: float) -> dict[str, float]:
    row = dict(north_m=3000.0, east_m=-4000.0, heading_deg=30.0, course_over_ground_deg=0.0,
               speed_over_ground_kn=12.0, rate_of_turn_deg_min=0.0, rudder_deg=0.0, roll_deg=0.0, pitch_deg=0.0,
               heave_m=0.0)
    row.update(changes)
    return row


def test_decode_reads_the_open_dis_entity_state_pdu():
    """The Entity State PDU shipped with open-dis-python (tests/EntityStatePdu-26.raw, written by another DIS
    program) must decode to the values open-dis-python's own tests/test_EntityStatePdu.py asserts: DIS 6,
    exercise 7, entity 42:4:26, force 1, entity type 1:1:39:7:2:1:0 (and the same alternative type), no
    velocity, location (4374082.80485589, 1667679.95730107, 4318284.36890269) m, psi 1.93505, theta 0,
    phi -2.31924 rad, marking "26". A field read at the wrong offset or with the wrong size fails here."""
    state = dis.decode(OPEN_DIS_PDU.read_bytes())
    assert (state.protocol_version, state.exercise_id) == (6, 7)
    assert state.entity_id == (42, 4, 26)
    assert state.force_id == 1
    assert state.entity_type == state.alternative_entity_type == (1, 1, 39, 7, 2, 1, 0)
    assert state.velocity == (0.0, 0.0, 0.0)
    assert state.location == pytest.approx((4374082.80485589, 1667679.95730107, 4318284.36890269), abs=1e-7)
    assert state.orientation.psi == pytest.approx(1.93505, abs=5e-6)
    assert state.orientation.theta == pytest.approx(0.0, abs=1e-7)
    assert state.orientation.phi == pytest.approx(-2.31924, abs=5e-6)
    assert state.marking == "26"


def test_the_open_dis_pdu_is_a_level_vehicle_our_angles_reproduce():
    """The open-dis PDU is a land platform 499 m above the ellipsoid at 42.88 N 20.87 E; its Euler angles
    put the body x axis due east and z straight down. geo.ecef_orientation of a level vehicle heading
    090 there must give the same angles (to float32 precision): a receiver and this sender reading DIS
    angles differently would turn or tilt every ship."""
    state = dis.decode(OPEN_DIS_PDU.read_bytes())
    lat, lon, height = geo.geodetic(np.array(state.location))
    assert (lat, lon) == pytest.approx((42.8825, 20.8700), abs=1e-4) and 0.0 < height < 1000.0
    axes_ned = geo.ned_basis(lat, lon).T @ geo.euler_matrix(*state.orientation)
    np.testing.assert_allclose(axes_ned, [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-6)
    ours = geo.ecef_orientation(lat, lon, math.radians(90.0), 0.0, 0.0)
    np.testing.assert_allclose(ours, state.orientation, atol=2e-6)


def test_header_identity_and_location():
    """The PDU must be 144 bytes, a DIS 7 Entity State PDU (decode checks type 1, family 1 and the length
    field), with the given exercise, entity id, force 1, a surface platform (kind 1, domain 2), the marking
    as ASCII text and the location at the row's place on the ellipsoid: a receiver uses each of these to
    show the ship."""
    row = make_row()
    data = dis.entity_state(row, ORIGIN, 10.0, entity_id=(3, 4, 5), marking="HMS TEST", exercise_id=7)
    assert len(data) == 144
    pdu = dis.decode(data)
    assert (pdu.protocol_version, pdu.exercise_id) == (7, 7)
    assert pdu.entity_id == (3, 4, 5)
    assert pdu.force_id == 1
    assert (pdu.entity_type.kind, pdu.entity_type.domain) == (1, 2)
    assert pdu.marking_character_set == 1 and pdu.marking == "HMS TEST"
    expected = geo.ecef(*geo.position(ORIGIN, row["north_m"], row["east_m"]))
    np.testing.assert_allclose(pdu.location, expected, atol=1e-6)
    assert np.linalg.norm(expected - geo.ecef(ORIGIN.latitude_deg, ORIGIN.longitude_deg)) == pytest.approx(
        5000.0, abs=0.1)
    assert dis.decode(dis.entity_state(row, ORIGIN, 0.0, marking="ELEVENCHARS")).marking == "ELEVENCHARS"


def test_dead_reckoning_one_second_ahead_reaches_the_next_position():
    """The PDU must ask for DRM(F,P,W) (algorithm 2: location + velocity t), and that extrapolation over 1 s
    must land within 2 cm of the PDU of the row 12 kn * 1 s further along the course (the meridian
    convergence 4 km west of the origin bends the course by 5 mm); a static algorithm or a wrong velocity
    leaves a receiver's ship behind or off course."""
    course = 40.0
    row = make_row(course_over_ground_deg=course)
    now = dis.decode(dis.entity_state(row, ORIGIN, 0.0))
    step = 12.0 * KNOT
    later_row = make_row(course_over_ground_deg=course,
                         north_m=row["north_m"] + step * math.cos(math.radians(course)),
                         east_m=row["east_m"] + step * math.sin(math.radians(course)))
    later = dis.decode(dis.entity_state(later_row, ORIGIN, 1.0))
    assert now.dead_reckoning_algorithm == 2
    extrapolated = np.array(now.location) + np.array(now.velocity) * 1.0
    assert np.linalg.norm(extrapolated - np.array(later.location)) < 0.02
    assert np.linalg.norm(np.array(later.location) - np.array(now.location)) == pytest.approx(step, abs=1e-3)


def test_orientation_bow_down_and_starboard_down_point_down():
    """With the record's pitch +5 (bow DOWN) and roll +10 (starboard DOWN) the decoded body x (bow) must
    dip sin 5 deg below the horizon, point along the heading, and the starboard axis dip cos 5 sin 10; a
    pitch sign not converted to DIS's bow-up would raise the bow instead."""
    row = make_row(heading_deg=30.0, pitch_deg=5.0, roll_deg=10.0)
    pdu = dis.decode(dis.entity_state(row, ORIGIN, 0.0))
    matrix = geo.euler_matrix(*pdu.orientation)
    basis = geo.ned_basis(*geo.position(ORIGIN, row["north_m"], row["east_m"]))
    bow, starboard = basis.T @ matrix[:, 0], basis.T @ matrix[:, 1]  # NED components
    assert bow[2] == pytest.approx(math.sin(math.radians(5.0)), abs=1e-6)
    assert math.degrees(math.atan2(bow[1], bow[0])) == pytest.approx(30.0, abs=1e-4)
    assert starboard[2] == pytest.approx(math.cos(math.radians(5.0)) * math.sin(math.radians(10.0)), abs=1e-6)


@pytest.mark.parametrize("course, axis", [(0.0, 0), (90.0, 1), (180.0, 0)])
def test_velocity_points_along_the_course_over_ground(course, axis):
    """The ECEF velocity must be the speed over ground along the course: north for 000, east for 090, south
    for 180, with no vertical part; a swapped or unrotated vector sends the dead-reckoned ship astray."""
    row = make_row(course_over_ground_deg=course, speed_over_ground_kn=12.0, heading_deg=course + 5.0)
    pdu = dis.decode(dis.entity_state(row, ORIGIN, 0.0))
    basis = geo.ned_basis(*geo.position(ORIGIN, row["north_m"], row["east_m"]))
    ned = basis.T @ np.array(pdu.velocity)
    sign = -1.0 if course == 180.0 else 1.0
    assert ned[axis] == pytest.approx(sign * 12.0 * KNOT, rel=1e-6)
    assert abs(ned[1 - axis]) < 1e-5 and abs(ned[2]) < 1e-5
    if course == 0.0:
        assert ned[0] > 0.0


@pytest.mark.parametrize("t", [0.0, 10.0, 3725.5, 7199.999])
def test_relative_timestamp(t):
    """The timestamp counts 3600/2^31 s past the hour in its upper 31 bits with the low bit 0 (relative
    time); otherwise receivers order and extrapolate PDUs wrongly."""
    stamp = dis.decode(dis.entity_state(make_row(), ORIGIN, t)).timestamp
    assert stamp & 1 == 0
    assert (stamp >> 1) * 3600.0 / 2**31 == pytest.approx(t % 3600.0, abs=2e-6)


def test_missing_speed_gives_no_velocity_and_missing_position_is_refused():
    """A row without speed over ground must still give a PDU (velocity 0); a row without a finite position
    cannot be placed and must be refused naming the column."""
    pdu = dis.decode(dis.entity_state(make_row(speed_over_ground_kn=float("nan")), ORIGIN, 0.0))
    assert pdu.velocity == (0.0, 0.0, 0.0)
    with pytest.raises(ParameterError, match="north_m"):
        dis.entity_state(make_row(north_m=float("inf")), ORIGIN, 0.0)


@pytest.mark.parametrize("kwargs, name", [
    (dict(marking="TWELVE CHARS"), "marking"), (dict(marking="ÖWNSHIP"), "marking"),
    (dict(entity_id=(1, 2, 70000)), "entity_id"), (dict(exercise_id=0), "exercise_id"),
])
def test_bad_identity_is_refused_in_one_line(kwargs, name):
    """Values DIS cannot carry must be refused naming the argument, not truncated silently."""
    with pytest.raises(ParameterError, match=name) as caught:
        dis.entity_state(make_row(), ORIGIN, 0.0, **kwargs)
    assert "\n" not in str(caught.value)


def edited(offset: int, value: bytes) -> bytes:
    """Own ship's PDU with ``value`` written at byte ``offset`` (offsets of the IEEE 1278.1 field table)."""
    data = bytearray(dis.entity_state(make_row(), ORIGIN, 0.0))
    data[offset:offset + len(value)] = value
    return bytes(data)


@pytest.mark.parametrize("data", [
    b"", b"\x07\x01\x01\x01", b"\x07\x01\x14\x05" + bytes(40),
    dis.entity_state(make_row(), ORIGIN, 0.0)[:-1], dis.entity_state(make_row(), ORIGIN, 0.0) + b"\0",
    edited(2, b"\x02"),  # a Fire PDU's type
    edited(3, b"\x02"),  # the warfare family
    edited(8, (100).to_bytes(2, "big")),  # a length field that is not the size
    edited(19, b"\x01"),  # one variable parameter announced, none there
])
def test_decode_refuses_what_is_not_an_entity_state_pdu(data):
    """Truncated or padded data, another PDU type or family, a wrong length field or announced variable
    parameters must raise ParameterError in one line, not return a half-read or misread PDU."""
    with pytest.raises(ParameterError, match="DIS data") as caught:
        dis.decode(data)
    assert "\n" not in str(caught.value)
