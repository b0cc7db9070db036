"""The model as the web UI sees it: groups, modules, connections and views as JSON.

Views are normalised from both file forms: an Ikaros 2 ``<view name>`` holding widget
elements (``<bar-graph .../>`` or ``<object class="BarGraph" .../>``) and Ikaros 3
``<widget class=...>`` elements (``_x``/``_y`` become ``x``/``y``; ``<widget>`` elements
placed directly in a group form one view). Widget class names become the kebab-case names
of the widget table. Data sources and parameters are resolved to full dotted paths from the
top group, kept beside the attributes as written (``source`` -> ``source_path``).
"""
from __future__ import annotations

import os
import re
from urllib.parse import quote

import numpy as np

from ..kernel.tree import Group, ModuleInstance, find_component
from .snapshot import plain

WIDGETS = (
    "bar-graph", "plot", "table", "grid", "heat-map", "image", "marker", "path", "trace",
    "text", "rectangle", "button", "switch", "slider-horizontal", "slider-vertical",
    "drop-down-menu", "joystick", "color-picker", "canvas3d", "surface-plot", "scatter-plot",
    "histogram", "boxplot", "polar-plot", "vector-field", "event-raster", "sequence-grid",
    "key-points", "epi-head", "target-boxes", "navigation-hud", "pan-tilt-hud",
    "world2dview", "world3dview", "ringworldview", "canvas", "graph", "control",
)
_BY_KEY = {w.replace("-", ""): w for w in WIDGETS}

# Attributes that name a data source (besides ``source`` and every ``*_source`` /
# ``*Source``): the Ikaros 2 colour planes of a grid, the 3-D view's matrix, a
# drop-down menu's list.
SOURCE_ATTRS = {"red", "green", "blue", "matrix", "list_parameter"}
GEOMETRY = ("x", "y", "width", "height")
DEFAULT_SIZE = 200
DEFAULT_GAP = 20
DEFAULT_COLUMNS = 3
DEFAULT_LIMIT = 24        # plots in a default view


def widget_class(name: str) -> str:
    """``BarGraph``, ``bar_graph``, ``bar-graph`` -> ``bar-graph``."""
    key = re.sub(r"[-_\s]", "", name).lower()
    if key in _BY_KEY:
        return _BY_KEY[key]
    kebab = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "-", name.strip())
    return re.sub(r"[_\s]+", "-", kebab).lower()


def is_source_attr(key: str) -> bool:
    return key == "source" or key.endswith("_source") or key.endswith("Source") or \
        key in SOURCE_ATTRS


def is_parameter_attr(key: str) -> bool:
    return key == "parameter" or key.endswith("_parameter") and key != "list_parameter" or \
        key.endswith("Parameter")


def _number(text, default):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return default
    if not np.isfinite(v):
        return default
    return int(v) if v == int(v) else v


# --- path resolution ---------------------------------------------------------------------

def _split(path: str) -> tuple[str, str]:
    comp, _, name = path.strip().rpartition(".")
    return comp, name


def resolve_source(net, base, text: str, depth: int = 0) -> str | None:
    """The full path of the buffer a widget source names, relative to ``base`` (a group,
    or a module for a class's own view), or None."""
    if not text or depth > 16:
        return None
    text = text.strip()
    text = re.sub(r"\[.*\]$", "", text)        # a selector is the widget's business
    text = text.split(":")[0].strip()            # an Ikaros 2 ":format" suffix
    if isinstance(base, ModuleInstance):
        found = _buffer(net, base, text)
        if found:
            return found
        base = base.parent
    comp_path, name = _split(text)
    if not name:
        return None
    comp = base if comp_path == "" else find_component(base, comp_path)
    if comp is None:
        return None
    if isinstance(comp, ModuleInstance):
        return _buffer(net, comp, name)
    if isinstance(comp, Group):
        for decl in comp.outputs:                # group outputs: aliases or ports
            if decl.get("name") != name:
                continue
            if decl.get("source"):
                return resolve_source(net, comp, decl.get("source"), depth + 1)
            for conn in connections(comp):
                if conn.get("target") == name and conn.get("source"):
                    return resolve_source(net, comp, conn.get("source"), depth + 1)
    return None


def _buffer(net, inst: ModuleInstance, name: str) -> str | None:
    path = f"{inst.path}.{name}" if name else None
    if path is None:
        return None
    try:
        net.buffer_array(path)
    except KeyError:
        return None
    return path


