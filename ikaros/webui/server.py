"""The web UI server: Starlette on uvicorn, over ``Network`` and its ``Controller``.

``create_app(net)`` makes the ASGI app (the HTTP API, the WebSocket ``/api/ws``, the browser
app and the model's files); ``serve(net, host, port, token)`` runs it with uvicorn in the
calling thread while the kernel runs in the controller's background thread. The protocol
is described in docs/webui-protocol.md; ``/api/openapi.json`` describes the HTTP part.
"""
from __future__ import annotations

import asyncio
import collections
import contextlib
import ipaddress
import json
import math
import os
import secrets
import socket
import threading
from functools import partial
from http.cookies import SimpleCookie
from urllib.parse import parse_qs

import numpy as np
from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.exceptions import HTTPException
from starlette.requests import ClientDisconnect, Request
from starlette.responses import FileResponse
from starlette.routing import Mount, Route, WebSocketRoute
from starlette.staticfiles import StaticFiles
from starlette.websockets import WebSocket, WebSocketDisconnect

from .. import access, limits
from ..errors import ModelError, RunError
from .. import priority
from ..kernel.builder import Builder
from ..kernel.carry import take_over
from ..kernel.classes import classes as find_classes
from ..kernel.control import PAUSE, STATES, STEP, STOP
from ..module import Module
from . import compat, editing, saving, settings
from . import state as run_tools
from .builds import DEFAULT_BUILD_TIMEOUT, BuildTimeout, run_build
from .confine import AccessRefused, check_parameter_value, editor_confinement
from .encoding import FORMATS, IMAGE_FORMATS, image_shape_ok
from .history import MAX_POINTS, MAX_TICKS as MAX_WINDOW
from .rates import RUNNING, TickRate
from .recording import RecordButton, ReplayBar
from .guards import (DEFAULT_MAX_BODY, BodyLimit, BodyTooLarge, Framing, client_gone,
                     quiet_refused_websockets)
from .openapi import openapi
from .requests import ApiError, Json, _body, _error, _loads, _query
from .snapshot import (DEFAULT_BUDGET, DEFAULT_MAX_RATE, STATUS_INTERVAL, Client, Hub,
                       LogBook, between_ticks, kernel_thread_alive, plain)
from .views import module_detail, network_json

STATIC_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "static")
TOKEN_COOKIE = "ikaros_token"
MAX_SUBSCRIPTIONS = 1000
# What /files/ serves from the model's folder: images for image widgets, nothing else.
FILE_TYPES = (".png", ".jpg", ".jpeg", ".gif", ".bmp", ".webp", ".svg")


class ImageFiles(StaticFiles):
    """Static files limited to image types."""

    def lookup_path(self, path: str):
        if not path.lower().endswith(FILE_TYPES):
            return "", None
        return super().lookup_path(path)


# --- access ------------------------------------------------------------------------------

def _token_of(scope) -> tuple[str | None, bool]:
    """(token given, whether it came in the query string)."""
    headers = {k.decode("latin-1").lower(): v.decode("latin-1")
               for k, v in scope.get("headers", [])}
    auth = headers.get("authorization", "")
    if auth.lower().startswith("bearer "):
        return auth[7:].strip(), False
    query = parse_qs(scope.get("query_string", b"").decode("latin-1"))
    if "token" in query:
        return query["token"][-1], True
    if "cookie" in headers:
        cookie = SimpleCookie()
        try:
            cookie.load(headers["cookie"])
        except Exception:
            return None, False
        if TOKEN_COOKIE in cookie:
            return cookie[TOKEN_COOKIE].value, False
    return None, False


class AccessMiddleware:
    """With a token, every HTTP request and WebSocket must carry it (``Authorization:
    Bearer``, ``?token=`` or the cookie set when it came in the query); otherwise 401.
    Cross-site requests that change something are refused in any case."""

    def __init__(self, app, token: str | None, hosts: tuple | None = None):
        self.app = app
        self.token = token
        self.hosts = {h.lower() for h in hosts} if hosts else None

    async def __call__(self, scope, receive, send):
        if scope["type"] not in ("http", "websocket"):
            return await self.app(scope, receive, send)
        if self.hosts is not None and _host_name(scope) not in self.hosts:
            return await self._deny(scope, receive, send, 400,
                                    "unknown Host: serve other names with --bind")
        if scope["type"] == "websocket" or scope.get("method") not in ("GET", "HEAD"):
            if not _same_origin(scope):
                return await self._deny(scope, receive, send, 403,
                                        "cross-origin request refused")
        if self.token is None:
            return await self.app(scope, receive, send)
        given, in_query = _token_of(scope)
        if given is None or not secrets.compare_digest(given.encode(), self.token.encode()):
            msg = "a valid access token is required" if given else \
                "an access token is required (Authorization: Bearer TOKEN or ?token=TOKEN)"
            return await self._deny(scope, receive, send, 401, msg)
        if in_query and scope["type"] == "http":
            cookie = f"{TOKEN_COOKIE}={self.token}; Path=/; HttpOnly; SameSite=Strict"

            async def send_with_cookie(message):
                if message["type"] == "http.response.start":
                    message = dict(message)
                    message["headers"] = list(message.get("headers", [])) + [
                        (b"set-cookie", cookie.encode("latin-1"))]
                await send(message)
            return await self.app(scope, receive, send_with_cookie)
        return await self.app(scope, receive, send)

    async def _deny(self, scope, receive, send, status, message):
        headers = {"WWW-Authenticate": "Bearer"} if status == 401 else None
        response = _error(status, message, headers)
        if scope["type"] == "http":
            return await response(scope, receive, send)
        await receive()                                   # websocket.connect
        if "websocket.http.response" in scope.get("extensions", {}):
            await send({"type": "websocket.http.response.start", "status": status,
                        "headers": response.raw_headers})
            await send({"type": "websocket.http.response.body", "body": response.body})
        else:
            await send({"type": "websocket.close", "code": 1008, "reason": message})


