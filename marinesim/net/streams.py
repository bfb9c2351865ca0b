"""Live NMEA 0183 and DIS output of a paced simulation over UDP."""

from __future__ import annotations

import math
from collections.abc import Mapping
from datetime import datetime, timedelta, timezone
from types import TracebackType

from marinesim.errors import ParameterError, require_positive
from marinesim.net.dis import entity_state
from marinesim.net.geo import Origin
from marinesim.net.nmea import sentences
from marinesim.net.udp import UdpSender

_TIME_SLACK = 1e-9
"""Output times are reached this fraction of a period early, so that t = k / rate summed in floats counts."""


class Streams:
    """NMEA sentences (one datagram each) and DIS Entity State PDUs of own ship, at ``rate_hz`` (a context manager).

    ``nmea_url`` and ``dis_url`` are 'udp://HOST:PORT' or None (no such output). Output times are the
    multiples of 1 / ``rate_hz`` seconds of simulation time; the UTC of time ``t_s`` is ``start_utc`` +
    ``t_s`` (a naive ``start_utc`` is taken as UTC). ``sent_nmea`` and ``sent_dis`` count the datagrams
    sent, ``errors`` the failed sends and the rows a DIS PDU could not be made of.
    """

    def __init__(self, nmea_url: str | None, dis_url: str | None, origin: Origin, start_utc: datetime,
                 rate_hz: float = 1.0) -> None:
        self.rate_hz = require_positive("rate_hz", rate_hz)
        self.origin = origin
        self.start_utc = (start_utc.replace(tzinfo=timezone.utc) if start_utc.tzinfo is None
                          else start_utc.astimezone(timezone.utc))
        self._nmea = UdpSender(nmea_url, "--nmea") if nmea_url is not None else None
        try:
            self._dis = UdpSender(dis_url, "--dis") if dis_url is not None else None
        except BaseException:
            if self._nmea is not None:
                self._nmea.close()
            raise
        self.urls = {"NMEA 0183": nmea_url, "DIS": dis_url}
        self._next = 0
        self.sent_nmea = 0
        self.sent_dis = 0
        self.skipped_dis = 0

    def describe(self) -> str:
        """Where the outputs go, in words: 'NMEA 0183 to udp://127.0.0.1:10110, DIS to ...'."""
        return ", ".join(f"{kind} to {url}" for kind, url in self.urls.items() if url is not None)

    @property
    def errors(self) -> int:
        """Failed sends of both outputs plus rows without a DIS PDU."""
        return sum(s.errors for s in (self._nmea, self._dis) if s is not None) + self.skipped_dis

    def due(self, t_s: float) -> bool:
        """Whether simulation time ``t_s`` (s) has reached the next output time (False with no output)."""
        if self._nmea is None and self._dis is None:
            return False
        return t_s * self.rate_hz >= self._next - _TIME_SLACK

    def pending(self, t_s: float) -> list[float]:
        """The output times (s, multiples of 1 / ``rate_hz``) reached by ``t_s`` and not sent yet, in order: a
        simulation that moved on by more than a period sends each of them."""
        if self._nmea is None and self._dis is None:
            return []
        last = math.floor(t_s * self.rate_hz + _TIME_SLACK)
        return [k / self.rate_hz for k in range(self._next, last + 1)]

    def send(self, t_s: float, row: Mapping[str, float]) -> None:
        """Send the record row of time ``t_s`` (s) and schedule the next output after ``t_s``."""
        self._next = math.floor(t_s * self.rate_hz + _TIME_SLACK) + 1
        if self._nmea is not None:
            utc = self.start_utc + timedelta(seconds=t_s)
            for line in sentences(row, self.origin, utc):
                self.sent_nmea += self._nmea.send(line.encode("ascii"))
        if self._dis is not None:
            try:
                pdu = entity_state(row, self.origin, t_s)
            except ParameterError:
                self.skipped_dis += 1
                return
            self.sent_dis += self._dis.send(pdu)

    def close(self) -> None:
        """Close both sockets."""
        for sender in (self._nmea, self._dis):
            if sender is not None:
                sender.close()

    def __enter__(self) -> Streams:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 traceback: TracebackType | None) -> None:
        self.close()