def resolve_parameter(net, base, text: str) -> str | None:
    """The full path of the module parameter a widget names, relative to ``base``, through
    a group's ``<parameter name target>`` renamings where needed; or None."""
    if not text:
        return None
    text = text.strip()
    if isinstance(base, ModuleInstance):
        if text in base.values:
            return f"{base.path}.{text}"
        base = base.parent
    comp_path, name = _split(text)
    comp = base if comp_path == "" else find_component(base, comp_path)
    if isinstance(comp, ModuleInstance):
        return f"{comp.path}.{name}" if name in comp.values else None
    if isinstance(comp, Group):
        for g in comp.chain():
            for r in g.renamings:
                if r.get("name") != name:
                    continue
                target = r.get("target", "")
                t_comp, t_name = _split(target)
                if t_comp:
                    m = find_component(g, t_comp)
                    if isinstance(m, ModuleInstance) and t_name in m.values:
                        return f"{m.path}.{t_name}"
                else:
                    for m in g.modules():
                        if t_name in m.values:
                            return f"{m.path}.{t_name}"
    return None


# --- views -------------------------------------------------------------------------------

def widget_json(net, base, node) -> dict:
    """One widget element as JSON: class, geometry as numbers, every other attribute as a
    string, plus resolved ``*_path`` attributes for sources and parameters."""
    attrs = dict(node.attrs)
    if node.tag in ("widget", "object"):
        cls = attrs.pop("class", "") or node.tag
    else:
        cls = node.tag
        attrs.pop("class", None)
    for a in ("x", "y"):
        if f"_{a}" in attrs:
            v = attrs.pop(f"_{a}")
            attrs.setdefault(a, v)
    w = {"class": widget_class(cls),
         "x": _number(attrs.pop("x", 0), 0), "y": _number(attrs.pop("y", 0), 0),
         "width": _number(attrs.pop("width", DEFAULT_SIZE), DEFAULT_SIZE),
         "height": _number(attrs.pop("height", DEFAULT_SIZE), DEFAULT_SIZE)}
    extra = {}
    for key, value in attrs.items():
        w[key] = str(value)
        if is_source_attr(key):
            extra[f"{key}_path"] = resolve_source(net, base, str(value))
        elif is_parameter_attr(key):
            extra[f"{key}_path"] = resolve_parameter(net, base, str(value))
    for key in ("command", "commandUp", "release_command"):
        if key in attrs:
            module, name = resolve_command(base, attrs[key], attrs.get("module"))
            extra[f"{key}_module"], extra[f"{key}_name"] = module, name
    if "file" in attrs:
        extra["file_url"] = file_urls(net, node, attrs["file"])
    for key, value in extra.items():
        w.setdefault(key, value)
    return w


def resolve_command(base, text: str, module: str | None) -> tuple[str | None, str]:
    """(full path of the module, command name) of a widget's command: ``command="reset"``
    with ``module="M"``, or ``command="M.reset"``."""
    text = (text or "").strip()
    if module:
        comp_text, name = module.strip(), text
    else:
        comp_text, _, name = text.rpartition(".")
    if isinstance(base, ModuleInstance) and comp_text in ("", base.name):
        return base.path, name
    group = base.parent if isinstance(base, ModuleInstance) else base
    comp = find_component(group, comp_text) if comp_text else None
    return (comp.path if isinstance(comp, ModuleInstance) else None), name


def file_urls(net, node, text: str) -> str | None:
    """``/files/...`` URLs of an image widget's comma-separated files (relative to the file
    the widget is written in), or None when one is outside the model's folder."""
    if not net.filename:
        return None
    root = os.path.dirname(os.path.abspath(net.filename))
    here = os.path.dirname(os.path.abspath(node.file or net.filename))
    urls = []
    for name in text.split(","):
        name = name.strip()
        if not name:
            continue
        rel = os.path.relpath(os.path.normpath(os.path.join(here, name)), root)
        if rel.startswith("..") or os.path.isabs(rel):
            return None
        urls.append("/files/" + "/".join(quote(p) for p in rel.split(os.sep)))
    return ",".join(urls)


def view_json(net, base, node) -> dict:
    """An Ikaros 2/3 ``<view>`` element as ``{"name", "widgets"}``."""
    widgets = [widget_json(net, base, child) for child in node.elements()]
    return {"name": node.get("name") or node.get("title") or "View", "widgets": widgets}


def group_views(net, group: Group) -> list[dict]:
    """The views of a group as written, or one default view."""
    views, loose = [], []
    for node in group.views:
        if node.tag == "widget":
            loose.append(node)
        else:
            views.append(view_json(net, group, node))
    if loose:
        views.append({"name": group.name,
                      "widgets": [widget_json(net, group, n) for n in loose]})
    return views or [default_view(net, group)]