def _host_name(scope) -> str:
    for k, v in scope.get("headers", []):
        if k.lower() == b"host":
            host = v.decode("latin-1").strip().lower()
            if host.startswith("["):
                return host[1:].split("]")[0]
            return host.rsplit(":", 1)[0] if host.count(":") == 1 else host
    return ""


_SECURE = {"http": "http", "ws": "http", "https": "https", "wss": "https"}


def _same_origin(scope) -> bool:
    """No Origin header, or exactly one naming this server's scheme, host and port."""
    headers = [(k.decode("latin-1").lower(), v.decode("latin-1"))
               for k, v in scope.get("headers", [])]
    origins = [v for k, v in headers if k == "origin"]
    if not origins:
        return True
    if len(origins) > 1:
        return False
    scheme, sep, rest = origins[0].strip().partition("://")
    host = next((v for k, v in headers if k == "host"), "")
    return bool(sep) and scheme.lower() == _SECURE.get(scope.get("scheme", "http"), "") \
        and rest.rstrip("/").lower() == host.strip().lower()


# --- validation helpers ------------------------------------------------------------------

def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _string(body: dict, key: str) -> str:
    v = body.get(key)
    if not isinstance(v, str) or not v.strip():
        raise ApiError(400, f'"{key}" must be a non-empty string')
    return v.strip()


def _check_value(path: str, ptype: str, value) -> None:
    """Refuse a value of the wrong JSON type for a parameter type (text is parsed by the
    kernel as in a model file)."""
    if value is None:
        raise ApiError(400, f'"value" for parameter "{path}" must not be null')
    if isinstance(value, str):
        return
    if not (_is_number(value) or isinstance(value, bool) or _numbers(value)):
        raise ApiError(400, f'"value" must be a number, a boolean, a string or a (nested) '
                            f'list of numbers, not {json.dumps(value)[:80]}')
    ok = {
        "number": _is_number(value),
        "int": _is_number(value) and float(value) == int(value),
        "bool": isinstance(value, bool) or value in (0, 1) and _is_number(value),
        "string": False,
        "list": isinstance(value, int) and not isinstance(value, bool) and value >= 0,
        "array": _numbers(value),
        "matrix": _numbers(value),
    }.get(ptype, False)
    if not ok:
        raise ApiError(422, f'bad value {json.dumps(value)[:80]} for {ptype} parameter '
                            f'"{path}"')


def _overrides_of(net) -> dict:
    """The top-group attributes given beside the file (``name=value`` on the command line,
    ``-d``, ``-t``): those of the built top group that the file does not say."""
    defaults = {c.get("name") for c in net.model.elements("parameter")
                if not c.get("target")}
    return {k: v for k, v in net.top.attrs.items()
            if net.model.attrs.get(k) != v and k not in defaults}


def _numbers(v) -> bool:
    if _is_number(v):
        return True
    return isinstance(v, list) and all(_numbers(x) for x in v)


# --- the app -----------------------------------------------------------------------------

