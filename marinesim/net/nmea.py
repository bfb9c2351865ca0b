"""NMEA 0183 sentences from one row of the simulator's record (docs/REFERENCES.md section 9).

Sentences, in the order :func:`sentences` gives them, and their talkers:

- ``$--GGA``, ``$--RMC``, ``$--VTG`` (GNSS position, fix, course and speed over ground): the ``talker``
  argument, ``GP`` by default.
- ``$HEHDT`` (true heading) and ``$HEROT`` (rate of turn): ``HE``, the north-seeking gyro talker that
  gyrocompasses send.
- ``$AGRSA`` (rudder sensor angle): ``AG``, the general autopilot talker, as steering systems that read the
  rudder feedback unit send it (integrated bridge systems use ``II``).
- ``$PASHR`` (proprietary attitude: time, true heading, roll, pitch, heave, accuracies, aiding and IMU
  status), the RT300 layout that NovAtel SPAN (OEM7 "PASHR" log), Trimble and Hemisphere receivers send.

Sign conventions of the sentences, converted from the record's (the rules of docs/CONVENTIONS.md: roll
positive starboard down, pitch positive bow DOWN, heave positive up, rate of turn and rudder positive to
starboard):

- ROT: deg/min, negative when the bow turns to port (NMEA 0183) -> the record's rate of turn as it is.
- RSA: deg, negative for rudder to port (NMEA 0183) -> the record's rudder angle as it is.
- PASHR roll positive starboard (right side) down, pitch positive bow UP, heave positive up: the SPAN
  attitude convention (roll right-handed about the forward axis, pitch right-handed about the starboard
  axis) that NovAtel's PASHR log carries with explicit signs, and nmea-kit's PASHR ("roll negative = port,
  pitch negative = bow down") -> roll as it is, pitch negated, heave as it is.

A value that is missing or not finite leaves its field empty; the sentence stays well formed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from datetime import datetime, timedelta, timezone

from marinesim.errors import ParameterError
from marinesim.net.geo import Origin, position

GYRO_TALKER = "HE"
"""Talker of HDT and ROT: heading, north-seeking gyro."""
RUDDER_TALKER = "AG"
"""Talker of RSA: autopilot, general."""

GGA_SATELLITES = 8
GGA_HDOP = 1.0
PASHR_ROLL_ACCURACY_DEG = 0.01
"""1-sigma accuracies the PASHR sentence claims (deg): those of a survey-grade motion sensor."""
PASHR_PITCH_ACCURACY_DEG = 0.01
PASHR_HEADING_ACCURACY_DEG = 0.02
PASHR_AIDING_STATUS = 1
"""GNSS quality of the PASHR sentence: 1, a GNSS fix without RTK."""
PASHR_IMU_STATUS = 1
"""IMU status of the PASHR sentence: 1, INS aligned (NovAtel's meaning)."""

KNOT_KMH = 1.852
"""Kilometres per hour in one knot."""


def checksum(body: str) -> str:
    """NMEA checksum of the characters between '$' and '*': their XOR, as two upper-case hex digits."""
    value = 0
    for char in body:
        value ^= ord(char)
    return f"{value:02X}"


def sentence(body: str) -> str:
    """The sentence '$' + body + '*' + checksum + CR LF; ``body`` is printable ASCII without '$', '*', '!'."""
    if any(not " " <= c <= "~" or c in "$*!" for c in body):
        raise ValueError(f"an NMEA sentence body must be printable ASCII without '$', '*' or '!', got {body!r}")
    return f"${body}*{checksum(body)}\r\n"


def sentences(row: Mapping[str, float], origin: Origin, utc: datetime, talker: str = "GP") -> list[str]:
    """GGA, RMC, VTG, HDT, ROT, RSA (when the row has ``rudder_deg``) and PASHR sentences of one record row.

    ``row`` holds the record's columns north_m, east_m (m from ``origin``), heading_deg,
    course_over_ground_deg (compass deg), speed_over_ground_kn, rate_of_turn_deg_min, rudder_deg (positive
    to starboard), roll_deg, pitch_deg (docs/CONVENTIONS.md signs) and heave_m (up); ``utc`` is the time
    of the row (a naive datetime is taken as UTC). Each string ends in CR LF.
    """
    if not (len(talker) == 2 and talker.isascii() and talker.isalpha() and talker.isupper()):
        raise ParameterError(f"talker must be two upper-case letters (an NMEA talker ID such as GP), "
                             f"got {talker!r}")
    utc = utc.replace(tzinfo=timezone.utc) if utc.tzinfo is None else utc.astimezone(timezone.utc)

    def value(key: str) -> float:
        try:
            number = float(row.get(key, math.nan))
        except (TypeError, ValueError):
            return math.nan
        return number if math.isfinite(number) else math.nan

    lat, lon = position(origin, value("north_m"), value("east_m"))
    fix = math.isfinite(lat) and math.isfinite(lon)
    sog, cog = value("speed_over_ground_kn"), value("course_over_ground_deg")
    hhmmss = _time(utc, 2)
    date = (utc + timedelta(microseconds=5000)).strftime("%d%m%y")
    lat_field, lon_field = _latitude(lat), _longitude(lon)
    heading = _bearing(value("heading_deg"), 2)

    out = [
        f"{talker}GGA,{hhmmss},{lat_field},{lon_field},{1 if fix else 0},{GGA_SATELLITES:02d},{GGA_HDOP:.1f},"
        f"0.0,M,0.0,M,,",
        f"{talker}RMC,{hhmmss},{'A' if fix else 'V'},{lat_field},{lon_field},{_fixed(sog, 2)},"
        f"{_bearing(cog, 2)},{date},,,{'A' if fix else 'N'}",
        f"{talker}VTG,{_bearing(cog, 2)},T,,M,{_fixed(sog, 2)},N,{_fixed(sog * KNOT_KMH, 2)},K,"
        f"{'A' if math.isfinite(sog) else 'N'}",
        f"{GYRO_TALKER}HDT,{heading},T",
        f"{GYRO_TALKER}ROT,{_fixed(value('rate_of_turn_deg_min'), 1)},"
        f"{'A' if math.isfinite(value('rate_of_turn_deg_min')) else 'V'}",
    ]
    if "rudder_deg" in row:
        rudder = value("rudder_deg")
        out.append(f"{RUDDER_TALKER}RSA,{_fixed(rudder, 1)},{'A' if math.isfinite(rudder) else 'V'},,V")
    out.append(
        f"PASHR,{_time(utc, 3)},{heading},T,{_fixed(value('roll_deg'), 2, signed=True)},"
        f"{_fixed(-value('pitch_deg'), 2, signed=True)},{_fixed(value('heave_m'), 2, signed=True)},"
        f"{PASHR_ROLL_ACCURACY_DEG:.3f},{PASHR_PITCH_ACCURACY_DEG:.3f},{PASHR_HEADING_ACCURACY_DEG:.3f},"
        f"{PASHR_AIDING_STATUS if fix else 0},{PASHR_IMU_STATUS}")
    return [sentence(body) for body in out]


def _fixed(x: float, decimals: int, signed: bool = False) -> str:
    """``x`` with ``decimals`` decimals ('+' shown when ``signed``), or '' when not finite."""
    if not math.isfinite(x):
        return ""
    rounded = round(x, decimals) + 0.0
    return f"{rounded:+.{decimals}f}" if signed else f"{rounded:.{decimals}f}"


def _bearing(deg: float, decimals: int) -> str:
    """A compass bearing wrapped to [0, 360) after rounding, or '' when not finite."""
    if not math.isfinite(deg):
        return ""
    rounded = round(deg % 360.0, decimals)
    return f"{(rounded if rounded < 360.0 else 0.0) + 0.0:.{decimals}f}"


def _time(utc: datetime, decimals: int) -> str:
    """hhmmss.ss (``decimals`` 2) or hhmmss.sss (3) of a UTC time, rounded."""
    step = 10 ** (6 - decimals)
    t = utc + timedelta(microseconds=step // 2)
    return f"{t:%H%M%S}.{t.microsecond // step:0{decimals}d}"


def _angle(deg: float, degree_digits: int, positive: str, negative: str) -> str:
    """``deg`` as d..dmm.mmmmm (``degree_digits`` degree digits) and its hemisphere letter; ',' if not finite."""
    if not math.isfinite(deg):
        return ","
    total = round(abs(deg) * 60.0 * 100000)
    degrees, rest = divmod(total, 60 * 100000)
    minutes, fraction = divmod(rest, 100000)
    return f"{degrees:0{degree_digits}d}{minutes:02d}.{fraction:05d},{positive if deg >= 0.0 else negative}"


def _latitude(lat: float) -> str:
    return _angle(lat, 2, "N", "S")


def _longitude(lon: float) -> str:
    return _angle(lon, 3, "E", "W")
