"""NMEA 0183 sentences of a record row (marinesim.net.nmea) read by pynmea2, and their live UDP streams."""

import math
import socket
from datetime import datetime, timezone

import numpy as np
import pynmea2
import pytest

from marinesim.errors import ParameterError
from marinesim.net import dis, geo, nmea
from marinesim.net.streams import Streams
from marinesim.net.udp import UdpSender, udp_address

ORIGIN = geo.Origin(60.1, 24.9)
UTC = datetime(2025, 3, 14, 9, 26, 53, 580000, tzinfo=timezone.utc)
WGS84_A, WGS84_F = 6378137.0, 1.0 / 298.257223563


def make_row(**changes: float) -> dict[str, float]:
    """A ship 5 km from the origin turning to starboard, rolled to starboard, bow down, heaved up."""
    row = dict(north_m=3000.0, east_m=4000.0, heading_deg=47.5, course_over_ground_deg=51.25,
               speed_over_ground_kn=11.8, rate_of_turn_deg_min=36.0, rudder_deg=15.0, roll_deg=4.5,
               pitch_deg=1.75, heave_m=0.62, time_s=0.0)
    row.update(changes)
    return row


def parse_all(lines: list[str]) -> list[pynmea2.NMEASentence]:
    for line in lines:
        assert line.endswith("\r\n") and len(line) <= 82
    return [pynmea2.parse(line.strip(), check=True) for line in lines]


def chord(p: tuple[float, float], q: tuple[float, float]) -> float:
    """ECEF straight-line distance (m) of two WGS84 points (deg), written out here."""
    def xyz(lat: float, lon: float) -> np.ndarray:
        e2 = WGS84_F * (2.0 - WGS84_F)
        la, lo = math.radians(lat), math.radians(lon)
        n = WGS84_A / math.sqrt(1.0 - e2 * math.sin(la) ** 2)
        return np.array([n * math.cos(la) * math.cos(lo), n * math.cos(la) * math.sin(lo), n * (1 - e2) * math.sin(la)])
    return float(np.linalg.norm(xyz(*p) - xyz(*q)))


def test_checksum_by_hand():
    """'AB' XORs to 0x03, 'A' is 0x41, 'z' 0x7A, and a sentence carries its body's XOR (computed here);
    a wrong checksum makes receivers drop every sentence."""
    assert nmea.checksum("AB") == "03"
    expected = 0
    for c in "GPHDT,123.4,T":
        expected ^= ord(c)
    assert nmea.sentence("GPHDT,123.4,T") == f"$GPHDT,123.4,T*{expected:02X}\r\n"
    assert nmea.checksum("A") == "41" and nmea.checksum("z") == "7A"


def test_sentences_parse_in_order_with_their_talkers():
    """Every sentence must parse with its checksum checked, in the order GGA RMC VTG HDT ROT RSA PASHR, with
    the gyro's HE talker on HDT/ROT and the autopilot's AG on RSA; a receiver filters on these."""
    parsed = parse_all(nmea.sentences(make_row(), ORIGIN, UTC))
    assert [type(s).__name__ for s in parsed] == ["GGA", "RMC", "VTG", "HDT", "ROT", "RSA", "ASHRATT"]
    assert [getattr(s, "talker", "P") for s in parsed] == ["GP", "GP", "GP", "HE", "HE", "AG", "P"]
    assert parse_all(nmea.sentences(make_row(), ORIGIN, UTC, talker="GN"))[0].talker == "GN"


def test_values_and_signs_agree_with_the_row():
    """Heading, course, speed (kn and km/h), rate of turn (a turn to starboard positive), rudder (to
    starboard positive), time and date must be the row's; PASHR roll must stay positive for starboard down,
    its pitch be negative for the row's bow DOWN (PASHR: bow up positive) and heave positive up."""
    row = make_row()
    gga, rmc, vtg, hdt, rot, rsa, pashr = parse_all(nmea.sentences(row, ORIGIN, UTC))
    assert float(hdt.heading) == pytest.approx(47.5) and float(pashr.true_heading) == pytest.approx(47.5)
    assert rmc.true_course == pytest.approx(51.25) and vtg.true_track == pytest.approx(51.25)
    assert rmc.spd_over_grnd == pytest.approx(11.8) and float(vtg.spd_over_grnd_kts) == pytest.approx(11.8)
    assert vtg.spd_over_grnd_kmph == pytest.approx(11.8 * 1.852, abs=0.005)
    assert float(rot.rate_of_turn) == pytest.approx(36.0) and rot.status == "A"
    assert float(rsa.rsa_starboard) == pytest.approx(15.0) and rsa.rsa_starboard_status == "A"
    assert pashr.roll == pytest.approx(4.5) and pashr.pitch == pytest.approx(-1.75)
    assert pashr.heave == pytest.approx(0.62)
    assert pashr.roll > 0 and pashr.pitch < 0  # starboard down, bow down in the PASHR convention
    assert gga.timestamp == UTC.time().replace(tzinfo=timezone.utc, microsecond=580000)
    assert rmc.datetime == UTC and pashr.timestamp.microsecond == 580000
    assert gga.gps_qual == 1 and int(gga.num_sats) == 8 and float(gga.horizontal_dil) == 1.0
    assert gga.altitude == 0.0 and gga.altitude_units == "M" and float(gga.geo_sep) == 0.0