class WebUI:
    """The state behind the routes of one app."""

    def __init__(self, net, static_dir: str, budget: float, max_rate: float,
                 status_interval: float, models_dir: str | None = None,
                 build_timeout: float = DEFAULT_BUILD_TIMEOUT,
                 build_limits: limits.Limits | None = None, failure: dict | None = None):
        self.net = net
        # A model that failed to build (webui/broken.py): its tree and error, until a build
        # from the editor succeeds.
        self.failure = failure
        self.on_quit = None                     # set by serve(): ends the server
        self.static_dir = os.path.abspath(static_dir)
        self.model_dir = os.path.dirname(os.path.abspath(net.filename)) if net.filename \
            else None
        # The one folder the editor saves, lists, opens and creates models in.
        self.models_dir = os.path.abspath(models_dir) if models_dir else self.model_dir
        # What a model from the editor may touch (docs/webui.md, "Who can do what").
        self.confinement = editor_confinement(self.models_dir, self.model_dir)
        self.build_timeout = build_timeout
        self.build_limits = build_limits
        self.logbook = LogBook(net)
        self.rates = TickRate()
        self.hub = Hub(net, self.status, self.logbook, budget, max_rate or DEFAULT_MAX_RATE,
                       status_interval)
        self._max_rate_given = max_rate is not None     # else the model's webui_req_int
        self._model_settings(net)
        self._classes = None
        self._changing = threading.Lock()       # one apply / open / new at a time
        self._ended_by_stop = None              # the network whose run the stop button ended
        # The network built from the command line's file (and its rebuilds after a stop):
        # rebuilt as the command line built it, not confined as a model from the editor.
        self._command_line_net = None if failure else net
        # What the command line set beside the file, kept while the model is rebuilt
        # (dropped when another model is opened or a new one made).
        self._overrides = _overrides_of(net)
        own_stop = net.top.attrs.get("stop")
        self._cli_stop = net.stop_tick if str(net.stop_tick) != str(own_stop).strip() and \
            not (net.stop_tick is None and own_stop in (None, "")) else None

    def _model_settings(self, net) -> None:
        """The web UI settings of the model's top group (webui/settings.py)."""
        keep = settings.log_limit(net)
        with self.logbook._lock:
            if keep != self.logbook.messages.maxlen:
                self.logbook.messages = collections.deque(self.logbook.messages, maxlen=keep)
        if not self._max_rate_given:
            self.hub.min_interval = settings.req_interval(net, 1.0 / DEFAULT_MAX_RATE)
        self.hub.rgb_quality, self.hub.gray_quality = settings.jpeg_qualities(net)

    # --- reads ---------------------------------------------------------------------------
    def status(self) -> dict:
        figures = plain(self.net.controller.figures())
        figures["file"] = os.path.basename(self.net.filename or "")
        figures["webui_req_int"] = self.hub.min_interval
        figures["webui_log_buffer_limit"] = self.logbook.messages.maxlen
        figures["rgb_quality"] = self.hub.rgb_quality
        figures["gray_quality"] = self.hub.gray_quality
        stop = self.net.stop_tick
        figures["stop_tick"] = stop if stop is not None and stop >= 0 else None
        if self.net.stopped:
            figures["state"] = "stop"
        running = figures["state"] in RUNNING
        figures.update(self.rates.sample(figures["tick"], running,
                                         tick_duration=figures["actual_tick_duration"] or 0.0))
        if not running:
            figures["actual_tick_duration"] = None    # no tick is running to measure
        return figures

    def _module(self, path: str):
        inst = self.net.modules.get(path)
        if inst is None:
            raise ApiError(404, f'no module "{path}" in {self.net.top.name}')
        return inst

    def _buffer_path(self, path: str) -> str:
        try:
            self.net.buffer_array(path)
        except KeyError:
            raise ApiError(404, f'no output or input "{path}" in {self.net.top.name}') \
                from None
        return path

    def _parameter_spec(self, path: str):
        comp, _, name = path.rpartition(".")
        inst = self.net.modules.get(comp)
        if inst is None or name not in inst.values:
            raise ApiError(404, f'no parameter "{path}" in {self.net.top.name}')
        return inst.module.description.parameter(name)

    async def _call(self, fn, *args):
        return await run_in_threadpool(between_ticks, self.net, fn, *args)

    # --- HTTP endpoints ------------------------------------------------------------------
    async def index(self, request: Request):
        _query(request)
        path = os.path.join(self.static_dir, "index.html")
        if not os.path.isfile(path):
            raise ApiError(404, "the browser app is not installed (no static/index.html)")
        return FileResponse(path)

    async def network(self, request: Request):
        _query(request)
        out = await self._call(network_json, self.net)
        if self.failure:
            out["build_error"] = self.failure["error"]
        return Json(out)

    async def classes(self, request: Request):
        _query(request)
        if self._classes is None:
            folders = [self.model_dir] if self.model_dir else []
            found = await run_in_threadpool(find_classes, folders)
            self._classes = {name: desc.to_dict() for name, desc in found.items()}
        return Json(self._classes)

    async def get_status(self, request: Request):
        _query(request)
        return Json(self.status())

    async def control(self, request: Request):
        body = await _body(request, ("state",))
        state = body["state"]
        if state not in STATES:
            raise ApiError(400, f'"state" must be one of {", ".join(STATES)}, not '
                                f'{json.dumps(state)[:40]}')
        net, ctrl = self.net, self.net.controller
        if net.stopped:
            if net is self._ended_by_stop and state != STOP:
                return await self._rebuild(state)
            raise ApiError(409, "the run has ended; apply, open or reload a model to run "
                                "again")
        self.status()                       # a rate sample at the change of state
        if state == STOP:           # the run ends: every module's stop(), devices made safe
            try:
                await run_in_threadpool(ctrl.end)
            except TimeoutError as e:
                raise ApiError(500, str(e)) from None
            self._ended_by_stop = net
        elif state in ("step", "play", "realtime") and not kernel_thread_alive(ctrl):
            ctrl.start(state)
        else:
            ctrl.set_state(state)
        return Json(self.status())

    async def _rebuild(self, state: str):
        """Run again after a stop: the model as it was built (with the edits applied to it)
        is built anew and runs from tick 0 in ``state``, as Ikaros 3 reloads its file."""
        with self._change():
            filename = self.net.filename
            model = await self._call(self._model_json)
            tree = self._tree({"tree": model["tree"]}, filename)
            command_line = self.net is self._command_line_net
            try:
                new = await self._build(filename, tree, self._overrides,
                                        confined=not command_line)
            except (ModelError, BuildTimeout) as e:
                return Json({"error": str(e), "node": None, "path": None}, status_code=422)
            await self._swap(new, state)
            if command_line:
                self._command_line_net = new
        return Json(self.status())

    async def parameter(self, request: Request):
        body = await _body(request, ("path", "value"), ("x", "y"))
        path = _string(body, "path")
        spec = self._parameter_spec(path)
        value, x, y = body["value"], body.get("x"), body.get("y")
        element = x is not None or y is not None
        if element:
            for key, v in (("x", x), ("y", y)):
                if v is not None and not (isinstance(v, int) and not isinstance(v, bool)
                                          and v >= 0):
                    raise ApiError(400, f'"{key}" must be a whole number >= 0')
            if spec.type not in ("array", "matrix"):
                raise ApiError(422, f'"x"/"y" need an array or matrix parameter; "{path}" '
                                    f'is a {spec.type}')
            if not _is_number(value) and not isinstance(value, bool):
                raise ApiError(422, f'"value" for one element of "{path}" must be a number')
        else:
            _check_value(path, spec.type, value)
            try:
                check_parameter_value(self.confinement, spec, value, self.net.filename)
            except AccessRefused as e:
                raise ApiError(403, str(e)) from None

        def change():
            net = self.net
            if element:
                arr = np.array(net.parameter(path), dtype=np.float32)
                xi, yi = x or 0, y or 0
                if arr.ndim == 1 and yi == 0 and xi < arr.shape[0]:
                    arr[xi] = float(value)
                elif arr.ndim == 2 and yi < arr.shape[0] and xi < arr.shape[1]:
                    arr[yi, xi] = float(value)
                else:
                    raise ApiError(422, f'no element x={xi}, y={yi} in "{path}" of shape '
                                        f'{list(arr.shape)}')
                net.set_parameter(path, arr)
            else:
                net.set_parameter(path, value)
            return net.parameter(path)
        try:
            new = await self._call(change)
        except ValueError as e:
            raise ApiError(422, str(e)) from None
        except KeyError as e:
            raise ApiError(404, str(e.args[0]) if e.args else str(e)) from None
        return Json({"path": path, "value": new})

    async def command(self, request: Request):
        body = await _body(request, ("module", "name"), ("x", "y", "value"))
        path, name = _string(body, "module"), _string(body, "name")
        inst = self._module(path)
        x, y = body.get("x", 0), body.get("y", 0)
        for key, v in (("x", x), ("y", y)):
            if not _is_number(v):
                raise ApiError(400, f'"{key}" must be a number')
        if type(inst.module).command is Module.command:
            raise ApiError(422, f'module "{path}" ({inst.entry.name}) takes no commands')
        try:
            await self._call(self.net.command, path, name, float(x), float(y),
                             body.get("value"))
        except KeyError as e:
            raise ApiError(404, str(e.args[0]) if e.args else str(e)) from None
        except Exception as e:
            raise ApiError(422, f'command "{name}" of "{path}" failed: '
                                f'{type(e).__name__}: {e}') from None
        return Json({"ok": True})

    async def module(self, request: Request):
        q = _query(request, ("path",))
        if "path" not in q:
            raise ApiError(400, 'missing query parameter "path"')
        inst = self._module(q["path"])
        return Json(await self._call(module_detail, self.net, inst))

    async def data(self, request: Request):
        q = _query(request, ("paths",))
        if not q.get("paths", "").strip():
            raise ApiError(400, 'missing query parameter "paths" (comma-separated paths)')
        paths = [self._buffer_path(p.strip()) for p in q["paths"].split(",")]

        def read():
            return {"tick": self.net.tick,
                    "data": {p: self.net.buffer_array(p).tolist() for p in paths}}
        return Json(await self._call(read))

    async def log(self, request: Request):
        q = _query(request, ("since",))
        text = q.get("since", "0")
        if not text.isdigit():
            raise ApiError(400, f'"since" must be a whole number >= 0, not "{text}"')
        nxt, messages = self.logbook.since(int(text))
        return Json({"next": nxt, "messages": messages})

    # --- the editor ----------------------------------------------------------------------
    def _folder(self) -> str:
        if not self.models_dir:
            raise ApiError(404, "the model has no folder")
        return self.models_dir

    def _model_json(self) -> dict:
        net = self.net
        if self.failure:
            f = self.failure
            return {"file": f["file"], "folder": self._folder(), "tree": f["tree"],
                    "version": saving.file_version(net.filename),
                    "error": {k: f[k] for k in ("error", "node", "path")}}
        tree = editing.tree_json(net.model, os.path.dirname(os.path.abspath(net.filename)))
        return {"file": os.path.basename(net.filename or ""), "folder": self._folder(),
                "tree": tree, "version": saving.file_version(net.filename)}

    async def model(self, request: Request):
        _query(request)
        return Json(await self._call(self._model_json))

    def _tree(self, body: dict, filename: str, reread: bool = True):
        try:
            with access.applied(self.confinement):
                return editing.tree_from_json(body["tree"], filename, reread)
        except editing.TreeError as e:
            raise ApiError(400, f'"tree": {e}') from None

    async def apply(self, request: Request):
        body = await _body(request, ("tree",), ("state",))
        state = body.get("state")
        if state is not None and (state not in STATES or state == STOP):
            raise ApiError(400, f'"state" must be one of '
                                f'{", ".join(s for s in STATES if s != STOP)}')
        with self._change():
            filename = self.net.filename
            try:
                tree = self._tree(body, filename)
                overrides = self._overrides
                new = await self._build(filename, tree, overrides, predecessor=self.net)
            except ModelError as e:
                return Json(editing.error_json(e), status_code=422)
            except BuildTimeout as e:
                return Json({"error": str(e), "node": None, "path": None}, status_code=422)
            await self._swap(new, state, keep_state=True)
        return Json({"ok": True, "network": await self._call(network_json, self.net)})

    async def save(self, request: Request):
        body = await _body(request, ("tree",), ("filename", "version"))
        name = body.get("filename")
        if name is None:
            path = self.net.filename
        else:
            if not isinstance(name, str):
                raise ApiError(400, '"filename" must be a string')
            path = self._file(name)
        version = body.get("version")
        if version is not None and not isinstance(version, str):
            raise ApiError(400, '"version" must be a string or null')
        tree = self._tree(body, path, reread=False)
        try:                    # the text is made before a file is: nothing half-written
            version = await run_in_threadpool(saving.save, tree, path, version,
                                              "version" in body)
        except saving.SaveConflict as e:
            return Json({"error": f"{os.path.basename(path)} was saved by another editor "
                                  f"(or changed on disk) since these edits began",
                         "version": e.version}, status_code=409)
        except ValueError as e:
            raise ApiError(400, f"the tree can not be written as XML: {e}") from None
        except OSError as e:
            raise ApiError(500, f"cannot write {os.path.basename(path)}: "
                                f"{e.strerror or e}") from None
        if path != self.net.filename:       # save as: the model's file is the new one now
            self.net.filename = path
            self._set_model_dir(os.path.dirname(path))
        return Json({"ok": True, "file": os.path.basename(path), "version": version})

    def _file(self, name: str) -> str:
        try:
            return editing.file_in(self._folder(), name)
        except editing.NameRefused as e:
            raise ApiError(403, str(e)) from None

    async def files(self, request: Request):
        _query(request)
        folder = self._folder()
        return Json({"folder": folder,
                     "files": await run_in_threadpool(editing.model_files, folder)})

    async def open(self, request: Request):
        body = await _body(request, ("filename",))
        name = body["filename"]
        if not isinstance(name, str):
            raise ApiError(400, '"filename" must be a string')
        path = self._file(name)
        real, folder = os.path.realpath(path), os.path.realpath(self._folder())
        if not os.path.isfile(path) or os.path.dirname(real) != folder:
            raise ApiError(404, f'no model "{name}" in the models folder')
        with self._change():
            try:
                new = await self._build(path, None, None)
            except (ModelError, BuildTimeout) as e:
                return Json({"error": str(e), "node": None, "path": None},
                            status_code=422)
            self._overrides, self._cli_stop = None, None
            await self._swap(new, PAUSE)
        return Json({"ok": True, "file": os.path.basename(path),
                     "network": await self._call(network_json, self.net)})

    async def new(self, request: Request):
        body = await _body(request, (), ("name",))
        try:
            tree, path = editing.new_model(self._folder(), body.get("name", "Untitled"))
        except editing.TreeError as e:
            raise ApiError(400, str(e)) from None
        with self._change():
            try:
                new = await self._build(path, tree, None)
            except ModelError as e:
                return Json(editing.error_json(e), status_code=422)
            except BuildTimeout as e:
                return Json({"error": str(e), "node": None, "path": None}, status_code=422)
            self._overrides, self._cli_stop = None, None
            await self._swap(new, PAUSE)
        return Json({"ok": True, "file": os.path.basename(path),
                     "network": await self._call(network_json, self.net)})

    @contextlib.contextmanager
    def _change(self):
        """Hold the lock of model changes; 409 when another change is under way."""
        if not self._changing.acquire(blocking=False):
            raise ApiError(409, "another apply, open or new is under way")
        try:
            yield
        finally:
            self._changing.release()

    async def _build(self, filename: str, tree, overrides: dict | None,
                     confined: bool = True, predecessor=None):
        """Build a network in a thread of its own, confined to the editor's folders (unless
        it is the command line's model built again), within the build time limit
        (BuildTimeout). With ``predecessor`` (an Apply) the modules that did not change are
        left to take over from it (``_swap(keep_state=True)``)."""
        log_level = self.net.log_level
        diagnostics = self.net.diagnostics.fresh()

        def build():
            with access.applied(self.confinement if confined else None):
                new = Builder(filename, overrides, model=tree, diagnostics=diagnostics,
                              limits=self.build_limits,
                              user_data=getattr(self.net, "user_data", None),
                              predecessor=predecessor).build()
            new.log_level = log_level
            return new
        return await run_build(build, self.build_timeout)

    async def _swap(self, new, state: str | None, keep_state: bool = False) -> None:
        """Stop and close the running network; run ``new`` in its place (with
        ``keep_state``, going on from the old one's tick with the state of the modules that
        did not change: an Apply)."""
        old, ctrl = self.net, self.net.controller
        alive = kernel_thread_alive(ctrl)
        previous = PAUSE if old.stopped or ctrl.state in (STOP, STEP) else ctrl.state
        state = state or previous
        ctrl.stop()
        await run_in_threadpool(ctrl.join, 30)
        if ctrl.running:
            await run_in_threadpool(new.close)
            raise ApiError(500, "the running network did not stop within 30 s")
        if keep_state:
            take_over(old, new)     # the modules that did not change keep their state
        else:
            new.profiling = old.profiling
            new.controller.tick_hooks.extend(ctrl.tick_hooks)
            ctrl.tick_hooks.clear()
        if self._cli_stop is not None:
            new.stop_tick = self._cli_stop
        await run_in_threadpool(old.close)
        # the wiring: everything that read the old network reads the new one
        self.net = new
        self.failure = None
        self.logbook.net = new
        self.logbook._last = None
        self._model_settings(new)
        hub = self.hub
        for client in list(hub.clients):
            client.subs = [(p, f) for p, f in client.subs if self._still_there(p, f)]
            client.version += 1
            client.last = None
        hub.use_network(new)
        self._set_model_dir(os.path.dirname(os.path.abspath(new.filename)))
        if alive or state not in (PAUSE,):
            new.controller.start(state)
        else:
            new.controller.set_state(state)
        hub.broadcast({"type": "network"})
        hub.poke()

    def _set_model_dir(self, folder: str) -> None:
        if folder != self.model_dir:
            self.model_dir = folder
            self._classes = None

    def _still_there(self, path: str, fmt: str) -> bool:
        try:
            shape = tuple(self.net.buffer_array(path).shape)
        except KeyError:
            return False
        return fmt not in IMAGE_FORMATS or image_shape_ok(shape)

    async def openapi(self, request: Request):
        _query(request)
        return Json(openapi())

    # --- the WebSocket -------------------------------------------------------------------
    async def websocket(self, ws: WebSocket):
        await ws.accept()
        client = Client(ws)
        self.hub.add(client)
        sender = asyncio.get_running_loop().create_task(self._send(client))
        try:
            while True:
                message = await ws.receive()
                if message["type"] == "websocket.disconnect":
                    break
                text = message.get("text")
                if text is None:
                    client.send_text({"type": "error",
                                      "error": "send JSON text frames, not binary"})
                    continue
                try:
                    self._handle(client, text)
                except ApiError as e:
                    client.send_text({"type": "error", "error": e.message})
        except WebSocketDisconnect:
            pass
        finally:
            self.hub.remove(client)
            sender.cancel()

    async def _send(self, client: Client):
        try:
            await client.run_sender()
        except asyncio.CancelledError:
            raise
        except Exception:             # the connection went away; the reader sees it too
            pass

    def _handle(self, client: Client, text: str) -> None:
        try:
            msg = _loads(text)
        except ValueError as e:
            raise ApiError(400, f"not valid JSON: {e}") from None
        if not isinstance(msg, dict) or not isinstance(msg.get("type"), str):
            raise ApiError(400, 'a message must be a JSON object with a "type"')
        kind = msg["type"]
        if kind == "ready":
            self.hub.set_ready(client)
        elif kind == "ping":
            client.send_text({"type": "pong", "t": msg.get("t")})
        elif kind == "subscribe":
            self.hub.subscribe(client, *self._subscriptions(msg))
        else:
            raise ApiError(400, f'unknown message type "{kind}" (subscribe, ready, ping)')

    def _subscriptions(self, msg: dict
                       ) -> tuple[list[tuple[str, str]], dict[str, int], dict[str, int]]:
        for key in msg:
            if key not in ("type", "buffers"):
                raise ApiError(400, f'unknown field "{key}" in subscribe')
        buffers = msg.get("buffers")
        if not isinstance(buffers, list):
            raise ApiError(400, 'subscribe needs "buffers": a list of {"path", "format"}')
        if len(buffers) > MAX_SUBSCRIPTIONS:
            raise ApiError(400, f"at most {MAX_SUBSCRIPTIONS} buffers")
        subs, points, windows = [], {}, {}
        for b in buffers:
            if not isinstance(b, dict) or not isinstance(b.get("path"), str):
                raise ApiError(400, 'each buffer must be {"path": "A.OUTPUT", "format": '
                                    '"raw"}')
            for key in b:
                if key not in ("path", "format", "points", "ticks"):
                    raise ApiError(400, f'unknown field "{key}" in a buffer')
            path, fmt = b["path"].strip(), b.get("format", "raw")
            if fmt not in FORMATS:
                raise ApiError(400, f'unknown format {json.dumps(fmt)[:40]} for "{path}" '
                                    f'(one of {", ".join(FORMATS)})')
            self._buffer_path(path)
            if fmt in IMAGE_FORMATS:
                shape = tuple(self.net.buffer_array(path).shape)
                if not image_shape_ok(shape):
                    raise ApiError(400, f'"{path}" of shape {list(shape)} is not an image: '
                                        f'{fmt} needs (rows, cols) or (3, rows, cols)')
            if "points" in b:
                n = b["points"]
                if fmt != "history" or not isinstance(n, int) or isinstance(n, bool) \
                        or not 1 <= n <= MAX_POINTS:
                    raise ApiError(400, f'"points" of "{path}" must be a whole number '
                                        f'1..{MAX_POINTS}, with the format "history"')
                points[path] = n
            if "ticks" in b:
                n = b["ticks"]
                if fmt != "history" or not isinstance(n, int) or isinstance(n, bool) \
                        or not 1 <= n <= MAX_WINDOW:
                    raise ApiError(400, f'"ticks" of "{path}" must be a whole number '
                                        f'1..{MAX_WINDOW}, with the format "history"')
                windows[path] = n
            subs.append((path, fmt))
        return subs, points, windows


