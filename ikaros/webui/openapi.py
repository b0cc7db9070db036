"""The OpenAPI 3.1 description of the web UI's HTTP API, served at ``/api/openapi.json``."""
from __future__ import annotations

from .state import STATE_FILE_PATTERN


def _json(schema: dict, description: str = "") -> dict:
    return {"description": description or "OK",
            "content": {"application/json": {"schema": schema}}}


_ERROR = {"$ref": "#/components/schemas/Error"}
_ERRORS = {"400": _json(_ERROR, "bad request: a bad field, type or value"),
           "401": _json(_ERROR, "a token is required"),
           "404": _json(_ERROR, "unknown path, module, buffer or parameter")}
_STATUS = {"$ref": "#/components/schemas/Status"}
_NODE = {"$ref": "#/components/schemas/Node"}
_ROOT = {"$ref": "#/components/schemas/Root"}
_CHANGED = {"type": "object", "properties": {"ok": {"type": "boolean"},
                                             "file": {"type": "string"},
                                             "network": {"$ref": "#/components/schemas/"
                                                                 "Network"}}}


_RECORDING = {"type": "object", "properties": {
    "recording": {"type": "boolean"}, "file": {"type": ["string", "null"]},
    "folder": {"type": ["string", "null"]}, "outputs": {"type": "integer"},
    "values": {"type": "integer"}, "every": {"type": "integer"},
    "largest": {"type": "array", "items": {"type": "array"}}}}
_PATTERNS = {"type": "array", "items": {"type": "string"}}


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


def _post(summary: str, body: dict, answer: dict, **more: str) -> dict:
    responses = {"200": _json(answer), **_ERRORS,
                 "403": _json(_ERROR, "cross-origin"),
                 "413": _json(_ERROR, "the body is larger than the limit"),
                 "415": _json(_ERROR, "the body is not JSON")}
    responses.update({code: _json(_ERROR, text) for code, text in more.items()})
    return {"post": {"summary": summary, "requestBody": _body(body), "responses": responses}}


def _editor_post(summary: str, body: dict, answer: dict) -> dict:
    op = _post(summary, body, answer)
    op["post"]["responses"].update({
        "403": _json(_ERROR, "a file name outside the models folder, or cross-origin"),
        "409": _json(_ERROR, "another apply, open or new is under way"),
        "422": _json({"$ref": "#/components/schemas/ModelError"},
                     "not a valid model: the kernel's error and the element at fault")})
    return op


def _compat(summary: str, answer: dict, **more: dict) -> dict:
    """A read-only route of Ikaros 3's API (webui/compat.py)."""
    return {"get": {"summary": summary, "responses": {"200": answer, **_ERRORS, **more},
                    "parameters": [{"name": "path", "in": "path", "required": True,
                                    "description": "a dotted path; it may start with . or "
                                                   "the top group's name",
                                    "schema": {"type": "string"}}]}}


def _q(name: str, description: str, schema: dict, required: bool = False) -> dict:
    return {"name": name, "in": "query", "required": required, "description": description,
            "schema": schema}


_NUMBERS = {"$ref": "#/components/schemas/Numbers"}
_STATES = ["stop", "pause", "step", "play", "fastforward", "realtime"]
_VALUE = {"description": "a number, bool, string, or (nested) list of numbers; text is "
                         "read as in a model file",
          "anyOf": [{"type": "number"}, {"type": "boolean"}, {"type": "string"}, _NUMBERS]}
# what the server strips (Python's whitespace) must leave some text
_NONBLANK = {"type": "string", "pattern": r"[^\s\x1c-\x1f\x85\xa0\u1680\u2000-\u200a"
                                         r"\u2028\u2029\u202f\u205f\u3000]"}
# Characters XML allows (the server refuses the others, and lone surrogates cannot be saved)
_XML_TEXT = r"^[^\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]*$"
_XML_NAME = "^[A-Za-z_][A-Za-z0-9_.-]*$"
_INCLUDE_FILE = (r'^[^"?\s\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]'
                 r'[^"?\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]*$')
_COMMENT = r"^[^\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff-]*$"   # no "-"


_NODE_FIELDS = {
    "id": {"type": ["integer", "null"], "minimum": 0,
           "description": "given by GET /api/model; none on new nodes"},
    "file": {"type": ["string", "null"]},
    "line": {"type": ["integer", "null"], "minimum": 1}}