def test_turn_and_rudder_to_port_are_negative():
    """NMEA ROT and RSA are negative to port; the record's negative (port) values must stay negative."""
    _, _, _, _, rot, rsa, _ = parse_all(nmea.sentences(make_row(rate_of_turn_deg_min=-20.0, rudder_deg=-35.0),
                                                       ORIGIN, UTC))
    assert float(rot.rate_of_turn) == pytest.approx(-20.0) and float(rsa.rsa_starboard) == pytest.approx(-35.0)


@pytest.mark.parametrize("origin", [ORIGIN, geo.Origin(-41.3, -174.8), geo.Origin(0.5, 179.99)])
def test_gga_fix_is_the_rows_place(origin):
    """pynmea2's latitude/longitude of GGA and RMC must be the row's position (to the 1e-5 minute the
    sentence carries), with hemisphere letters right south and west."""
    row = make_row(north_m=-3000.0, east_m=4000.0)
    gga, rmc = parse_all(nmea.sentences(row, origin, UTC))[:2]
    lat, lon = geo.position(origin, row["north_m"], row["east_m"])
    for fix in (gga, rmc):
        assert fix.latitude == pytest.approx(lat, abs=2e-7) and fix.longitude == pytest.approx(lon, abs=2e-7)
    assert gga.lat_dir == ("N" if lat >= 0 else "S") and gga.lon_dir == ("E" if lon >= 0 else "W")


@pytest.mark.parametrize("origin", [ORIGIN, geo.Origin(-45.0, 12.0)])
def test_distance_between_two_fixes_is_the_rows_distance(origin):
    """Two GGA fixes of a ship 5 km from the origin must be as far apart as the rows' north/east (0.1 %),
    for a short leg and a long one; a stretched longitude scale would fail this."""
    first = make_row(north_m=3000.0, east_m=4000.0)
    for second in (make_row(north_m=3200.0, east_m=4250.0), make_row(north_m=-4000.0, east_m=-3000.0),
                   make_row(north_m=3000.0, east_m=3500.0)):
        fixes = [parse_all(nmea.sentences(r, origin, UTC))[0] for r in (first, second)]
        measured = chord(*[(f.latitude, f.longitude) for f in fixes])
        expected = math.hypot(second["north_m"] - first["north_m"], second["east_m"] - first["east_m"])
        assert measured == pytest.approx(expected, rel=1e-3)


def test_non_finite_values_leave_fields_empty():
    """NaN or infinite values must give empty fields in sentences that still parse (no 'nan' text), the
    fix marked invalid when the position is unknown; a missing rudder leaves RSA out."""
    row = make_row(north_m=float("nan"), heave_m=float("inf"), roll_deg=float("-inf"),
                   rate_of_turn_deg_min=float("nan"), speed_over_ground_kn=float("nan"))
    del row["rudder_deg"]
    lines = nmea.sentences(row, ORIGIN, UTC)
    assert not any("nan" in line.lower() or "inf" in line.lower() for line in lines)
    gga, rmc, vtg, hdt, rot, pashr = parse_all(lines)
    assert (gga.lat, gga.lon, gga.gps_qual) == ("", "", 0) and rmc.status == "V"
    assert rot.rate_of_turn == "" and rot.status == "V" and vtg.spd_over_grnd_kmph is None
    assert pashr.heave is None and pashr.roll is None and pashr.pitch == pytest.approx(-1.75)
    assert float(hdt.heading) == pytest.approx(47.5)


def test_heading_just_below_360_and_time_just_before_midnight_round_over():
    """359.999 deg must read 0.00 (not 360.00) and 23:59:59.999 the next day's 00:00:00.00 with its date."""
    late = datetime(2024, 12, 31, 23, 59, 59, 999000, tzinfo=timezone.utc)
    gga, rmc, _, hdt, *_ = parse_all(nmea.sentences(make_row(heading_deg=359.999), ORIGIN, late))
    assert float(hdt.heading) == 0.0
    assert rmc.datetime == datetime(2025, 1, 1, tzinfo=timezone.utc)


