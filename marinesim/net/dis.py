"""IEEE 1278.1 (DIS 7) Entity State PDUs of own ship, written and read with :mod:`struct`.

World coordinates are ECEF (metres, m/s; :mod:`marinesim.net.geo`); orientation the DIS Euler angles of
the body axes x forward, y starboard, z down. The record's pitch (bow DOWN positive, docs/CONVENTIONS.md)
is negated into DIS's bow-up pitch; its roll (starboard down positive) is DIS's roll as it is.

The PDU (IEEE 1278.1-2012 section 7.2.2, 144 bytes without variable parameters, network byte order):

====== ===== ======================================================================================
offset bytes field
====== ===== ======================================================================================
0      12    header: protocol version u8, exercise id u8, PDU type u8 (1), protocol family u8 (1),
             timestamp u32, length u16, PDU status u8, padding u8 (DIS 5 and 6: u16 padding)
12     6     entity id: site u16, application u16, entity u16
18     2     force id u8, number of variable parameters u8
20     8     entity type: kind u8, domain u8, country u16, category, subcategory, specific, extra u8
28     8     alternative entity type (the same record)
36     12    linear velocity x, y, z float32 (m/s, ECEF)
48     24    location x, y, z float64 (m, ECEF)
72     12    orientation psi, theta, phi float32 (rad)
84     4     appearance u32
88     40    dead reckoning: algorithm u8, 15 bytes of other parameters, linear acceleration 3 x float32
             (m/s^2), angular velocity 3 x float32 (rad/s)
128    12    marking: character set u8 (1 ASCII), 11 characters (NUL padded)
140    4     capabilities u32
====== ===== ======================================================================================
"""

from __future__ import annotations

import math
import struct
from collections.abc import Mapping
from dataclasses import dataclass
from typing import NamedTuple

from marinesim.constants import KNOT
from marinesim.errors import ParameterError
from marinesim.net.geo import Origin, ecef, ecef_orientation, ned_basis, position


PROTOCOL_VERSION = 7
ENTITY_STATE_TYPE = 1
ENTITY_INFORMATION_FAMILY = 1
PLATFORM_KIND = 1
SURFACE_DOMAIN = 2
COUNTRY_OTHER = 0
FORCE_FRIENDLY = 1
ASCII_MARKING = 1
DRM_FPW = 2
"""Dead reckoning DRM(F,P,W): constant velocity, fixed orientation, world coordinates (the velocity this PDU
carries), so that a receiver moves the ship along its course between PDUs."""

TIMESTAMP_UNITS_PER_HOUR = 2**31
"""A DIS timestamp counts 3600 s / 2^31 units past the hour in its upper 31 bits."""

_FORMAT = struct.Struct(">4BIH2B" "3H2B" "2BH4B" "2BH4B" "3f" "3d" "3f" "I" "B15s3f3f" "B11s" "I")
"""The Entity State PDU without variable parameters (the table in the module docstring)."""
ENTITY_STATE_SIZE = _FORMAT.size
"""Bytes of an Entity State PDU without variable parameters (144)."""


class Vector3(NamedTuple):
    """Three components of a DIS vector (ECEF for location and velocity)."""

    x: float
    y: float
    z: float


class Orientation(NamedTuple):
    """DIS Euler angles (rad): body -> ECEF is Rz(psi) Ry(theta) Rx(phi) (:func:`marinesim.net.geo.euler_matrix`)."""

    psi: float
    theta: float
    phi: float


class EntityType(NamedTuple):
    """A DIS entity type record (the SISO-REF-010 enumerations)."""

    kind: int
    domain: int
    country: int
    category: int
    subcategory: int
    specific: int
    extra: int


@dataclass(frozen=True)
class EntityState:
    """The fields of one Entity State PDU (without variable parameters) as :func:`decode` reads them.

    ``timestamp`` is the raw DIS timestamp (:func:`timestamp`); ``location`` (m) and ``velocity`` (m/s) are
    ECEF, ``acceleration`` (m/s^2) and ``angular_velocity`` (rad/s) the dead reckoning parameters'; ``marking``
    is the marking's characters up to the first NUL, read as Latin-1 (whose first half is ASCII).
    """

    protocol_version: int
    exercise_id: int
    timestamp: int
    pdu_status: int
    entity_id: tuple[int, int, int]
    force_id: int
    entity_type: EntityType
    alternative_entity_type: EntityType
    velocity: Vector3
    location: Vector3
    orientation: Orientation
    appearance: int
    dead_reckoning_algorithm: int
    acceleration: Vector3
    angular_velocity: Vector3
    marking_character_set: int
    marking: str
    capabilities: int


def timestamp(t_s: float) -> int:
    """DIS relative timestamp of simulation time ``t_s`` (s): units of 3600/2^31 s past the hour, low bit 0."""
    units = int((t_s % 3600.0) / 3600.0 * TIMESTAMP_UNITS_PER_HOUR)
    return min(units, TIMESTAMP_UNITS_PER_HOUR - 1) << 1