def _element(root: bool) -> dict:
    """An element node; the root is a <group> and may carry the comments outside it."""
    props = {
        **_NODE_FIELDS,
        "tag": {"const": "group"} if root else
        {"type": "string", "pattern": _XML_NAME, "description": "the element name"},
        "attrs": {"type": "object", "propertyNames": {"pattern": _XML_NAME},
                  "additionalProperties": {"anyOf": [{"type": "string", "pattern": _XML_TEXT},
                                                     {"type": "number"}]},
                  "description": "every attribute, in file order"},
        "text": {"type": ["string", "null"], "pattern": _XML_TEXT},
        "children": {"type": "array", "items": _NODE}}
    if root:
        props["outside"] = {
            "type": "object", "additionalProperties": False,
            "description": "comments before and after the root",
            "properties": {k: {"type": "array", "items": {"type": "string",
                                                          "pattern": _COMMENT}}
                           for k in ("before", "after")}}
    return {"type": "object", "required": ["tag"], "additionalProperties": False,
            "properties": props,
            "description": "a model tree: its root is a <group>" if root else "an element"}


_PROFILE = {"type": "object", "required": ["on", "modules"], "properties": {
    "on": {"type": "boolean"},
    "modules": {"type": "array", "items": {
        "type": "object", "required": ["module", "class", "count", "mean", "max", "total"],
        "properties": {"module": {"type": "string"}, "class": {"type": "string"},
                       "count": {"type": "integer"}, "mean": {"type": "number"},
                       "max": {"type": "number"}, "total": {"type": "number"}}}}}}


