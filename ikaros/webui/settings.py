"""The web UI's settings in the model's top group, under their Ikaros 3 names:

* ``webui_req_int``: the shortest time in seconds between two data snapshots sent to the
  clients (default ``1 / DEFAULT_MAX_RATE``: 15 a second);
* ``webui_log_buffer_limit``: how many of the latest messages the server keeps for
  ``/api/log`` (default 1000);
* ``rgb_quality``, ``gray_quality``: the JPEG quality (1-100) of colour and of gray images
  (default 85 both).

A bad value is reported as a warning and the default is used: the model runs as it would
without the web UI.
"""
from __future__ import annotations

from ..module import WARNING
from .encoding import JPEG_QUALITY

LOG_KEEP = 1000


def _setting(net, key: str, convert, kind: str, minimum, default, maximum=float("inf")):
    text = net.top.attrs.get(key)
    if text in (None, ""):
        return default
    try:
        value = convert(text.strip())
        if minimum <= value <= maximum and value != float("inf"):
            return value
    except ValueError:
        pass
    bounds = f">= {minimum}" if maximum == float("inf") else f"from {minimum} to {maximum}"
    net.notify(WARNING, None, f'{key}="{text}" must be {kind} {bounds}; the web UI '
                              f'uses {default:g}')
    return default


def req_interval(net, default: float) -> float:
    """Seconds between two snapshots at least: ``webui_req_int``, else ``default``."""
    return _setting(net, "webui_req_int", float, "a number of seconds", 0, default)


def log_limit(net) -> int:
    """The messages kept for ``/api/log``: ``webui_log_buffer_limit``, else LOG_KEEP."""
    return _setting(net, "webui_log_buffer_limit", int, "a whole number", 1, LOG_KEEP)


def jpeg_qualities(net) -> tuple[int, int]:
    """The JPEG quality of colour and of gray images: ``rgb_quality``, ``gray_quality``."""
    return tuple(_setting(net, key, int, "a whole number", 1, JPEG_QUALITY, maximum=100)
                 for key in ("rgb_quality", "gray_quality"))