def create_app(net, token: str | None = None, static_dir: str | None = None, *,
               hosts: tuple | None = None, budget: float = DEFAULT_BUDGET,
               max_rate: float | None = None,
               status_interval: float = STATUS_INTERVAL,
               models_dir: str | None = None, max_body: int = DEFAULT_MAX_BODY,
               build_timeout: float = DEFAULT_BUILD_TIMEOUT,
               max_memory: int | None = None, failure: dict | None = None) -> Starlette:
    """The ASGI app serving ``net``. With ``token``, every request must carry it. With
    ``hosts``, requests whose ``Host`` names another host are refused (a guard against DNS
    rebinding when no token is required). ``budget`` is the time in seconds the kernel may
    spend copying data for clients after one tick; ``max_rate`` caps the data frames per
    second (default: one per the model's ``webui_req_int`` seconds, else 15). ``models_dir``
    is the folder the editor saves, lists, opens and creates models in (default: the
    model's folder). The editor may replace the running network:
    ``app.state.ui.net`` is the current one. ``max_body`` limits request bodies and
    WebSocket messages (bytes); the editor's builds are abandoned after ``build_timeout``
    seconds and may use ``max_memory`` bytes of buffers. ``failure`` is a model that failed
    to build (``webui.broken.open_broken``), shown in the editor."""
    build_limits = limits.Limits().with_memory(max_memory)
    ui = WebUI(net, static_dir or STATIC_DIR, budget, max_rate, status_interval, models_dir,
               build_timeout, build_limits, failure)
    routes = [
        Route("/", ui.index, methods=["GET"]),
        Route("/api/network", ui.network, methods=["GET"]),
        Route("/api/classes", ui.classes, methods=["GET"]),
        Route("/api/status", ui.get_status, methods=["GET"]),
        Route("/api/control", ui.control, methods=["POST"]),
        Route("/api/parameter", ui.parameter, methods=["POST"]),
        Route("/api/command", ui.command, methods=["POST"]),
        Route("/api/module", ui.module, methods=["GET"]),
        Route("/api/data", ui.data, methods=["GET"]),
        Route("/api/log", ui.log, methods=["GET"]),
        Route("/api/model", ui.model, methods=["GET"]),
        Route("/api/apply", ui.apply, methods=["POST"]),
        Route("/api/save", ui.save, methods=["POST"]),
        Route("/api/files", ui.files, methods=["GET"]),
        Route("/api/open", ui.open, methods=["POST"]),
        Route("/api/new", ui.new, methods=["POST"]),
        Route("/api/openapi.json", ui.openapi, methods=["GET"]),
        Route("/api/state", partial(run_tools.state, ui), methods=["POST"]),
        Route("/api/profiling", partial(run_tools.profiling, ui), methods=["GET", "POST"]),
        Route("/api/startup", partial(run_tools.startup, ui), methods=["GET"]),
        Route("/api/quit", partial(run_tools.quit_, ui), methods=["POST"]),
        Route("/json/{path:path}", partial(compat.json_value, ui), methods=["GET"]),
        Route("/csv/{path:path}", partial(compat.csv_value, ui), methods=["GET"]),
        WebSocketRoute("/api/ws", ui.websocket),
        Mount("/static", app=StaticFiles(directory=ui.static_dir, check_dir=False),
              name="static"),
    ]
    routes[-2:-2] = [Route("/api/record", RecordButton(ui).endpoint, methods=["GET", "POST"]),
                     Route("/api/replay", ReplayBar(ui).endpoint, methods=["GET", "POST"])]
    if ui.model_dir:
        async def model_files(scope, receive, send):      # the current model's folder
            app = ImageFiles(directory=ui.model_dir, check_dir=False)
            await app(scope, receive, send)
        routes.append(Mount("/files", app=model_files, name="files"))

    async def api_error(request, exc: ApiError):
        return _error(exc.status, exc.message)

    async def http_error(request, exc: HTTPException):
        if exc.status_code == 404:
            message = f"not found: {request.url.path}"
        elif exc.status_code == 405:
            message = f"method {request.method} not allowed on {request.url.path}"
        else:
            message = str(exc.detail)
        return _error(exc.status_code, message, getattr(exc, "headers", None))

    async def body_too_large(request, exc: BodyTooLarge):
        return _error(413, str(exc))

    async def server_error(request, exc: Exception):
        return _error(500, f"internal error: {type(exc).__name__}: {exc}")

    app = Starlette(routes=routes, exception_handlers={
        ApiError: api_error, HTTPException: http_error, BodyTooLarge: body_too_large,
        ClientDisconnect: client_gone, Exception: server_error})
    app.state.ui = ui
    app.add_middleware(BodyLimit, limit=max_body,
                       too_large=_error(413, str(BodyTooLarge(max_body))))
    app.add_middleware(AccessMiddleware, token=token, hosts=hosts)
    app.add_middleware(Framing, answer=lambda status, message: _error(
        status, message, {"Connection": "close"}))
    return app


