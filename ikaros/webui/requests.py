"""Reading and answering the API's requests: the error a route raises (``ApiError``), the
JSON response, and the checked query string and JSON body. The server and its route files
(compat, recording, state) use them."""
from __future__ import annotations

import json

from starlette.requests import Request
from starlette.responses import JSONResponse

from .guards import MAX_JSON_DEPTH, json_depth
from .snapshot import plain


class ApiError(Exception):
    """A request that can not be served: answered with ``{"error": message}``."""

    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status = status
        self.message = message


class Json(JSONResponse):
    def render(self, content) -> bytes:
        # a lone surrogate sent by a client and quoted back stays a JSON escape (\ud800)
        return json.dumps(plain(content), ensure_ascii=False, allow_nan=False,
                          separators=(",", ":")).encode("utf-8", "backslashreplace")


def _error(status: int, message: str, headers: dict | None = None) -> Json:
    return Json({"error": message}, status_code=status, headers=headers)


def _reject_constant(name):
    raise ValueError(f"{name} is not a JSON number")


def _loads(text):
    if json_depth(text) > MAX_JSON_DEPTH:       # before the decoder's recursion can overflow
        raise ValueError(f"arrays and objects nest deeper than {MAX_JSON_DEPTH} levels")
    return json.loads(text, parse_constant=_reject_constant)


def _query(request: Request, allowed: tuple = ()) -> dict:
    params = {}
    for key, value in request.query_params.multi_items():
        if key == "token":
            continue
        if key not in allowed:
            raise ApiError(400, f'unknown query parameter "{key}"' +
                           (f" (expected: {', '.join(allowed)})" if allowed else
                            " (this endpoint takes none)"))
        if key in params:
            raise ApiError(400, f'query parameter "{key}" given more than once')
        params[key] = value
    return params


async def _body(request: Request, required: tuple, optional: tuple = ()) -> dict:
    _query(request)
    ctype = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if ctype != "application/json":
        raise ApiError(415, "the body must be JSON (Content-Type: application/json)")
    raw = await request.body()
    try:
        body = _loads(raw.decode("utf-8"))
    except (ValueError, UnicodeDecodeError) as e:
        raise ApiError(400, f"the body is not valid JSON: {e}") from None
    if not isinstance(body, dict):
        raise ApiError(400, "the body must be a JSON object")
    for key in body:
        if key not in required and key not in optional:
            raise ApiError(400, f'unknown field "{key}" (expected: '
                                f'{", ".join(required + optional)})')
    for key in required:
        if key not in body:
            raise ApiError(400, f'missing field "{key}"')
    return body
