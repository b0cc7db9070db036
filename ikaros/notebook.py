"""Networks and models in Jupyter: HTML tables, the web UI in a cell, and a progress bar."""
from __future__ import annotations

import atexit
import html
import sys
import threading
from typing import Iterable

_SERVERS: dict[int, "WebView"] = {}     # id(net) -> the server showing it


def in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (not a terminal IPython, not a plain script)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    return shell is not None and type(shell).__name__ == "ZMQInteractiveShell"


# --- tables ------------------------------------------------------------------------------

def _table(title: str, header: Iterable[str], rows: list[Iterable]) -> str:
    e = html.escape
    head = "".join(f"<th style='text-align:left'>{e(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td style='text-align:left'>{e(str(c))}</td>"
                                    for c in row) + "</tr>" for row in rows)
    return (f"<details open><summary><b>{e(title)}</b> ({len(rows)})</summary>"
            f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></details>")


def _shape(buf) -> str:
    if buf.kind == "input" and not buf.incoming:
        return "unconnected"
    return "x".join(map(str, buf.shape)) if buf.shape else "scalar"


def network_html(net) -> str:
    """A network as HTML: its modules with class and port shapes, and its connections."""
    modules = []
    for inst in sorted(net.schedule, key=lambda m: m.order):
        inputs, outputs = net._buffers[inst]
        modules.append((inst.path, inst.entry.name,
                        ", ".join(f"{n} {_shape(b)}" for n, b in inputs.items()),
                        ", ".join(f"{n} {_shape(b)}" for n, b in outputs.items())))
    connections = [(run.source.path, run.target.path, run.delay, len(run.src_index))
                   for run in net.runs]
    state = "ended" if net.stopped else "running"
    return (f"<div><b>ikaros network {html.escape(net.top.name)}</b>: tick {net.tick}, "
            f"{state}, tick_duration {net.clock.tick_duration} s"
            + _table("Modules", ("module", "class", "inputs", "outputs"), modules)
            + _table("Connections", ("source", "target", "delay", "elements"), connections)
            + "</div>")


def model_html(model) -> str:
    """A model built in code (an ``ikaros.Group``) as HTML: modules with class and
    parameters, and connections (shapes are known once it is built)."""
    modules = [(m.path(), m.class_name,
                ", ".join(f"{k}={v}" for k, v in m.attrs.items() if k not in ("class", "name")))
               for m in model.walk() if hasattr(m, "class_name")]
    connections = []
    groups = [model] + [g for g in model.walk() if not hasattr(g, "class_name")]
    for group in groups:
        prefix = group.path()
        for c in group.connections:
            at = (lambda a: f"{prefix}.{a}" if prefix and a else a)
            connections.append((at(c.get("source")), at(c.get("target")),
                                c.get("delay", "1")))
    attrs = ", ".join(f"{k}={v}" for k, v in model.attrs.items() if k != "name")
    return (f"<div><b>ikaros model {html.escape(model.name or '')}</b>"
            f"{': ' + html.escape(attrs) if attrs else ''}"
            + _table("Modules", ("module", "class", "parameters"), modules)
            + _table("Connections", ("source", "target", "delay"), connections)
            + "</div>")


# --- the web UI in a cell ----------------------------------------------------------------

class WebView:
    """The web UI of a network served on 127.0.0.1 by a background thread; shown in a
    notebook cell as an IFrame. It stops with the Python process, or with ``stop()``."""

    def __init__(self, net, width: int | str = "100%", height: int = 600):
        from .webui.server import create_app, listen
        import uvicorn
        self.net = net
        self.width, self.height = width, height
        sock = listen("127.0.0.1", 0)
        self.port = sock.getsockname()[1]
        self.url = f"http://127.0.0.1:{self.port}/"
        app = create_app(net, hosts=("127.0.0.1", "localhost"))
        self.app = app
        config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="off",
                                timeout_graceful_shutdown=1, ws_per_message_deflate=False)
        self._server = uvicorn.Server(config)
        self._server.install_signal_handlers = lambda: None   # not the main thread
        self._thread = threading.Thread(target=self._server.run, kwargs={"sockets": [sock]},
                                        name="ikaros-notebook-ui", daemon=True)
        self._sock = sock
        self._thread.start()
        atexit.register(self.stop)

    @property
    def running(self) -> bool:
        return self._thread.is_alive()

    def stop(self, timeout: float = 5) -> None:
        """Stop the server (the network goes on)."""
        self._server.should_exit = True
        self._thread.join(timeout)
        self._sock.close()
        _SERVERS.pop(id(self.net), None)

    def _repr_html_(self) -> str:
        width = self.width if isinstance(self.width, str) else f"{self.width}px"
        return (f'<iframe src="{html.escape(self.url)}" style="width:{width};'
                f'height:{self.height}px;border:1px solid #ccc"></iframe>')

    def __repr__(self) -> str:
        return f"<ikaros web UI of {self.net.top.name} at {self.url}>"


def show(net, width: int | str = "100%", height: int = 600) -> WebView:
    """Serve the web UI of ``net`` (once per network) and show it in the cell. The servers
    of networks that have ended (closed, or replaced by ``net.apply``) are stopped."""
    for old in [v for v in _SERVERS.values() if v.net.stopped and v.net is not net]:
        old.stop()
    view = _SERVERS.get(id(net))
    if view is None or not view.running:
        view = _SERVERS[id(net)] = WebView(net, width, height)
    view.width, view.height = width, height
    return view


# --- a progress bar ----------------------------------------------------------------------

def run_with_progress(net, run, ticks: int) -> int:
    """Call ``run()`` (which runs ``ticks`` ticks) with a progress bar of the ticks done
    (without one when tqdm is not installed: ``pip install ikaros[notebook]``)."""
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return run()
    bar = tqdm(total=ticks, unit="tick", desc=net.top.name)
    hooks = net.controller.tick_hooks

    def advance():
        bar.update(1)
    hooks.append(advance)
    try:
        return run()
    finally:
        hooks.remove(advance)
        bar.close()
