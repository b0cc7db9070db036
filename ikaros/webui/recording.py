"""The record button's endpoint: ``GET /api/record`` says whether the running network is
being recorded; ``POST /api/record {"on": true|false}`` starts a recording of every output
into a new HDF5 file in the models folder, or ends it. A recording also ends when its
network does (the editor's apply, open and new build a new one)."""
from __future__ import annotations

import os
import time

from starlette.concurrency import run_in_threadpool
from starlette.requests import Request

from .server import ApiError, Json, _body, _query
from .snapshot import between_ticks


class RecordButton:
    """The state behind ``/api/record`` for one app."""

    def __init__(self, ui):
        self.ui = ui                # the WebUI: its current network and models folder
        self.recorder = None

    def _answer(self):
        recorder = self.recorder
        on = recorder is not None and not recorder.closed and recorder.net is self.ui.net
        return Json({"recording": on,
                           "file": os.path.basename(recorder.filename) if on else None,
                           "folder": self._folder()})

    def _folder(self) -> str | None:
        return self.ui.models_dir or self.ui.model_dir

    async def endpoint(self, request: Request):
        if request.method == "GET":
            _query(request)
            return self._answer()
        body = await _body(request, ("on",))
        if not isinstance(body["on"], bool):
            raise ApiError(400, '"on" must be true or false')
        current = self.recorder
        if current is not None and not current.closed:
            await run_in_threadpool(current.close)   # its network may be another one now
        self.recorder = None
        if body["on"]:
            self.recorder = await run_in_threadpool(self._start)
        return self._answer()

    def _start(self):
        from ..experiments.recording import Recorder
        folder = self._folder()
        if not folder:
            raise ApiError(409, "no models folder to record into (start ikaros with "
                                   "--models DIR)")
        net = self.ui.net
        if net.stopped:
            raise ApiError(409, "the run has ended; restart ikaros to record")
        stem = os.path.splitext(os.path.basename(net.filename or "model"))[0]
        name = f"{stem}-{time.strftime('%Y%m%d-%H%M%S')}"
        path, k = os.path.join(folder, name + ".h5"), 1
        while os.path.exists(path):         # never over an earlier recording
            k += 1
            path = os.path.join(folder, f"{name}-{k}.h5")
        try:
            return between_ticks(net, Recorder, net, path, command_line=["web UI"])
        except ImportError as e:
            raise ApiError(501, str(e)) from None
        except OSError as e:
            raise ApiError(500, str(e)) from None
