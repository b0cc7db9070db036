"""Recordings in the web UI. The record button's endpoint: ``GET /api/record`` says whether
the running network is being recorded, and how many values a recording of the outputs
matching ``?only=`` (glob patterns, comma-separated; every output without it) holds per tick;
``POST /api/record {"on": true|false}`` starts a recording of those outputs (``"only"``,
every ``"every"``-th tick) into a new HDF5 file (an MCAP file of ROS 2 messages with
``"format": "mcap"``) in the user-data folder (``ikaros -u DIR``,
else ``recordings`` in the user's data folder: never the models folder, which may be a
source tree), or ends it. A recording that cannot start leaves no folder it made behind. A recording also ends when its network does (the editor's apply,
open and new build a new one). And the replay bar's endpoint, ``/api/replay``, for
``ikaros --replay``."""
from __future__ import annotations

import math
import os
import time

import platformdirs
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request

from ..experiments.reading import open_file
from ..experiments.recorders import open_recorder
from ..experiments.signals import select_outputs
from .requests import ApiError, Json, _body, _query
from .snapshot import between_ticks


FORMATS = ("h5", "mcap")
LARGEST = 5         # the biggest outputs of a selection, named in GET /api/record


def _patterns(value, where: str) -> list[str] | None:
    """Glob patterns of output addresses: a list of strings, or one string of them
    separated by commas; None (every output) when empty."""
    if value is None:
        return None
    if isinstance(value, str):
        value = value.split(",")
    if not isinstance(value, list) or not all(isinstance(p, str) for p in value):
        raise ApiError(400, f'{where} must be glob patterns of output addresses, such as '
                            f'["Arm.*", "Gain.OUTPUT"]')
    patterns = [p.strip() for p in value if p.strip()]
    return patterns or None


def recordings_folder(user_data: str | None) -> str:
    """Where the record button writes: the user-data folder (``-u DIR``), else
    ``recordings`` in the user's data folder (``~/.local/share/ikaros/recordings`` on Linux,
    ``$XDG_DATA_HOME/ikaros/recordings`` when that is set)."""
    if user_data:
        return os.path.abspath(user_data)
    return os.path.join(platformdirs.user_data_dir("ikaros"), "recordings")


class RecordButton:
    """The state behind ``/api/record`` for one app."""

    def __init__(self, ui):
        self.ui = ui                # the WebUI: its current network and models folder
        self.recorder = None

    def _answer(self, only: list[str] | None = None):
        recorder = self.recorder
        on = recorder is not None and not recorder.closed and recorder.failure is None \
            and recorder.net is self.ui.net
        folder = os.path.dirname(recorder.filename) if on else self._folder()
        answer = {"recording": on, "file": os.path.basename(recorder.filename) if on else None,
                  "folder": folder}
        if on:          # what it records
            signals = recorder.signals
            answer["every"] = recorder.every
        else:           # what a recording of ``only`` would
            try:
                signals = select_outputs(self.ui.net, only)[0]
            except ValueError as e:         # a pattern that matches no output
                raise ApiError(404, str(e)) from None
        sizes = sorted(((s.stop - s.start, s.name) for s in signals), reverse=True)
        answer.update(outputs=len(signals), values=sum(n for n, _ in sizes),
                      largest=[[path, n] for n, path in sizes[:LARGEST]])
        return Json(answer)

    def _folder(self) -> str:
        return recordings_folder(getattr(self.ui.net, "user_data", None))

    async def endpoint(self, request: Request):
        if request.method == "GET":
            query = _query(request, ("only",))
            return await run_in_threadpool(self._answer,
                                           _patterns(query.get("only"), '"only"'))
        body = await _body(request, ("on",), ("format", "only", "every"))
        if not isinstance(body["on"], bool):
            raise ApiError(400, '"on" must be true or false')
        kind = body.get("format", "h5")
        if kind not in FORMATS:
            raise ApiError(400, f'"format" must be {" or ".join(FORMATS)}')
        only = _patterns(body.get("only"), '"only"')
        every = body.get("every", 1)
        if isinstance(every, bool) or not isinstance(every, (int, float)) or \
                not (math.isfinite(every) and every >= 1 and every == int(every)):
            raise ApiError(400, '"every" must be a whole number of ticks >= 1')
        every = int(every)
        current = self.recorder
        if current is not None and not current.closed:
            # between its network's ticks (that network may be another one now)
            await run_in_threadpool(between_ticks, current.net, current.close)
        self.recorder = None
        if body["on"]:
            self.recorder = await run_in_threadpool(self._start, "." + kind, only, every)
        return await run_in_threadpool(self._answer)

    def _start(self, extension: str, only: list[str] | None = None, every: int = 1):
        folder = self._folder()
        net = self.ui.net
        if net.stopped:
            raise ApiError(409, "the run has ended; restart ikaros to record")
        try:
            select_outputs(net, only)
        except ValueError as e:
            raise ApiError(404, str(e)) from None
        made = not os.path.isdir(folder)
        try:
            os.makedirs(folder, exist_ok=True)
        except OSError as e:
            raise ApiError(500, f"cannot make the recordings folder {folder}: "
                                f"{e.strerror or e}") from None
        try:
            return self._open(net, folder, extension, only, every)
        except BaseException:
            if made:                        # the folder it made for nothing
                _remove_if_empty(folder)
            raise

    @staticmethod
    def _open(net, folder: str, extension: str, only: list[str] | None, every: int):
        stem = os.path.splitext(os.path.basename(net.filename or "model"))[0]
        name = f"{stem}-{time.strftime('%Y%m%d-%H%M%S')}"
        path, k = os.path.join(folder, name + extension), 1
        while os.path.exists(path):         # never over an earlier recording
            k += 1
            path = os.path.join(folder, f"{name}-{k}{extension}")
        try:
            return between_ticks(net, open_recorder, net, path, only=only, every=every,
                                 command_line=["web UI"])
        except ImportError as e:
            raise ApiError(501, str(e)) from None
        except OSError as e:
            raise ApiError(500, str(e)) from None


