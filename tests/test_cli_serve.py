"""``marinesim serve`` as a user runs it (a process of its own on the loopback) with a station joining from the command
line and an NMEA 0183 stream read by a real parser (pynmea2, checksums checked) against the run's motion table."""

from __future__ import annotations

import math
import os
import re
import socket
import subprocess
import sys
from datetime import datetime, timezone
from pathlib import Path

import numpy as np
import pandas as pd
import pynmea2
import pytest

from conftest import VESSEL_SCENARIO, write
from marinesim.cli import main
from marinesim.resources import resource_dir

TRANSIT = resource_dir("configs") / "training" / "heavy_weather_transit.toml"
START = datetime(2026, 10, 28, 17, 5, tzinfo=timezone.utc)
"""The scenario's ``time_utc``: the NMEA clock's zero."""
HANG_S = 600.0
"""s: a serve that has not ended by then hangs (it runs 20 simulated seconds at 4 times real time)."""
A, F = 6378137.0, 1.0 / 298.257223563
"""WGS84: the semi-major axis (m) and the flattening."""


def _metres_per_degree(lat_deg: float) -> tuple[float, float]:
    """(north, east) metres per degree of latitude and longitude at ``lat_deg``, from the WGS84 radii of curvature."""
    e2 = F * (2.0 - F)
    s2 = math.sin(math.radians(lat_deg)) ** 2
    meridian = A * (1.0 - e2) / (1.0 - e2 * s2) ** 1.5
    normal = A / math.sqrt(1.0 - e2 * s2)
    return math.radians(meridian), math.radians(normal * math.cos(math.radians(lat_deg)))


def _serve(tmp_path: Path, *options: str) -> tuple[subprocess.Popen, dict[str, str]]:
    """``marinesim serve`` on a free loopback port for 20 s at 4 x real time; the process and the addresses it
    printed (read as it prints them): the instructor's page and a station's URL."""
    process = subprocess.Popen(
        [sys.executable, "-m", "marinesim", "serve", str(TRANSIT), "--bind", "127.0.0.1:0", "--duration", "20",
         "--time-scale", "4", "--log", str(tmp_path / "served.jsonl"), "--quiet", *options],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=tmp_path,
        env=os.environ | {"PYTHONUNBUFFERED": "1"})
    printed, found = [], {}
    for line in process.stdout:
        printed.append(line)
        if page := re.search(r"instructor page: (http://\S+)", line):
            found["page"] = page.group(1)
        if station := re.search(r"--connect '(ws://[^']+)'", line):
            found["station"] = station.group(1)
            return process, found
    process.wait(HANG_S)
    raise AssertionError("serve printed no station URL:\n" + "".join(printed))


def _until_printed(process: subprocess.Popen, text: str, printed: list[str]) -> None:
    """Read ``process``'s lines into ``printed`` until one holds ``text`` (it ends the test if the process ends)."""
    for line in process.stdout:
        printed.append(line)
        if text in line:
            return
    raise AssertionError(f"never printed {text!r}:\n" + "".join(printed))


def test_a_station_joins_from_the_command_line_and_follows_to_the_end(tmp_path, capsys):
    """The command line a station's operator types (the URL serve printed) joins an exercise served frozen, follows
    it from the instructor's resume to its end, and says so; a wrong token or address is one line and status 2, not
    a traceback or a hang. Served frozen, the exercise waits for the station however long it takes to start."""
    from marinesim.net.station import Link

    process, urls = _serve(tmp_path, "--frozen")
    url, printed = urls["station"], []
    try:
        assert main(["run", str(TRANSIT), "--duration", "20", "--connect", url.replace("token=", "token=x"),
                     "--headless", "--station", "crane"]) == 2
        assert "refused the station (403: wrong token)" in capsys.readouterr().err
        assert main(["run", "--connect", "http://127.0.0.1:1/ws", "--headless"]) == 2
        assert "--connect http://127.0.0.1:1/ws: expected ws://HOST:PORT/ws?token=TOKEN" in capsys.readouterr().err
        station = subprocess.Popen([sys.executable, "-m", "marinesim", "run", str(TRANSIT), "--duration", "20",
                                    "--connect", url, "--headless", "--station", "crane"], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True, cwd=tmp_path)
        _until_printed(process, "station crane joins", printed)
        page = urls["page"]
        instructor = Link(url.split("?")[0] + "?" + page.split("?")[1], {"type": "hello", "role": "instructor"})
        instructor.send({"type": "control", "control": "resume"})
        out = station.communicate(timeout=HANG_S)[0]
        instructor.close()
    finally:
        rest = "".join(printed) + process.communicate(timeout=HANG_S)[0]
    assert station.returncode == 0, out
    assert "station crane: followed the exercise to t 20.0 s" in out
    assert process.returncode == 0, rest
    assert "the exercise ended" in rest
    assert main(["report", str(tmp_path / "served.jsonl"), "--out", str(tmp_path / "report.html")]) == 0


