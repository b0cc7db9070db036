"""The web UI: an HTTP + WebSocket server over the kernel's control API, and the browser app
in ``static/``. The protocol is described in docs/webui-protocol.md.

    from ikaros.webui import create_app, serve
    serve(net, "127.0.0.1", 8000)        # blocks; the kernel runs in a background thread

Needs the ``web`` extra: ``pip install 'ikaros[web]'``.
"""
from __future__ import annotations

__all__ = ["create_app", "serve", "MissingWebDependencies"]


class MissingWebDependencies(ImportError):
    """Starlette, uvicorn or websockets is not installed."""


def _check() -> None:
    missing = []
    for name in ("starlette", "uvicorn", "websockets"):
        try:
            __import__(name)
        except ImportError:
            missing.append(name)
    if missing:
        raise MissingWebDependencies(
            f"the web UI needs {', '.join(missing)}: pip install 'ikaros[web]'")


def create_app(*args, **kwargs):
    """The Starlette app serving ``net`` (see ``ikaros.webui.server.create_app``)."""
    _check()
    from .server import create_app as _create_app
    return _create_app(*args, **kwargs)


def serve(*args, **kwargs):
    """Serve ``net`` until Ctrl-C (see ``ikaros.webui.server.serve``)."""
    _check()
    from .server import serve as _serve
    return _serve(*args, **kwargs)