def entity_state(row: Mapping[str, float], origin: Origin, t_s: float, entity_id: tuple[int, int, int] = (1, 1, 1),
                 marking: str = "OWNSHIP", exercise_id: int = 1) -> bytes:
    """One Entity State PDU (144 bytes, network order) for own ship in record row ``row`` at time ``t_s`` (s).

    ``row`` needs north_m, east_m (m from ``origin``) and heading_deg; roll_deg, pitch_deg (record signs)
    and speed_over_ground_kn with course_over_ground_deg (compass) are taken as 0 (no velocity) where
    missing or not finite. ``entity_id`` is (site, application, entity), ``marking`` at most 11 ASCII
    characters. Entity type: a surface platform (kind 1, domain 2, country 0); force 1 (friendly); dead
    reckoning :data:`DRM_FPW`; appearance, capabilities, acceleration and angular velocity 0.
    """
    if not (len(entity_id) == 3 and all(isinstance(i, int) and 0 <= i <= 65535 for i in entity_id)):
        raise ParameterError(f"entity_id must be three integers in 0..65535 (site, application, entity), "
                             f"got {entity_id!r}")
    if not (isinstance(exercise_id, int) and 1 <= exercise_id <= 255):
        raise ParameterError(f"exercise_id must be an integer in 1..255, got {exercise_id!r}")
    if not (len(marking) <= 11 and all(" " <= c <= "~" for c in marking)):
        raise ParameterError(f"marking must be at most 11 printable ASCII characters, got {marking!r}")

    north, east, heading = (_required(row, key) for key in ("north_m", "east_m", "heading_deg"))
    lat, lon = position(origin, north, east)
    psi, theta, phi = ecef_orientation(lat, lon, math.radians(heading), -math.radians(_optional(row, "pitch_deg")),
                                       math.radians(_optional(row, "roll_deg")))
    sog, cog = _optional(row, "speed_over_ground_kn"), _optional(row, "course_over_ground_deg")
    velocity = ned_basis(lat, lon) @ [sog * KNOT * math.cos(math.radians(cog)),
                                      sog * KNOT * math.sin(math.radians(cog)), 0.0]
    location = ecef(lat, lon)
    surface_platform = (PLATFORM_KIND, SURFACE_DOMAIN, COUNTRY_OTHER, 0, 0, 0, 0)
    return _FORMAT.pack(
        PROTOCOL_VERSION, exercise_id, ENTITY_STATE_TYPE, ENTITY_INFORMATION_FAMILY, timestamp(t_s),
        ENTITY_STATE_SIZE, 0, 0,
        *entity_id, FORCE_FRIENDLY, 0,
        *surface_platform, *surface_platform,
        *(float(v) for v in velocity), *(float(v) for v in location), psi, theta, phi,
        0,
        DRM_FPW, bytes(15), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        ASCII_MARKING, marking.encode("ascii"),
        0)


def decode(data: bytes) -> EntityState:
    """The fields of the Entity State PDU in ``data`` (the bytes of one PDU of DIS version 5, 6 or 7).

    Refuses with :class:`ParameterError` anything but a 144-byte PDU of type 1, family 1 whose length field
    is 144 and that carries no variable parameters.
    """
    if len(data) != ENTITY_STATE_SIZE:
        raise ParameterError(f"DIS data ({len(data)} bytes): expected a {ENTITY_STATE_SIZE}-byte Entity State PDU "
                             f"without variable parameters")
    f = _FORMAT.unpack(data)
    if (f[2], f[3]) != (ENTITY_STATE_TYPE, ENTITY_INFORMATION_FAMILY):
        raise ParameterError(f"DIS data: PDU type {f[2]}, family {f[3]}; expected an Entity State PDU "
                             f"(type {ENTITY_STATE_TYPE}, family {ENTITY_INFORMATION_FAMILY})")
    if f[5] != ENTITY_STATE_SIZE or f[12] != 0:
        raise ParameterError(f"DIS data: an Entity State PDU with length field {f[5]} and {f[12]} variable "
                             f"parameters; expected {ENTITY_STATE_SIZE} and 0")
    characters = f[46].split(b"\0", 1)[0]
    return EntityState(
        protocol_version=f[0], exercise_id=f[1], timestamp=f[4], pdu_status=f[6], entity_id=(f[8], f[9], f[10]),
        force_id=f[11], entity_type=EntityType(*f[13:20]), alternative_entity_type=EntityType(*f[20:27]),
        velocity=Vector3(*f[27:30]), location=Vector3(*f[30:33]), orientation=Orientation(*f[33:36]),
        appearance=f[36], dead_reckoning_algorithm=f[37], acceleration=Vector3(*f[39:42]),
        angular_velocity=Vector3(*f[42:45]), marking_character_set=f[45],
        marking=characters.decode("latin-1"), capabilities=f[47])


def _number(row: Mapping[str, float], key: str) -> float:
    try:
        return float(row.get(key, math.nan))
    except (TypeError, ValueError):
        return math.nan


def _required(row: Mapping[str, float], key: str) -> float:
    value = _number(row, key)
    if not math.isfinite(value):
        raise ParameterError(f"{key} must be a finite number for a DIS Entity State PDU, got {row.get(key)!r}")
    return value


def _optional(row: Mapping[str, float], key: str) -> float:
    value = _number(row, key)
    return value if math.isfinite(value) else 0.0