def test_bad_serve_and_stream_options_are_one_line_each(tmp_path, capsys):
    """A time scale the page does not offer, a session log over the scenario (refused before the exercise runs, not
    after it), an address that is not HOST:PORT, a stream to something that is not a
    UDP address, a stream from a scenario that does not say where it is, a station asked to stream: each is one
    line naming the option, status 2, before anything is built or listens."""
    nowhere = write(tmp_path, VESSEL_SCENARIO)  # no [environment] position
    cases = [(["serve", str(TRANSIT), "--time-scale", "3"], "--time-scale 3: expected one of 0.25, 0.5, 1, 2, 4, 8"),
             (["serve", str(nowhere), "--log", str(nowhere)], "one of this command's inputs"),
             (["serve", str(TRANSIT), "--bind", "localhost"], "--bind localhost: expected HOST:PORT"),
             (["serve", str(TRANSIT), "--nmea", "tcp://127.0.0.1:10110"], "--nmea must be udp://HOST:PORT"),
             (["run", str(nowhere), "--headless", "--nmea", "udp://127.0.0.1:10110"],
              "--nmea and --dis need where the exercise is: [environment] latitude_deg and longitude_deg"),
             (["run", str(TRANSIT), "--connect", "ws://127.0.0.1:1/ws?token=t", "--dis", "udp://127.0.0.1:3000"],
              "--nmea and --dis stream from marinesim serve")]
    for argv, message in cases:
        assert main(argv) == 2, argv
        err = capsys.readouterr().err.strip()
        assert message in err and len(err.splitlines()) == 1, err


def test_the_nmea_stream_agrees_with_the_motion_table(tmp_path):
    """Every sentence the server streams passes pynmea2's checksum; heading, roll and pitch agree with the run's
    motion table (the replay of its log, exported) at the sentence's time, and the distance between the first and
    last fixes is the speed over ground times the time between them. An ECDIS or a helideck monitoring system fed
    wrong signs, a wrong clock or a wrong place would show the instructor another ship than the trainee's."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as listener:
        listener.bind(("127.0.0.1", 0))
        listener.settimeout(HANG_S)
        process, _ = _serve(tmp_path, "--nmea", f"udp://127.0.0.1:{listener.getsockname()[1]}")
        rest = process.communicate(timeout=HANG_S)[0]
        assert process.returncode == 0, rest
        listener.settimeout(0.5)  # the datagrams are in the socket's buffer: the server has ended
        lines = []
        try:
            while True:
                lines.append(listener.recv(4096).decode("ascii"))
        except TimeoutError:
            pass
    sentences = [pynmea2.parse(line.strip(), check=True) for line in lines]
    assert len(sentences) == 7 * 21  # a burst of 7 each simulated second, 0 to 20 s, however the ticks fell
    assert main(["replay", str(tmp_path / "served.jsonl"), "--export", str(tmp_path / "replay.csv")]) == 0
    table = pd.read_csv(tmp_path / "replay.csv")
    bursts = [sentences[i:i + 7] for i in range(0, len(sentences) - 6, 7)]
    fixes = []
    for gga, _rmc, _vtg, hdt, _rot, _rsa, pashr in bursts:
        assert [type(s).__name__ for s in (gga, hdt, pashr)] == ["GGA", "HDT", "ASHRATT"]
        stamp = datetime.combine(START.date(), pashr.timestamp.replace(tzinfo=None), tzinfo=timezone.utc)
        t = (stamp - START).total_seconds()
        assert t == pytest.approx(round(t), abs=1e-3)  # on the second: the state of that time, not a tick's

        def at(column: str) -> float:
            return float(np.interp(t, table["time_s"], table[column]))

        assert float(hdt.heading) == pytest.approx(at("heading_deg"), abs=0.06)
        assert float(pashr.roll) == pytest.approx(at("roll_deg"), abs=0.01)  # starboard down, as the table
        assert float(pashr.pitch) == pytest.approx(-at("pitch_deg"), abs=0.01)  # bow up, the table's bow down
        assert float(pashr.heave) == pytest.approx(at("heave_m"), abs=0.01)
        fixes.append((t, gga.latitude, gga.longitude))
    (t0, lat0, lon0), (t1, lat1, lon1) = fixes[0], fixes[-1]
    north, east = _metres_per_degree((lat0 + lat1) / 2.0)
    distance = math.hypot((lat1 - lat0) * north, (lon1 - lon0) * east)
    speed = table[(table["time_s"] >= t0) & (table["time_s"] <= t1)]["speed_over_ground_kn"].mean() * 1852 / 3600
    assert t1 - t0 >= 15.0 and distance == pytest.approx(speed * (t1 - t0), rel=2e-3)
