"""Read-only routes of the Ikaros 3 HTTP API, for researchers' scripts written for it
(docs/webui.md, "Ikaros 3's HTTP API"):

* ``GET /json/<path>``: ``{"path", "shape", "value"}`` of an output, input or parameter;
* ``GET /csv/<path>``: an output or input of rank 1 or 2 (or a number or array parameter)
  as CSV, one line per row.

``<path>`` is a dotted path as in ``/api/data``; as in Ikaros 3 it may start with ``.`` or
with the top group's name. The routes that change the run (``/play``, ``/control/...``)
are not taken over: Ikaros 3 answers them to GET, which any web page can send.

Each ``async def`` here is a route handler taking the ``WebUI`` and the request; the
routes are made in ``server.create_app``.
"""
from __future__ import annotations

import numpy as np
from starlette.responses import Response

from .requests import ApiError, Json, _query
from .snapshot import plain


def _path(ui, request) -> str:
    path = request.path_params["path"].strip().lstrip(".")
    top = ui.net.top.name
    return path[len(top) + 1:] if path.startswith(top + ".") else path


def _read(ui, path: str):
    """The value at path: a buffer, else a parameter (raises ApiError 404)."""
    net = ui.net
    try:
        return net.output(path)
    except KeyError:
        pass
    try:
        return net.parameter(path)
    except KeyError:
        raise ApiError(404, f'no output, input or parameter "{path}" in {net.top.name}') \
            from None


async def json_value(ui, request):
    _query(request)
    path = _path(ui, request)
    value = await ui._call(_read, ui, path)
    shape = list(np.shape(value)) if isinstance(value, (np.ndarray, list)) else []
    return Json({"path": path, "shape": shape, "value": plain(value)})


async def csv_value(ui, request):
    _query(request)
    path = _path(ui, request)
    value = await ui._call(_read, ui, path)
    if isinstance(value, (bool, str)):
        raise ApiError(422, f'"{path}" is not numeric: no CSV')
    array = np.asarray(value, dtype=float)
    if array.ndim > 2:
        raise ApiError(422, f'"{path}" has rank {array.ndim}: CSV holds rank 1 or 2')
    rows = np.atleast_2d(array) if array.size else np.zeros((0, 0))
    text = "".join(",".join(f"{x:.10g}" for x in row) + "\n" for row in rows)
    return Response(text, media_type="text/csv")
