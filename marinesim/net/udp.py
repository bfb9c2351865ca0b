"""UDP output: 'udp://HOST:PORT' addresses and a sender that never stops a simulation."""

from __future__ import annotations

import socket
from types import TracebackType
from urllib.parse import urlsplit

from marinesim.errors import ParameterError


def udp_address(url: str, name: str = "address") -> tuple[str, int]:
    """(host, port) of 'udp://HOST:PORT' (an IPv6 host in brackets); ``name`` names the option in errors."""
    expected = f"{name} must be udp://HOST:PORT with a port in 1..65535, got {url!r}"
    if not isinstance(url, str) or any(c.isspace() for c in url):
        raise ParameterError(expected)
    parts = urlsplit(url)
    try:
        port = parts.port
    except ValueError:
        raise ParameterError(expected) from None
    if (parts.scheme.lower() != "udp" or not parts.hostname or port is None or not 1 <= port <= 65535
            or parts.path not in ("", "/") or parts.query or parts.fragment or parts.username is not None):
        raise ParameterError(expected)
    return parts.hostname, port


class UdpSender:
    """Sends datagrams to one address from an unconnected UDP socket (a context manager).

    A failed send (no route, a refusal reported by the network) is counted in ``errors``, not raised: a
    missing listener must not stop a simulation. ``sent`` counts datagrams handed to the network.
    """

    def __init__(self, url: str, name: str = "address") -> None:
        host, port = udp_address(url, name)
        try:
            family, _, _, _, address = socket.getaddrinfo(host, port, type=socket.SOCK_DGRAM)[0]
        except (socket.gaierror, UnicodeError) as error:
            raise ParameterError(f"{name}: cannot resolve host {host!r} of {url!r} ({error})") from None
        self.url = url
        self.address = address
        self.sent = 0
        self.errors = 0
        self.last_error: OSError | None = None
        self._socket = socket.socket(family, socket.SOCK_DGRAM)
        if family == socket.AF_INET:
            self._socket.setsockopt(socket.SOL_SOCKET, socket.SO_BROADCAST, 1)

    def send(self, data: bytes) -> bool:
        """Send one datagram; True if the network took it, False (counted in ``errors``) if not."""
        try:
            self._socket.sendto(data, self.address)
        except OSError as error:
            self.errors += 1
            self.last_error = error
            return False
        self.sent += 1
        return True

    def close(self) -> None:
        """Close the socket."""
        self._socket.close()

    def __enter__(self) -> UdpSender:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 traceback: TracebackType | None) -> None:
        self.close()