def default_view(net, group: Group) -> dict:
    """One plot per output of the group's modules, three per row, 200 x 200 px, 20 px apart;
    a group without modules of its own shows those of its subgroups, nearest first, so the
    view is never blank. At most DEFAULT_LIMIT plots."""
    widgets = []
    level = [("", group)]
    while level and len(widgets) < DEFAULT_LIMIT:
        deeper = []
        for prefix, g in level:
            for comp in g.children.values():
                if not isinstance(comp, ModuleInstance):
                    deeper.append((f"{prefix}{comp.name}.", comp))
                    continue
                for name, _ in module_ports(net, comp)[1]:
                    if len(widgets) == DEFAULT_LIMIT:
                        break
                    i = len(widgets)
                    source = f"{prefix}{comp.name}.{name}"
                    widgets.append({
                        "class": "plot",
                        "x": DEFAULT_GAP + (i % DEFAULT_COLUMNS) * (DEFAULT_SIZE + DEFAULT_GAP),
                        "y": DEFAULT_GAP + (i // DEFAULT_COLUMNS) * (DEFAULT_SIZE + DEFAULT_GAP),
                        "width": DEFAULT_SIZE, "height": DEFAULT_SIZE, "title": source,
                        "source": source, "source_path": _buffer(net, comp, name)})
        if widgets:         # the nearest level that has outputs is the view
            break
        level = deeper
    return {"name": group.name, "widgets": widgets, "default": True}


# --- modules and groups ------------------------------------------------------------------

def module_ports(net, inst: ModuleInstance) -> tuple[list, list]:
    """([(input name, spec)], [(output name, spec)]) of a module, including ports added in
    ``configure``."""
    ins, outs = net.ports(inst.path)
    return [(s.name, s) for s in ins], [(s.name, s) for s in outs]


def _shape(net, path: str) -> list[int]:
    try:
        return list(net.buffer_array(path).shape)
    except KeyError:
        return []


def _value(net, inst: ModuleInstance, name: str):
    try:
        return plain(net.parameter(f"{inst.path}.{name}"))
    except KeyError:
        return None


def module_json(net, inst: ModuleInstance) -> dict:
    ins, outs = module_ports(net, inst)
    params = []
    for spec in inst.module.description.parameters:
        if spec.name not in inst.values:
            continue
        params.append({"name": spec.name, "type": spec.type,
                       "value": _value(net, inst, spec.name), "options": list(spec.options)})
    return {"name": inst.name, "path": inst.path, "class": inst.entry.name,
            "outputs": [{"name": n, "shape": _shape(net, f"{inst.path}.{n}")}
                        for n, _ in outs],
            "inputs": [{"name": n, "shape": _shape(net, f"{inst.path}.{n}")}
                       for n, _ in ins],
            "parameters": params}


def module_detail(net, inst: ModuleInstance) -> dict:
    """``GET /api/module``: a module with descriptions, defaults and its class's view."""
    desc = inst.module.description
    ins, outs = module_ports(net, inst)
    params = []
    for spec in desc.parameters:
        if spec.name not in inst.values:
            continue
        params.append({"name": spec.name, "type": spec.type,
                       "value": _value(net, inst, spec.name), "default": plain(spec.default),
                       "options": list(spec.options), "description": spec.description})
    view = None
    if getattr(desc, "view", None) is not None:
        try:
            view = view_json(net, inst, desc.view)
        except Exception:
            view = None
    return {"path": inst.path, "class": inst.entry.name, "description": desc.description,
            "parameters": params,
            "inputs": [{"name": n, "shape": _shape(net, f"{inst.path}.{n}"),
                        "connected": bool(inst.module.connected(n)),
                        "description": getattr(s, "description", "")} for n, s in ins],
            "outputs": [{"name": n, "shape": _shape(net, f"{inst.path}.{n}"),
                         "description": getattr(s, "description", "")} for n, s in outs],
            "view": view}


def connections(group: Group) -> list:
    """The connection elements of a group, as written."""
    return list(group.connections) or list(group.node.elements("connection"))


def _decl(node) -> dict:
    return {k: str(v) for k, v in node.attrs.items()}


def group_json(net, group: Group) -> dict:
    groups, modules = [], []
    for comp in group.children.values():
        if isinstance(comp, Group):
            groups.append(group_json(net, comp))
        elif isinstance(comp, ModuleInstance):
            modules.append(module_json(net, comp))
    return {"name": group.name, "path": group.path, "groups": groups, "modules": modules,
            "views": group_views(net, group),
            "connections": [{"source": c.get("source"), "target": c.get("target"),
                             "delay": c.get("delay")} for c in connections(group)],
            "inputs": [_decl(n) for n in group.inputs],
            "outputs": [_decl(n) for n in group.outputs]}


def network_json(net) -> dict:
    """``GET /api/network``."""
    return {"file": os.path.basename(net.filename or ""), "name": net.top.name,
            "top": group_json(net, net.top)}
