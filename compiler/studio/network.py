"""Where the studio can be reached: the URL to print, the LAN address, a QR code of it."""

from __future__ import annotations

import contextlib
import ipaddress
import socket
import sys
from typing import TextIO

#: an address no packet is sent to: connecting a UDP socket only picks the outgoing interface
ROUTE_PROBE = ("192.0.2.1", 9)  # TEST-NET-1 (RFC 5737)


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    with contextlib.suppress(ValueError):
        return ipaddress.ip_address(host).is_loopback
    return False


def lan_address() -> str:
    """This machine's address on its local network (the interface of the default route), or
    127.0.0.1 when it has none."""
    with contextlib.suppress(OSError), socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.connect(ROUTE_PROBE)
        address: str = probe.getsockname()[0]
        return address
    return "127.0.0.1"


def shown_host(bound: str) -> str:
    """The host a person types: the LAN address for a wildcard bind, the bind address otherwise."""
    return lan_address() if bound in ("0.0.0.0", "::", "") else bound


def print_qr(url: str, out: TextIO | None = None) -> None:
    """The URL as a QR code in the terminal (a phone's camera opens it); on this call's stdout by default."""
    import segno  # only when the studio is served on the network

    segno.make(url, error="m").terminal(out=out if out is not None else sys.stdout, compact=True)
