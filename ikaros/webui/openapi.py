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
_NODE = {"$ref": "#/components/schemas/Node"}
_CHANGED = {"type": "object", "properties": {"ok": {"type": "boolean"},
                                             "file": {"type": "string"},
                                             "network": {"$ref": "#/components/schemas/"
                                                                 "Network"}}}


_RECORDING = {"type": "object", "properties": {
    "recording": {"type": "boolean"}, "file": {"type": ["string", "null"]},
    "folder": {"type": ["string", "null"]}}}


_REPLAY = {"type": "object", "properties": {
    "replay": {"type": "boolean"}, "file": {"type": "string"}, "rows": {"type": "integer"},
    "row": {"type": "integer"}, "tick": {"type": ["integer", "null"]}}}


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


def _editor_post(summary: str, body: dict, answer: dict) -> dict:
    op = _post(summary, body, answer)
    op["post"]["responses"].update({
        "403": _json(_ERROR, "a file name outside the models folder, or cross-origin"),
        "409": _json(_ERROR, "another apply, open or new is under way"),
        "422": _json({"$ref": "#/components/schemas/ModelError"},
                     "not a valid model: the kernel's error and the element at fault")})
    return op


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
        "/api/model": _get("The model tree of the running network (for the editor)",
                           {"type": "object", "properties": {
                               "file": {"type": "string"}, "folder": {"type": "string"},
                               "tree": _NODE}}),
        "/api/apply": _editor_post(
            "Rebuild the network from an edited tree and run it from tick 0 (module state "
            "is reset); an invalid tree changes nothing (422)",
            {"type": "object", "required": ["tree"], "additionalProperties": False,
             "properties": {"tree": _NODE, "state": {
                 "enum": ["pause", "step", "play", "realtime"],
                 "description": "the run state after the rebuild (default: as before)"}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"},
                                              "network": {"$ref": "#/components/schemas/"
                                                                  "Network"}}}),
        "/api/save": _editor_post(
            "Write the tree to the model's file, or save as a plain .ikg name in the models "
            "folder (does not rebuild)",
            {"type": "object", "required": ["tree"], "additionalProperties": False,
             "properties": {"tree": _NODE, "filename": {"type": "string",
                                                        "example": "copy.ikg"}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"},
                                              "file": {"type": "string"}}}),
        "/api/files": _get("The .ikg models in the models folder",
                           {"type": "object", "properties": {
                               "folder": {"type": "string"},
                               "files": {"type": "array", "items": {"type": "string"}}}}),
        "/api/open": _editor_post(
            "Load and build another model of the models folder (paused); an invalid model "
            "changes nothing (422)",
            {"type": "object", "required": ["filename"], "additionalProperties": False,
             "properties": {"filename": {"type": "string"}}}, _CHANGED),
        "/api/new": _editor_post(
            "A new empty model (one group) in the models folder, not yet saved (paused)",
            {"type": "object", "additionalProperties": False,
             "properties": {"name": {"type": "string", "default": "Untitled"}}}, _CHANGED),
        "/api/record": {**_get("Whether the running network is being recorded", _RECORDING),
                        **_post("Start recording every output into a new HDF5 file in the "
                                "models folder (on: true), or end the recording (on: false)",
                                {"type": "object", "required": ["on"],
                                 "additionalProperties": False,
                                 "properties": {"on": {"type": "boolean"}}}, _RECORDING)},
        "/api/replay": {**_get("Whether a recording is replayed (ikaros --replay), its rows "
                               "and the row shown", _REPLAY),
                        **_post("Show row k of the recording (its tick number is in the "
                                "answer)", {"type": "object", "required": ["row"],
                                            "additionalProperties": False,
                                            "properties": {"row": {"type": "integer",
                                                                   "minimum": 0}}},
                                _REPLAY)},
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
        "Node": {"type": "object", "required": ["tag"], "additionalProperties": False,
                 "properties": {
                     "id": {"type": ["integer", "null"], "minimum": 0,
                            "description": "given by GET /api/model; none on new nodes"},
                     "tag": {"type": "string",
                             "description": "an element name, #comment or #include"},
                     "attrs": {"type": "object", "additionalProperties": {"type": "string"},
                               "description": "every attribute, in file order"},
                     "text": {"type": ["string", "null"]},
                     "children": {"type": "array", "items": _NODE},
                     "file": {"type": ["string", "null"]},
                     "line": {"type": ["integer", "null"]}}},
        "ModelError": {"type": "object", "required": ["error"], "properties": {
            "error": {"type": "string"},
            "node": {"type": ["integer", "null"], "description": "id of the element at fault"},
            "path": {"type": ["array", "null"], "items": {"type": "integer"},
                     "description": "child indices from the root to the element at fault"}}},
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