def openapi() -> dict:
    num = {"type": "number"}
    obj = {"type": "object"}
    paths = {
        "/api/network": _get("The model: groups, modules, connections and views",
                             {"$ref": "#/components/schemas/Network"}),
        "/api/classes": _get("Every module class: {name: class description}", obj),
        "/api/status": _get("Run state and timing figures", _STATUS),
        "/api/control": _post(
            "Change the run mode; \"stop\" ends the run (every module's stop() is called) "
            "and a later mode runs the model again from tick 0",
            {"type": "object", "required": ["state"], "additionalProperties": False,
             "properties": {"state": {"enum": _STATES}}}, _STATUS,
            **{"409": "the run has ended: apply, open or reload a model"}),
        "/api/parameter": _post(
            "Set a module parameter (or one element of an array or matrix parameter)",
            {"type": "object", "required": ["path", "value"], "additionalProperties": False,
             "properties": {"path": {**_NONBLANK, "example": "Arm.PID.gain"},
                            "value": _VALUE,
                            "x": {"type": "integer", "minimum": 0,
                                  "description": "column (or index)"},
                            "y": {"type": "integer", "minimum": 0, "description": "row"}}},
            {"type": "object", "properties": {"path": {"type": "string"}, "value": {}}},
            **{"403": "a file parameter naming a file outside the models folder, or "
                      "cross-origin",
               "422": "a value this parameter does not take (its type, range, or an "
                      "element outside it)"}),
        "/api/command": _post(
            "Call a module's command(name, x, y, value)",
            {"type": "object", "required": ["module", "name"], "additionalProperties": False,
             "properties": {"module": _NONBLANK, "name": _NONBLANK,
                            "x": num, "y": num, "value": {}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"}}},
            **{"422": "the module takes no commands, or the command failed"}),
        "/api/module": _get("One module: parameters, inputs, outputs, descriptions",
                            {"$ref": "#/components/schemas/ModuleDetail"},
                            [_q("path", "the module's dotted path", {"type": "string"},
                                True)]),
        "/api/data": _get("One-off read of buffers as nested lists",
                          {"type": "object", "properties": {"tick": {"type": "integer"},
                                                            "data": obj}},
                          [_q("paths", "comma-separated buffer paths", _NONBLANK, True)]),
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
                               "tree": _NODE,
                               "version": {"type": ["string", "null"],
                                           "description": "the version of the model's "
                                                          "file (null: not saved yet), "
                                                          "for /api/save"},
                               "error": {"$ref": "#/components/schemas/ModelError",
                                         "description": "only while the model the "
                                                        "server started with fails to "
                                                        "build: why, and where"}}}),
        "/api/apply": _editor_post(
            "Rebuild the network from an edited tree and run it from tick 0 (module state "
            "is reset); an invalid tree changes nothing (422)",
            {"type": "object", "required": ["tree"], "additionalProperties": False,
             "properties": {"tree": _ROOT, "state": {
                 "enum": ["pause", "step", "play", "fastforward", "realtime"],
                 "description": "the run state after the rebuild (default: as before)"}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"},
                                              "network": {"$ref": "#/components/schemas/"
                                                                  "Network"}}}),
        "/api/save": _editor_post(
            "Write the tree to the model's file, or save as a plain .ikg name in the models "
            "folder (does not rebuild); with a version, 409 (and the file's version now) "
            "when the file is at another one: another editor saved it since",
            {"type": "object", "required": ["tree"], "additionalProperties": False,
             "properties": {"tree": _ROOT, "filename": {"type": "string",
                                                        "example": "copy.ikg"},
                            "version": {"type": ["string", "null"],
                                        "description": "the version of the file the "
                                                       "edits were made from "
                                                       "(/api/model), null for none"}}},
            {"type": "object", "properties": {"ok": {"type": "boolean"},
                                              "file": {"type": "string"},
                                              "version": {"type": ["string", "null"]}}}),
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
             "properties": {"name": {"type": "string", "default": "Untitled",
                                     "pattern": "^[A-Za-z_][A-Za-z0-9_-]*$",
                                     "maxLength": 100}}}, _CHANGED),
        "/api/record": {**_get("Whether the running network is being recorded, and how many "
                               "values a tick a recording of the outputs matching only holds",
                               _RECORDING,
                               [_q("only", "glob patterns of output addresses, "
                                           "comma-separated (default: every output)",
                                   {"type": "string"})]),
                        **_post("Start recording the outputs matching only (every output "
                                "without it), every every-th tick, into a new HDF5 file in "
                                "the recordings folder (on: true), or end the recording "
                                "(on: false)",
                                {"type": "object", "required": ["on"],
                                 "additionalProperties": False,
                                 "properties": {"on": {"type": "boolean"},
                                                "format": {"enum": ["h5", "mcap"]},
                                                "only": _PATTERNS,
                                                "every": {"type": "integer", "minimum": 1}}},
                                _RECORDING,
                                **{"409": "no models folder to record into, or the run has "
                                          "ended"})},
        "/api/replay": {**_get("Whether a recording is replayed (ikaros --replay), its rows "
                               "and the row shown", _REPLAY),
                        **_post("Show row k of the recording (its tick number is in the "
                                "answer)", {"type": "object", "required": ["row"],
                                            "additionalProperties": False,
                                            "properties": {"row": {"type": "integer",
                                                                   "minimum": 0}}},
                                _REPLAY, **{"409": "not replaying a recording, or the run "
                                                   "has ended"})},
        "/api/openapi.json": _get("This description", obj),
        "/api/state": _post(
            "Save, load or reset the state of the model (or of one module or group): "
            "outputs, delay lines and the state the classes declare",
            {"type": "object", "required": ["action"], "additionalProperties": False,
             "properties": {
                 "action": {"enum": ["save", "load", "reset"]},
                 "filename": {"type": "string", "pattern": STATE_FILE_PATTERN,
                              "description": "a plain name in the models folder (default: "
                                             "the model's name with .state); not for reset"},
                 "scope": {"type": "string", "description": "a module or group path; "
                                                          "default: the whole network"}}},
            {"type": "object", "required": ["ok", "action", "tick", "scope"], "properties": {
                "ok": {"type": "boolean"}, "action": {"type": "string"},
                "tick": {"type": "integer"}, "scope": {"type": "string"},
                "file": {"type": "string"}, "item_count": {"type": "integer"}}},
            **{"403": "not a plain .state name in the models folder, or cross-origin",
               "422": "the file does not fit the network (item, type or shape named), or a "
                      "reset given a file name",
               "500": "the file can not be written"}),
        "/api/profiling": {**_get("Per-module time, most total time first", _PROFILE),
                           **_post("Switch the measuring of per-module time on or off",
                                   {"type": "object", "required": ["on"],
                                    "additionalProperties": False,
                                    "properties": {"on": {"type": "boolean"}}}, _PROFILE)},
        "/api/startup": _get("The build steps of the running network and their times",
                             {"type": "object", "required": ["steps", "total"],
                              "properties": {"total": num, "steps": {
                                  "type": "array", "items": {
                                      "type": "object", "required": ["step", "seconds"],
                                      "properties": {"step": {"type": "string"},
                                                     "seconds": num}}}}}),
        "/api/quit": _post("Stop the run (every module's stop is called) and end the server",
                           {"type": "object", "additionalProperties": False,
                            "properties": {}},
                           {"type": "object", "properties": {"ok": {"type": "boolean"}}},
                           **{"409": "the server was not started by ikaros (an app made "
                                     "with create_app only)"}),
        "/json/{path}": _compat("Ikaros 3's read of an output, input or parameter",
                                _json({"type": "object", "properties": {
                                    "path": {"type": "string"},
                                    "shape": {"type": "array", "items": {"type": "integer"}},
                                    "value": {}}})),
        "/csv/{path}": _compat("Ikaros 3's read of an output, input or number parameter as "
                               "CSV (rank 1 or 2)",
                               {"description": "one line per row",
                                "content": {"text/csv": {"schema": {"type": "string"}}}},
                               **{"422": _json(_ERROR, "not numeric, or rank above 2")}),
    }
    num_or_none = {"type": ["number", "null"]}
    schemas = {
        "Error": {"type": "object", "required": ["error"],
                  "properties": {"error": {"type": "string"}}},
        "Status": {"type": "object", "properties": {
            "state": {"enum": _STATES},
            "stop_tick": {"type": ["integer", "null"],
                          "description": "the tick the run pauses at (-s N), or null"},
            "tick": {"type": "integer"}, "tick_duration": num, "time": num, "elapsed": num,
            "ticks_per_second": num_or_none, "ticks_per_second_mean": num_or_none,
            "actual_tick_duration": num_or_none, "actual_tick_duration_mean": num_or_none,
            "lag": num, "lag_max": num,
            "lag_p99": num, "resyncs": {"type": "integer"}, "cpu_usage": num,
            "cpu_cores": {"type": "integer", "description": "the cores cpu_usage is a share "
                          "of (all of them together)"}, "idle": num,
            "file": {"type": "string"},
            "webui_req_int": {"type": "number", "description": "seconds between two data "
                              "snapshots at least (the model's setting of that name)"},
            "webui_log_buffer_limit": {"type": "integer", "description": "the messages "
                                       "kept for /api/log"},
            "rgb_quality": {"type": "integer", "description": "of JPEG colour images"},
            "gray_quality": {"type": "integer", "description": "of JPEG gray images"},
            "priority": {"type": ["object", "null"], "description": "what the run asked for "
                         "(priority, cpus, lock_memory), was granted and was refused; null "
                         "when it asked for nothing", "properties": {
                             "requested": {"type": "string"},
                             "tick_thread": {"type": ["string", "null"]},
                             "device_threads": {"type": "array", "items": {"type": "string"}},
                             "background_threads": {"type": "array",
                                                    "items": {"type": "string"}},
                             "cpus": {"type": ["array", "null"],
                                      "items": {"type": "integer"}},
                             "memory_locked": {"type": ["boolean", "null"]},
                             "refused": {"type": "array", "items": {"type": "string"}}}},
            "thread_pools": {"type": "object", "description": "the numerical libraries' "
                             "thread pools, limited while the run is in real time",
                             "properties": {
                                 "limit": {"type": ["integer", "null"]},
                                 "realtime": {"type": "boolean"},
                                 "error": {"type": "string"},
                                 "pools": {"type": "array", "items": obj}}}}},
        "Network": {"type": "object", "properties": {
            "file": {"type": "string"}, "name": {"type": "string"},
            "top": {"$ref": "#/components/schemas/Group"},
            "build_error": {"type": "string", "description": "only while the model the "
                            "server started with fails to build (an empty network of its "
                            "name runs)"}}},
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
        "Numbers": {"type": "array", "items": {"anyOf": [num, _NUMBERS]},
                    "description": "a (nested) list of numbers"},
        "Root": _element(root=True),
        "Node": {"anyOf": [{"$ref": "#/components/schemas/Element"},
                           {"$ref": "#/components/schemas/Comment"},
                           {"$ref": "#/components/schemas/Include"}]},
        "Element": _element(root=False),
        "Comment": {"type": "object", "required": ["tag"], "additionalProperties": False,
                    "properties": {**_NODE_FIELDS, "tag": {"const": "#comment"},
                                   "text": {"type": ["string", "null"],
                                            "pattern": _COMMENT}}},
        "Include": {"type": "object", "required": ["tag", "attrs"],
                    "additionalProperties": False, "properties": {
                        **_NODE_FIELDS, "tag": {"const": "#include"},
                        "attrs": {"type": "object", "required": ["file"],
                                  "additionalProperties": False, "properties": {
                                      "file": {"type": "string",
                                               "pattern": _INCLUDE_FILE}}},
                        "children": {"type": "array", "items": _NODE,
                                     "description": "the included elements (read-only)"}}},
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