def _remove_if_empty(folder: str) -> None:
    try:
        os.rmdir(folder)                    # only when empty
    except OSError:
        pass


class ReplayBar:
    """``GET /api/replay``: whether the network replays a recording (``ikaros --replay``),
    its rows and the row shown; ``POST /api/replay {"row": k}`` shows row k (the Replay
    modules seek to it and one tick runs)."""

    def __init__(self, ui):
        self.ui = ui
        self._ticks: tuple[str, list] | None = None     # (recording, its tick numbers)

    def _recorded_ticks(self, path: str) -> list:
        if self._ticks is None or self._ticks[0] != path:
            with open_file(path) as f:
                self._ticks = (path, [int(t) for t in f.read("tick", 0, f.rows)])
        return self._ticks[1]

    def _replays(self) -> list:
        return [inst for inst in self.ui.net.modules.values() if inst.entry.name == "Replay"]

    def _answer(self):
        path = getattr(self.ui.net, "replayed", None)
        if path is None:
            return Json({"replay": False})
        ticks = self._recorded_ticks(path)
        replays = self._replays()
        row = replays[0].module.row if replays else -1
        return Json({"replay": True, "file": os.path.basename(path), "rows": len(ticks),
                     "row": row, "tick": ticks[row] if 0 <= row < len(ticks) else None})

    async def endpoint(self, request: Request):
        if request.method == "GET":
            _query(request)
            return await run_in_threadpool(self._answer)
        body = await _body(request, ("row",))
        path = getattr(self.ui.net, "replayed", None)
        if path is None:
            raise ApiError(409, "not replaying a recording (start ikaros with --replay)")
        rows = len(await run_in_threadpool(self._recorded_ticks, path))
        row = body["row"]
        if not isinstance(row, int) or isinstance(row, bool) or not 0 <= row < rows:
            raise ApiError(400, f'"row" must be a whole number from 0 to {rows - 1}')
        if self.ui.net.stopped:
            raise ApiError(409, "the run has ended; restart ikaros to replay again")
        await run_in_threadpool(self._show, row)
        return await run_in_threadpool(self._answer)

    def _show(self, row: int) -> None:
        net = self.ui.net

        def seek():
            for inst in self._replays():
                net.command(inst.path, "seek", x=row)
        between_ticks(net, seek)
        ctrl = net.controller
        if not ctrl.running:
            net.step()
            return
        if ctrl.state in ("play", "realtime"):
            return              # the next tick shows it
        done = net.tick
        ctrl.step()
        deadline = time.monotonic() + 2
        while net.tick == done and time.monotonic() < deadline:
            time.sleep(0.005)