# --- serving -----------------------------------------------------------------------------

class ServeError(Exception):
    """The server could not start (the address is in use, say)."""


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def new_token() -> str:
    return secrets.token_urlsafe(18)


def listen(host: str, port: int) -> socket.socket:
    """A listening socket on host:port (port 0 picks a free one)."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as e:
        raise ServeError(f'cannot resolve "{host}": {e.strerror or e}') from None
    family, _, _, _, address = infos[0]
    sock = socket.socket(family, socket.SOCK_STREAM)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(address)
        sock.listen(128)
    except OSError as e:
        sock.close()
        raise ServeError(f"cannot listen on {host}:{port}: {e.strerror or e}") from None
    sock.set_inheritable(True)
    return sock


def serve(net, host: str = "127.0.0.1", port: int = 8000, token: str | None = None,
          state: str = "pause", static_dir: str | None = None, sock=None,
          on_ready=None, on_end=None, **app_options) -> None:
    """Serve the web UI of ``net`` until Ctrl-C (or SIGTERM), with the kernel running in
    the controller's background thread, starting in ``state``. Serving another machine
    (a host that is not a loopback address) requires a token. ``on_ready(url)`` is called
    once the socket listens; ``on_end(network)`` once the kernel loop has stopped, with the
    network then served (the editor may have built another), before it is closed. The
    caller closes ``net`` (a network the editor built in its place is closed here)."""
    import uvicorn
    if token is None and not is_loopback(host):
        raise ServeError(f"serving {host} (not this machine only) requires an access token")
    if token is None and "hosts" not in app_options:
        app_options["hosts"] = ("127.0.0.1", "localhost", "::1", host)
    app = create_app(net, token=token, static_dir=static_dir, **app_options)
    sock = sock or listen(host, port)
    port = sock.getsockname()[1]
    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="off",
                            timeout_graceful_shutdown=3, ws_per_message_deflate=False,
                            ws_max_size=app_options.get("max_body", DEFAULT_MAX_BODY))
    server = uvicorn.Server(config)

    def quit_server():
        app.state.ui.net.controller.stop()
        server.should_exit = True
    app.state.ui.on_quit = quit_server
    quiet_refused_websockets()
    ctrl = net.controller
    previous_hook = threading.excepthook

    def quiet_run_errors(args):
        # A fatal error ends the run; it has been reported already and the UI shows it.
        if not issubclass(args.exc_type, RunError):
            previous_hook(args)
    threading.excepthook = quiet_run_errors
    ctrl.start(state)
    try:
        if on_ready is not None:
            shown = f"[{host}]" if ":" in host else host
            on_ready(f"http://{shown}:{port}/")
        priority.below_tick_thread()        # this thread serves; the kernel's is started
        server.run(sockets=[sock])
    finally:
        app.state.ui.hub.close()
        current = app.state.ui.net          # the editor may have replaced the network
        current.controller.stop()
        current.controller.join(10)
        if on_end is not None:
            on_end(current)
        if current is not net:
            current.close()
        sock.close()
        threading.excepthook = previous_hook
