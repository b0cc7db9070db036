"""The OpenAPI 3.1 description of the web UI's HTTP API, served at ``/api/openapi.json``."""
from __future__ import annotations


def _json(schema: dict, description: str = "") -> dict:
    return {"description": description or "OK",
            "content": {"application/json": {"schema": schema}}}


_ERROR = {"$ref": "#/components/schemas/Error"}
_ERRORS = {"400": _json(_ERROR, "bad request: a bad field, type or value"),
           "401": _json(_ERROR, "a token is required"),
           "404": _json(_ERROR, "unknown path, module, buffer or parameter")}
_STATUS = {"$ref": "#/components/schemas/Status"}


def _body(schema: dict) -> dict:
    return {"required": True, "content": {"application/json": {"schema": schema}}}


def _get(summary: str, answer: dict, params: list | None = None) -> dict:
    op = {"summary": summary, "responses": {"200": _json(answer), **_ERRORS}}
    if params:
        op["parameters"] = params
    return {"get": op}


def _post(summary: str, body: dict, answer: dict) -> dict:
    return {"post": {"summary": summary, "requestBody": _body(body),
                     "responses": {"200": _json(answer), **_ERRORS,
                                   "415": _json(_ERROR, "the body is not JSON")}}}


def _q(name: str, description: str, schema: dict, required: bool = False) -> dict:
    return {"name": name, "in": "query", "required": required, "description": description,
            "schema": schema}


_VALUE = {"description": "a number, bool, string, or (nested) list of numbers; text is "
                         "read as in a model file"}


def openapi() -> dict:
    num = {"type": "number"}
    obj = {"type": "object"}
    paths = {
        "/api/network": _get("The model: groups, modules, connections and views",
                             {"$ref": "#/components/schemas/Network"}),
        "/api/classes": _get("Every module class: {name: class description}", obj),
        "/api/status": _get("Run state and timing figures", _STATUS),
        "/api/control": _post(
            "Change the run mode",
            {"type": "object", "required": ["state"], "additionalProperties": False,
             "properties": {"state": {"enum": ["stop", "pause", "step", "play",
                                               "realtime"]}}}, _STATUS),
        "/api/parameter": _post(
            "Set a module parameter (or one element of an array or matrix parameter)",
            {"type": "object", "required": ["path", "value"], "additionalProperties": False,
             "properties": {"path": {"type": "string", "example": "Arm.PID.gain"},
                            "value": _VALUE,
                            "x": {"type": "integer", "minimum": 0,
                                  "description": "column (or index)"},
                            "y": {"type": "integer", "minimum": 0, "description": "row"}}},
            {"type": "object", "properties": {"path": {"type": "string"}, "value": {}}}),
        "/api/command": _post(
            "Call a module's command(name, x, y, value)",
            {"type": "object", "required": ["module", "name"], "additionalProperties": False,
             "properties": {"module": {"type": "string"}, "name": {"type": "string"},
                            "x": num, "y": num, "value": {}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"}}}),
        "/api/module": _get("One module: parameters, inputs, outputs, descriptions",
                            {"$ref": "#/components/schemas/ModuleDetail"},
                            [_q("path", "the module's dotted path", {"type": "string"},
                                True)]),
        "/api/data": _get("One-off read of buffers as nested lists",
                          {"type": "object", "properties": {"tick": {"type": "integer"},
                                                            "data": obj}},
                          [_q("paths", "comma-separated buffer paths", {"type": "string"},
                              True)]),
        "/api/log": _get("Notifications since a sequence number",
                         {"type": "object", "properties": {
                             "next": {"type": "integer"},
                             "messages": {"type": "array", "items": {
                                 "$ref": "#/components/schemas/LogMessage"}}}},
                         [_q("since", "first sequence number wanted",
                             {"type": "integer", "minimum": 0})]),
        "/api/openapi.json": _get("This description", obj),
    }
    schemas = {
        "Error": {"type": "object", "required": ["error"],
                  "properties": {"error": {"type": "string"}}},
        "Status": {"type": "object", "properties": {
            "state": {"enum": ["stop", "pause", "step", "play", "realtime"]},
            "tick": {"type": "integer"}, "tick_duration": num, "time": num, "elapsed": num,
            "ticks_per_second": num, "actual_tick_duration": num, "lag": num, "lag_max": num,
            "lag_p99": num, "resyncs": {"type": "integer"}, "cpu_usage": num, "idle": num,
            "file": {"type": "string"}}},
        "Network": {"type": "object", "properties": {
            "file": {"type": "string"}, "name": {"type": "string"},
            "top": {"$ref": "#/components/schemas/Group"}}},
        "Group": {"type": "object", "properties": {
            "name": {"type": "string"}, "path": {"type": "string"},
            "groups": {"type": "array", "items": {"$ref": "#/components/schemas/Group"}},
            "modules": {"type": "array", "items": {"$ref": "#/components/schemas/Module"}},
            "views": {"type": "array", "items": {"$ref": "#/components/schemas/View"}},
            "connections": {"type": "array", "items": obj},
            "inputs": {"type": "array", "items": obj},
            "outputs": {"type": "array", "items": obj}}},
        "Module": {"type": "object", "properties": {
            "name": {"type": "string"}, "path": {"type": "string"},
            "class": {"type": "string"}, "outputs": {"type": "array", "items": obj},
            "inputs": {"type": "array", "items": obj},
            "parameters": {"type": "array", "items": obj}}},
        "ModuleDetail": {"type": "object", "properties": {
            "path": {"type": "string"}, "class": {"type": "string"},
            "description": {"type": "string"},
            "parameters": {"type": "array", "items": obj},
            "inputs": {"type": "array", "items": obj},
            "outputs": {"type": "array", "items": obj}, "view": {}}},
        "View": {"type": "object", "properties": {
            "name": {"type": "string"},
            "widgets": {"type": "array", "items": {"type": "object", "properties": {
                "class": {"type": "string"}, "x": num, "y": num, "width": num,
                "height": num}, "additionalProperties": True}}}},
        "LogMessage": {"type": "object", "properties": {
            "seq": {"type": "integer"}, "tick": {"type": "integer"},
            "level": {"type": "string"}, "module": {"type": "string"},
            "message": {"type": "string"}}},
    }
    return {
        "openapi": "3.1.0",
        "info": {"title": "ikaros web UI", "version": "1",
                 "description": "The HTTP part of the web UI protocol "
                                "(docs/webui-protocol.md). With a token, send it as "
                                "Authorization: Bearer TOKEN or ?token=TOKEN. Live data "
                                "comes over the WebSocket /api/ws."},
        "paths": paths,
        "components": {"schemas": schemas,
                       "securitySchemes": {"bearer": {"type": "http", "scheme": "bearer"},
                                           "query": {"type": "apiKey", "in": "query",
                                                     "name": "token"}}},
    }