@pytest.mark.parametrize("url", ["localhost:5000", "udp://host:0", "udp://host:70000", "udp://:5000",
                                 "tcp://host:5000", "udp://host", "udp://host:abc", "", "udp://host:5000/path"])
def test_bad_urls_are_refused_in_one_line(url):
    """Anything but udp://HOST:PORT with a port in 1..65535 must raise ParameterError quoting the value."""
    with pytest.raises(ParameterError) as caught:
        udp_address(url, "nmea_url")
    message = str(caught.value)
    assert "\n" not in message and repr(url) in message and "udp://HOST:PORT" in message
    assert message.startswith("nmea_url")


def test_good_urls():
    """Host names, IPv4 and bracketed IPv6 hosts with their ports must come back as (host, port)."""
    assert udp_address("udp://127.0.0.1:10110") == ("127.0.0.1", 10110)
    assert udp_address("udp://bridge.local:3000") == ("bridge.local", 3000)
    assert udp_address("udp://[::1]:65535") == ("::1", 65535)


def receiver() -> socket.socket:
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.bind(("127.0.0.1", 0))
    sock.settimeout(5.0)
    return sock


def test_streams_send_nmea_and_dis_over_loopback_at_their_rate():
    """Streams at 2 Hz fed a 10 Hz simulation for 1 s must send at t = 0, 0.5 and 1.0 (float sums of 0.1
    included): 7 NMEA datagrams and one DIS PDU each, which pynmea2 and dis.decode read back as the row."""
    with receiver() as nmea_in, receiver() as dis_in:
        nmea_port, dis_port = nmea_in.getsockname()[1], dis_in.getsockname()[1]
        with Streams(f"udp://127.0.0.1:{nmea_port}", f"udp://127.0.0.1:{dis_port}", ORIGIN, UTC, 2.0) as streams:
            t, times = 0.0, []
            for _ in range(11):
                if streams.due(t):
                    streams.send(t, make_row(time_s=t, north_m=3000.0 + 10.0 * t))
                    times.append(t)
                t += 0.1
            assert times == pytest.approx([0.0, 0.5, 1.0]) and not streams.due(t - 0.1 + 1e-6)
            assert (streams.sent_nmea, streams.sent_dis, streams.errors) == (21, 3, 0)
        lines = [nmea_in.recv(2048).decode("ascii") for _ in range(21)]
        pdus = [dis.decode(dis_in.recv(2048)) for _ in range(3)]
    parsed = parse_all(lines)
    assert [type(s).__name__ for s in parsed[:7]] == ["GGA", "RMC", "VTG", "HDT", "ROT", "RSA", "ASHRATT"]
    last = parsed[14]
    assert last.latitude == pytest.approx(geo.position(ORIGIN, 3010.0, 4000.0)[0], abs=2e-7)
    assert last.timestamp.second == 54 and last.timestamp.microsecond == 580000  # UTC + 1 s
    np.testing.assert_allclose(pdus[2].location,
                               geo.ecef(*geo.position(ORIGIN, 3010.0, 4000.0)), atol=1e-6)


def test_a_missing_listener_or_a_refused_send_does_not_stop_the_simulation():
    """Sending to a port nobody listens on must not raise; a send the network refuses is counted."""
    with receiver() as gone:
        port = gone.getsockname()[1]
    with Streams(f"udp://127.0.0.1:{port}", None, ORIGIN, UTC) as streams:
        for step in range(3):
            streams.send(float(step), make_row())
        assert streams.sent_nmea + streams.errors == 21

    class Refusing:
        def sendto(self, data: bytes, address: object) -> int:
            raise ConnectionRefusedError(111, "Connection refused")

        def close(self) -> None:
            pass

    with UdpSender(f"udp://127.0.0.1:{port}") as sender:
        sender._socket.close()
        sender._socket = Refusing()
        assert sender.send(b"$X*00\r\n") is False and (sender.sent, sender.errors) == (0, 1)


def test_streams_refuse_a_bad_rate_or_url():
    """A rate that is not positive and a malformed URL must be refused naming the option."""
    with pytest.raises(ParameterError, match="rate_hz"):
        Streams(None, None, ORIGIN, UTC, rate_hz=0.0)
    with pytest.raises(ParameterError, match="--dis"):
        Streams(None, "udp://127.0.0.1", ORIGIN, UTC)
