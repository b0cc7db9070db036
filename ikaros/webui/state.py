"""The run tools of the web UI's HTTP API: the model's state (save, load, reset), the
profiling window, the start-up steps and quit (docs/webui-protocol.md, "Run tools").

Each ``async def`` here is a route handler taking the ``WebUI`` and the request; the
routes are made in ``server.create_app``.
"""
from __future__ import annotations

import os
import re

from starlette.concurrency import run_in_threadpool

from ..kernel import state as kernel_state
from .requests import ApiError, Json, _body, _query
from .snapshot import between_ticks

# a plain name in the models folder: no separators, not hidden, ending in .state
STATE_FILE = re.compile(r"[^\W][\w\-. &=+,()]*\.state\Z")
STATE_FILE_PATTERN = r"^[A-Za-z0-9_][A-Za-z0-9_. &=+,()-]*\.state$"   # OpenAPI
STATE_ACTIONS = ("save", "load", "reset")


def default_state_file(net) -> str:
    """``model.state`` (in the models folder, as ``model.ikg`` is)."""
    return os.path.basename(net.state_file())


def _state_path(ui, name: str) -> str:
    if not isinstance(name, str) or not STATE_FILE.match(name) or ".." in name:
        raise ApiError(403, f'"{str(name)[:80]}" is not a plain state file name in the models '
                            f'folder (letters, digits, spaces and _ - . & = + , ( ), ending in '
                            f'.state)')
    return os.path.join(ui._folder(), name)


def _scope(ui, scope) -> str | None:
    if scope is None or scope == "":
        return None
    if not isinstance(scope, str):
        raise ApiError(400, '"scope" must be a module or group path')
    net = ui.net
    if not any(p == scope or p.startswith(scope + ".") for p in net.modules):
        raise ApiError(404, f'no module or group "{scope}" with modules in {net.top.name}')
    return scope


async def state(ui, request):
    """POST /api/state {"action": "save" | "load" | "reset", "filename", "scope"}."""
    body = await _body(request, ("action",), ("filename", "scope"))
    action = body["action"]
    if action not in STATE_ACTIONS:
        raise ApiError(400, f'"action" must be one of {", ".join(STATE_ACTIONS)}')
    scope = _scope(ui, body.get("scope"))
    if action == "reset":
        if "filename" in body:
            raise ApiError(422, 'reset takes no "filename"')
        path = None
    else:
        path = _state_path(ui, body.get("filename") or default_state_file(ui.net))
        if action == "load" and not os.path.isfile(path):
            raise ApiError(404, f'no state file "{os.path.basename(path)}" in the models '
                                f'folder')
    net = ui.net

    def run():
        if action == "save":
            return kernel_state.save(net, path, scope)
        if action == "load":
            return kernel_state.load(net, path, scope)
        kernel_state.reset(net, scope)
        return {"scope": scope or "network"}
    try:
        header = await run_in_threadpool(between_ticks, net, run)
    except kernel_state.StateError as e:
        raise ApiError(422, str(e)) from None
    except OSError as e:
        raise ApiError(500, f"cannot write {os.path.basename(path)}: {e.strerror or e}") \
            from None
    ui.hub.poke()
    answer = {"ok": True, "action": action, "tick": net.tick,
              "scope": scope or "network"}
    if path:
        answer["file"] = os.path.basename(path)
        answer["item_count"] = header["item_count"]
    return Json(answer)


def _profile(net) -> dict:
    rows = [dict(m, total=m["count"] * m["mean"]) for m in net.module_figures()]
    rows.sort(key=lambda m: (-m["total"], m["module"]))
    return {"on": bool(net.profiling), "modules": rows}


async def profiling(ui, request):
    """GET /api/profiling: per-module time, most time first. POST {"on": bool} switches
    the measuring on or off."""
    if request.method == "POST":
        body = await _body(request, ("on",))
        if not isinstance(body["on"], bool):
            raise ApiError(400, '"on" must be true or false')
        net = ui.net

        def switch():
            net.profiling = body["on"]
        await run_in_threadpool(between_ticks, net, switch)
    else:
        _query(request)
    return Json(await run_in_threadpool(between_ticks, ui.net, _profile, ui.net))


async def startup(ui, request):
    """GET /api/startup: the build steps of the running network and their times."""
    _query(request)
    steps = ui.net.startup.as_list()
    return Json({"steps": steps, "total": sum(s["seconds"] for s in steps)})


async def quit_(ui, request):
    """POST /api/quit {}: stop the run (every module's stop is called) and end the server."""
    await _body(request, ())
    if ui.on_quit is None:
        raise ApiError(409, "this server was not started by ikaros and does not quit")
    ui.on_quit()
    return Json({"ok": True})
