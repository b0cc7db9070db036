"""Addresses and keys of links: loopback unless told otherwise, a key for other machines."""
from __future__ import annotations

import ipaddress
import os

from .wire import LinkError

KEY_VARIABLE = "IKAROS_LINK_KEY"
LOOPBACK_NAMES = {"localhost", "127.0.0.1", "::1"}


def is_loopback(host: str) -> bool:
    """Whether ``host`` is this machine only (127.0.0.0/8, ::1, localhost)."""
    if host in LOOPBACK_NAMES:
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def link_key(text: str | None) -> bytes | None:
    """The shared key: the given text, else the environment variable IKAROS_LINK_KEY,
    else None (no key)."""
    text = text or os.environ.get(KEY_VARIABLE, "")
    return text.encode() if text else None


def check_key(host: str, key: bytes | None, what: str) -> None:
    """A link that other machines can reach (or that reaches another machine) needs a key."""
    if key is None and not is_loopback(host):
        raise LinkError(f'{what} "{host}" is not this machine (127.0.0.1): a link to or from '
                        f'another machine needs a shared key: give the same key to both sides '
                        f'(the key parameter, ikaros worker --key, or the environment variable '
                        f'{KEY_VARIABLE})')


def tcp(host: str, port: int) -> str:
    """The ZeroMQ address of a TCP endpoint (``*`` and 0.0.0.0 bind every interface)."""
    if ":" in host and not host.startswith("["):
        host = f"[{host}]"
    return f"tcp://{host}:{port}"


def split_address(text: str, default_port: int) -> tuple[str, int]:
    """``host``, ``host:port`` or ``tcp://host:port`` -> (host, port)."""
    text = text.strip()
    if text.startswith("tcp://"):
        text = text[6:]
    host, colon, port = text.rpartition(":")
    if not colon or "]" in port:
        return text.strip("[]"), default_port
    if not port.isdigit() or not 0 <= int(port) <= 65535:
        raise LinkError(f'"{text}": the port must be a number from 0 to 65535')
    return host.strip("[]"), int(port)
