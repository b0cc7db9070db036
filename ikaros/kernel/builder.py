"""The builder: a model tree -> groups and modules -> buffers and links -> sizes -> a
schedule and the element maps a Network runs."""
from __future__ import annotations

import collections
import gc
import os
import re

from ..access import AccessRefused, check_file_parameter, current as access_now
from ..errors import ModelError
from ..interrupt import fault_text, is_interrupt, module_faults
from ..language.diagnostics import Diagnostics, collecting, warn_at
from ..language.dialect import DIALECTS, read_dialect
from ..language.node import INCLUDE, Node
from ..limits import (LimitError, Limits, applied, check_module_count, check_shape,
                      current as current_limits, max_modules)
from ..language.reader import read_file
from ..language.values import (ValueError_, parse_bool, parse_delays, parse_int,
                               split_selectors, value_text)
from ..description import parse_alias
from ..module import Clock, CRandom, Module, parameter_attribute
from .buffers import Buffer, Link
from .carry import adoptable
from .classes import ClassRegistry
from .concatenation import (ATTRIBUTE as CONCATENATION, DEFAULT as DEFAULT_CONCATENATION,
                            check_value as check_concatenation, warn_shared_zero_delay,
                            window_order)
from .layout import layout, runs_into
from .loadwarnings import configuring
from .network import Network
from .ranges import check_parameter, fit_shape
from .schedule import schedule
from .startup import StartupSteps
from .topdefaults import top_level_defaults
from .scope import VariableError, convert, from_python, lookup_parameter, substitute
from .dynamic import check_dynamic_connections, unresolved_capacity
from .gating import MODULE_START, StartSteps, first_tick
from .sizes import SizeError, WAIT, rule_shape, shape_expression
from .tree import Component, Group, ModuleInstance, Scope, find_component

_NAME = re.compile(r"[A-Za-z_](?:[\w\- ]*[\w\-])?$")


_ONE_TICK = [1]     # the default delay (link delays are never changed after parsing)
_SHORT_DELAYS = {"0": [0], "1": _ONE_TICK}   # shared, as _ONE_TICK is


# A build that leaves more new objects than this freezes them (see _collector_paused).
FREEZE_MINIMUM = 50_000


class _collector_paused:
    """Reading and building make many long-lived objects; collecting garbage meanwhile only
    costs time (the collector runs again as usual afterwards).

    The first collection after a build traces every object the build left (about 0.2 us
    each: 50-60 ms for a model of 10,000 modules), and the next collections of the older
    generations trace them again (while the model runs). After a large build (``freeze`` with more than FREEZE_MINIMUM new
    objects) every object is moved to the collector's permanent generation instead
    (``gc.freeze``), where no collection traces it; the network's ``close`` gives them
    back (``gc.unfreeze``). Small builds are left alone: they gain little, and a process
    that loads many small models without closing them must not keep their garbage."""

    def __enter__(self):
        self.enabled = gc.isenabled()
        gc.disable()
        self.count = gc.get_count()[0]
        return self

    def freeze(self) -> bool:
        """Freeze every object if the build left many; returns whether it did."""
        if not self.enabled or gc.get_count()[0] - self.count <= FREEZE_MINIMUM:
            return False
        gc.freeze()
        return True

    def __exit__(self, *exc):
        if self.enabled:
            gc.enable()


class Builder:
    """Builds one model: a file, the text of one (``text``), or a model tree already read
    (``model``, as the editor holds it). ``diagnostics`` collects the load-time warnings
    (and says whether the load is strict or lenient)."""

    #: what a build makes when no ``network_factory`` is given. Importing ``ikaros`` sets it to
    #: ``ikaros.Network``, the kernel's network plus what joins it to notebooks and recording
    #: (the kernel does not know them).
    network_class: type = Network

    def __init__(self, filename: str, overrides: dict | None = None, text: str | None = None,
                 notify=None, registry: ClassRegistry | None = None,
                 model: Node | None = None, diagnostics: Diagnostics | None = None,
                 limits: Limits | None = None, network_factory=None,
                 user_data: str | None = None, predecessor=None):
        self.limits = limits
        # the running network this build replaces (an Apply): the modules that did not
        # change are taken over from it, not started again (kernel/carry.py)
        self.predecessor = predecessor
        self.adopting: dict = {}
        self.user_data = user_data      # where modules write relative files (-u DIR)
        self.filename = os.path.abspath(filename)
        if model is not None and model.tag != "group":
            raise model.error(f"the root element is <{model.tag}> but must be <group>")
        self.model = model            # read by build() when not given
        self._text = text
        self.overrides = {k: value_text(v) for k, v in (overrides or {}).items()}
        self.registry = registry or ClassRegistry([os.path.dirname(self.filename)])
        self.diagnostics = diagnostics or Diagnostics()
        # makes the Network from (builder, top, order, runs, edges); ikaros.load's runs
        # groups with a process attribute in other processes (ikaros.links.split)
        self.network_factory = network_factory
        self.clock = Clock()
        self.c_random = CRandom()      # the C rand() stream the network's modules share
        self.connections: list[tuple[Node, Group]] = []
        self.ports: dict[tuple, Buffer] = {}
        self.instances: list[ModuleInstance] = []
        self.buffers: dict[ModuleInstance, tuple[dict, dict]] = {}
        self._folders: dict[str, str] = {}     # the folder of each file read
        self._sources: dict[tuple, Buffer] = {}   # (group, address) -> a connection's source
        self.startup = StartupSteps()           # the time of each build step
        self._confined = True          # whether file parameters are checked (set by _build)
        self._checked_shapes: set[tuple] = set()   # output shapes that passed check_shape
        self._concatenations: dict[Group, str] = {}   # each group's concatenation setting
        self._configuring: dict = {}   # a module's notify while configured, per notify

    # --- the tree ------------------------------------------------------------------------
    def build_tree(self) -> Group:
        # so many modules that building them would pass the memory limit: refused first
        _check_module_count(self.model, _count_modules(self.model))
        self._most_modules = max_modules()
        attrs = dict(self.model.attrs)
        if "user_data" in attrs:
            warn_at(self.model, "user_data in a model file is ignored (a model may not "
                                "choose where files are written); use ikaros -u DIR")
            del attrs["user_data"]
        attrs.update(self.overrides)
        self.dialect = attrs.get("dialect")
        if not self.dialect:
            reading = read_dialect(self.model, os.path.dirname(self.filename))
            self.dialect = reading.dialect
            if reading.reason:
                self.diagnostics.note(reading.reason, self.model.file, self.model.line)
        if self.dialect not in DIALECTS:
            raise self.model.error(f'dialect="{self.dialect}" must be "2" (Ikaros 2) or "3" '
                                   f'(Ikaros 3)')
        name = attrs.get("name") or "Main"
        return self._group(self.model, None, name, attrs, (self.filename,))

    def _group(self, node: Node, parent: Group | None, name: str, attrs: dict,
               files: tuple) -> Group:
        _check_depth(node, parent)
        group = Group(name, node, parent, dict(attrs))
        if parent is None:
            group.defaults = top_level_defaults(self.dialect, self.filename)
        anonymous = 0
        for child in node.elements():
            tag = child.tag
            if tag in ("module", "group"):
                child_name = child.attrs.get("name")
                if child_name is None and tag == "group":
                    anonymous += 1
                    child_name = f"Group-{anonymous}"
                if child_name is None and child.attrs.get("class"):
                    child_name = self._unnamed_module(child, group)
                if not child_name:
                    raise child.error(f"a <{tag}> needs a name")
                child_name = self._substitute(child_name, child, group, "name")
                if not _NAME.match(child_name):
                    raise child.error(f'"{child_name}" is not a valid name (letters, digits, _, '
                                      f'- and inner spaces, not starting with a digit)')
                if child_name in group.children:
                    raise child.error(f'duplicate name "{child_name}" in group '
                                      f'"{group.path or group.name}"')
                if tag == "group":
                    group.children[child_name] = self._subgroup(child, group, child_name, files)
                else:
                    group.children[child_name] = self._module(child, group, child_name, files)
            elif tag == "connection":
                group.connections.append(child)
                self.connections.append((child, group))
            elif tag == "input":
                group.inputs.append(child)
            elif tag == "output":
                if not child.get("name"):
                    raise child.error("a group <output> needs a name")
                if child.get("shape") or child.get("size"):
                    raise child.error("a group output can not have a shape or size: it is "
                                      "sized from its connection")
                group.outputs.append(child)
            elif tag == "parameter":
                if child.get("target"):
                    group.renamings.append(child)
                elif child.get("name") and child.get("default") is not None:
                    group.attrs.setdefault(child.get("name"), child.get("default"))
            elif tag in ("view", "widget"):
                group.views.append(child)
        return group

    def _unnamed_module(self, node: Node, group: Group) -> str:
        """A <module> without a name takes its class name (Ikaros 2); the file read keeps
        that name, so saving writes it."""
        name = self._substitute(node.attrs["class"], node, group, "class")
        warn_at(node, f'a <module> without a name takes its class name "{name}"')
        attrs = {}
        for key, value in node.attrs.items():
            attrs[key] = value
            if key == "class":
                attrs["name"] = name
        node.attrs = attrs
        return name

    def _subgroup(self, node: Node, parent: Group, name: str, files: tuple) -> Group:
        external = node.get("external")
        if not external:
            return self._group(node, parent, name, node.attrs, files)
        path = self._substitute(external, node, parent, "external")
        _confined(node, path, "group file")
        merged, file = self._merge_file(node, path, files)
        merged.attrs.pop("external", None)
        return self._group(merged, parent, name, merged.attrs, files + (file,))

    def _merge_file(self, node: Node, path: str, files: tuple) -> tuple[Node, str]:
        """A group file's root with the referring element's attributes (which win) and
        children added."""
        file = os.path.normpath(os.path.join(os.path.dirname(node.file or self.filename),
                                             path))
        if file in files:
            raise node.error(f'"{os.path.basename(file)}" includes itself')
        if not os.path.isfile(file):
            raise node.error(f'group file "{path}" not found')
        try:
            root = read_file(file, root_tag="group")
        except ModelError as e:
            raise node.error(f'group file "{path}" is not a model: {e}') from None
        attrs = dict(root.attrs)
        attrs.update({k: v for k, v in node.attrs.items() if k != "class"})
        merged = Node("group", attrs, list(root.children) + list(node.children), root.file,
                      root.line, root.text)
        return merged, file

    def _module(self, node: Node, group: Group, name: str, files: tuple) -> Component:
        attrs = node.attrs
        class_name = attrs.get("class")
        if not class_name:
            raise node.error("a <module> needs a class")
        class_name = self._substitute(class_name, node, group, "class")
        folders = [self._folder(node.file or self.filename)]
        if attrs.get("path"):
            class_path = self._substitute(attrs["path"], node, group, "path")
            _confined(node, class_path, "class path")
            folders.insert(0, os.path.join(folders[0], class_path))
        entry = self.registry.find(class_name, folders, files)
        if entry is None:
            itself = self.registry.find(class_name, folders)
            if itself is not None and itself.is_group and itself.group in files:
                raise node.error(f'class "{class_name}" is the group file '
                                 f'"{os.path.basename(itself.group)}", which this module is '
                                 f'part of: a group file cannot be used inside itself')
            raise node.error(f'unknown class "{class_name}"')
        if entry.is_group:
            merged, file = self._merge_file(node, entry.group, files)
            merged.attrs["name"] = name
            return self._group(merged, group, name, merged.attrs, files + (file,))
        if len(self.instances) >= self._most_modules:        # (group files add modules)
            _check_module_count(node, len(self.instances) + 1, growing=True)
        inst = ModuleInstance(name, node, group, entry, len(self.instances))
        self.instances.append(inst)
        return inst

    def _substitute(self, text: str, node: Node, group: Group, what: str) -> str:
        """An attribute's value with its variables resolved in the scope of its element."""
        if "@" not in text and "{" not in text:
            return text
        try:
            return substitute(text, Scope(node, group))
        except VariableError as e:
            raise node.error(f"{what}: {e}") from None

    def _folder(self, file: str) -> str:
        folder = self._folders.get(file)
        if folder is None:
            folder = self._folders[file] = os.path.dirname(file)
        return folder

    # --- modules -------------------------------------------------------------------------
    def instantiate(self, inst: ModuleInstance) -> None:
        """Create the Python module object, set its parameters, and run its configure()."""
        try:
            cls = inst.entry.module_class()
        except ModelError as e:
            reason = e.reason if e.filename is None else f'class "{inst.entry.name}": {e}'
            raise inst.node.error(reason) from None
        desc = cls.description
        for spec in desc.parameters:
            inst.values[spec.name], inst.has_value[spec.name] = self._parameter(inst, spec)
        for spec in desc.parameters:
            if spec.shape:
                self._fixed_parameter_shape(inst, spec)
        for key in ("shape", "size"):
            if key in inst.attrs and key not in inst.values:
                inst.shape_attribute = inst.attrs[key]
                break
        try:
            module = cls()
        except module_faults() as e:
            if is_interrupt(e):
                raise
            raise inst.node.error(f"creating the module failed: {fault_text(e)}") \
                from None
        module.name, module.path, module.element = inst.name, inst.path, inst.node
        module.user_data = self.user_data
        module.dialect = self.dialect
        module.clock = self.clock
        module._ik_c_random = self.c_random
        for name, value in inst.values.items():
            setattr(module, parameter_attribute(name), value)
        inst.module = module
        notify = self._configuring.get(module._ik_notify)      # one for modules alike
        if notify is None:
            notify = self._configuring[module._ik_notify] = configuring(self.diagnostics,
                                                                        module._ik_notify)
        module._ik_notify = notify
        self._run_settings(inst)
        try:
            module.configure()
        except module_faults() as e:
            if is_interrupt(e) or (isinstance(e, ModelError) and e.filename is not None):
                raise
            raise inst.node.error(f"configure failed: {fault_text(e)}") from None

    def _run_settings(self, inst: ModuleInstance) -> None:
        """``period``, ``phase``, ``async``, ``module_start`` and ``start_tick`` of a
        module element."""
        attrs = inst.attrs
        if not _RUN_SETTINGS.intersection(attrs):
            return                          # the defaults of ModuleInstance

        def setting(key, default, parse):
            text = inst.attrs.get(key)
            if text in (None, ""):
                return default
            try:
                text = substitute(text, inst, own=key)
                return parse(text) if text.strip() else default
            except (ValueError_, VariableError) as e:
                raise inst.node.error(f"{key}: {e}") from None

        inst.period = setting("period", 1, parse_int)
        inst.phase = setting("phase", 0, parse_int)
        inst.asynchronous = setting("async", False, parse_bool)
        if inst.period < 1 or not 0 <= inst.phase < inst.period:
            raise inst.node.error(f"period must be >= 1 and phase in 0..period-1 (period "
                                  f"{inst.period}, phase {inst.phase})")
        start = setting("module_start", "at_tick", str).strip()
        if start not in MODULE_START:
            raise inst.node.error(f'module_start="{start}" must be at_tick, first_data or '
                                  f'all_data (or 0, 1, 2)')
        inst.module_start = MODULE_START[start]
        inst.start_tick = setting("start_tick", 0, parse_int)
        if inst.start_tick < 0:
            raise inst.node.error(f"start_tick must be >= 0 (start_tick {inst.start_tick})")

    def _fixed_parameter_shape(self, inst: ModuleInstance, spec) -> None:
        """A matrix parameter whose class declares its ``shape`` (after every parameter has
        its value, so the shape may name them): zero-filled, or an error when too long."""
        try:
            shape = shape_expression(inst, spec.shape, {})
            inst.values[spec.name] = fit_shape(inst.values[spec.name], shape)
        except (SizeError, ValueError_) as e:
            raise inst.node.error(f'parameter "{spec.name}" of {inst.path}: {e}') from None

    def _default(self, spec):
        """A parameter's default in this file: Ikaros 3's where it changed it (dialect 3)."""
        if self.dialect == "3" and spec.default_v3 is not None:
            return spec.default_v3
        return spec.default

    def _parameter(self, inst: ModuleInstance, spec) -> tuple[object, bool]:
        try:
            found = lookup_parameter(inst, spec.name)
        except VariableError as e:
            raise inst.node.error(f'parameter "{spec.name}": {e}') from None
        where = inst
        try:
            if found is not None:
                raw, where, _ = found
                text = raw
                if spec.type not in _EMPTY_IS_A_VALUE:
                    if "@" in text or "{" in text:
                        text = substitute(text, where, own=spec.name)
                    if not text.strip():    # unset, as in Ikaros 2
                        warn_at(where.node, f'parameter "{spec.name}" of {inst.path} has an '
                                            f'empty value; the default applies')
                        if where is inst and not raw.strip():
                            del inst.attrs[spec.name]      # so that saving leaves it out
                        found = None
            if found is not None:
                value = convert(text, spec, where, own=spec.name)
            elif self._default(spec) is not None and self._default(spec) != "":
                default = self._default(spec)
                if isinstance(default, str):
                    value = convert(default, spec, inst)
                else:
                    value = from_python(default, spec)
            else:
                return from_python(None, spec), False
            check_parameter(value, spec)
            if self._confined:
                check_file_parameter(spec, value, self._folder(inst.node.file or
                                                               self.filename))
            return value, True
        except AccessRefused as e:
            raise inst.node.error(f"{e}") from None
        except (ValueError_, VariableError, ValueError) as e:
            node = where.node if hasattr(where, "node") else inst.node
            raise node.error(f'parameter "{spec.name}" of {inst.path}: {e}') from None

    def make_buffers(self, inst: ModuleInstance) -> None:
        module: Module = inst.module
        inputs, outputs = {}, {}
        dotted = "." in "".join(inst.attrs)     # INPUT.flatten="yes" and the like
        joined = self._concatenation(inst) if module._ik_inputs else None
        for spec in module._ik_inputs.values():
            flatten, stack, use_label = spec.flatten, spec.stack, spec.use_label
            concatenation = joined
            if dotted:
                flatten = self._input_flag(inst, spec.name, "flatten", flatten)
                stack = self._input_flag(inst, spec.name, "stack", stack)
                use_label = self._input_flag(inst, spec.name, "use_label", use_label)
                own = inst.attrs.get(f"{spec.name}.{CONCATENATION}")
                if own:
                    concatenation = self._concatenation_value(inst, inst.node, own)
            inputs[spec.name] = Buffer("input", inst, spec.name, optional=spec.optional,
                                       flatten=flatten, stack=stack, fixed=spec.size,
                                       node=inst.node, use_label=use_label,
                                       concatenation=concatenation)
        for spec in module._ik_outputs.values():
            buf = Buffer("output", inst, spec.name, optional=spec.optional, node=inst.node)
            buf.shape = module._ik_output_shapes.get(spec.name)
            buf.dynamic = spec.dynamic
            outputs[spec.name] = buf
        self.buffers[inst] = (inputs, outputs)
        module._ik_input_buffers = inputs       # for input_parts and input_label

    def _concatenation(self, comp: Component) -> str:
        """The ``concatenation`` setting seen from a module or group: its own attribute, then
        the enclosing groups', then the dialect's default (kernel/concatenation.py)."""
        text = comp.attrs.get(CONCATENATION)
        if text:
            return self._concatenation_value(comp, comp.node, text)
        parent = comp.parent
        if parent is None:
            return DEFAULT_CONCATENATION[self.dialect]
        value = self._concatenations.get(parent)
        if value is None:
            value = self._concatenations[parent] = self._concatenation(parent)
        return value

    def _concatenation_value(self, scope, node: Node, text: str) -> str:
        try:
            return check_concatenation(substitute(text, scope))
        except (ValueError, VariableError) as e:
            raise node.error(str(e)) from None

    def _input_flag(self, inst: ModuleInstance, name: str, key: str, default: bool) -> bool:
        """An input's flag as the module element sets it (``INPUT.flatten="yes"``)."""
        value = inst.attrs.get(f"{name}.{key}")
        return self._flag(inst, value, key) if value else default

    def _flag(self, inst, text, what) -> bool:
        try:
            return parse_bool(substitute(text, inst))
        except (ValueError_, VariableError) as e:
            raise inst.node.error(f"{what}: {e}") from None

    # --- connections ---------------------------------------------------------------------
    def connect(self, order: int, node: Node, group: Group) -> None:
        attrs = node.attrs
        source = self._connection_attr(node, group, "source")
        target = self._connection_attr(node, group, "target")
        if not source:
            raise node.error("a connection needs a source")
        if not target:
            raise node.error("a connection needs a target")
        try:
            src_path, src_sel = split_selectors(source)
            dst_path, dst_sel = split_selectors(target)
            delay = attrs.get("delay")
            if delay is None:
                delays = _ONE_TICK
            elif delay in _SHORT_DELAYS:
                delays = _SHORT_DELAYS[delay]
            else:
                delay = self._connection_attr(node, group, "delay")
                if delay:
                    delays = parse_delays(delay, wrap_ranges=self.dialect == "3")
                else:               # unset, as in Ikaros 2: the default delay
                    warn_at(node, "an empty delay means the default, 1")
                    if not attrs["delay"].strip():
                        del attrs["delay"]          # so that saving leaves it out
                    delays = _ONE_TICK
            offsets = {}
            if "sourceoffset" in attrs or "targetoffset" in attrs or "size" in attrs:
                offsets = {k: parse_int(v) for k in ("sourceoffset", "targetoffset", "size")
                           if k in attrs and (v := self._connection_attr(node, group, k))}
        except ValueError_ as e:
            raise node.error(str(e)) from None
        if offsets:
            src_sel, dst_sel = _placement(node, offsets, src_sel, dst_sel)
        else:
            src_sel = src_sel and ("selector", src_sel)
            dst_sel = dst_sel and ("selector", dst_sel)
        try:
            src = self._sources.get((group, src_path))
            if src is None:
                src = self._sources[group, src_path] = self._source(group, src_path, node)
            targets = self._targets(group, dst_path, node)
        except ModelError as e:
            if not (self.diagnostics.lenient and getattr(e, "missing_endpoint", False)):
                raise
            # Ikaros 3 drops ("prunes") such a connection and runs the rest
            self.diagnostics.warn(f"{e.reason}; the connection is dropped (lenient)",
                                  node.file, node.line, node.label())
            _remove(self.model, node)        # so that saving leaves it out
            return
        label = self._connection_attr(node, group, "label") if "label" in attrs else None
        for dst in targets:
            Buffer.link(Link(src, dst, window_order(delays, dst.concatenation), node, order,
                             src_sel, dst_sel, label or None))

    def _connection_attr(self, node: Node, group: Group, key: str) -> str | None:
        value = node.attrs.get(key)
        if value is None:
            return None
        if "@" in value or "{" in value:
            value = self._substitute(value, node, group, key)
        return value.strip()

    def _split(self, group: Group, path: str, node: Node, role: str):
        comp_path, dot, port = path.rpartition(".")
        if not dot:
            return group, path
        comp = group.children.get(comp_path)     # the common case: a child of this group
        if comp is None:
            comp = group.top() if comp_path == "" else find_component(group, comp_path)
        if comp is None:
            raise _missing(node, f'connection {role} "{path}" not found: there is no '
                                 f'"{comp_path}" seen from group "{group.path or group.name}"')
        return comp, port

    def _port(self, group: Group, direction: str, name: str, decl: Node) -> Buffer:
        key = (group, direction, name)
        if key not in self.ports:
            flags = {k: self._flag(group, decl.get(k), k) for k in ("flatten", "stack")
                     if decl.get(k)}
            own = decl.get(CONCATENATION)
            flags["concatenation"] = self._concatenation_value(group, decl, own) if own \
                else self._concatenation(group)
            self.ports[key] = Buffer("port", group, name, node=decl, **flags)
        return self.ports[key]

    def _source(self, group: Group, path: str, node: Node) -> Buffer:
        comp, port = self._split(group, path, node, "source")
        if isinstance(comp, ModuleInstance):
            _refuse_private_state(comp, port, path, node)
            inputs, outputs = self.buffers[comp]
            if port not in outputs:
                raise _missing(node, f'connection source "{path}" not found: module '
                                     f'{comp.path} has no output named "{port}" '
                                     f'(outputs: {", ".join(outputs) or "none"})')
            return outputs[port]
        inside = comp is group or comp in set(group.chain())
        decls = [d for d in (comp.inputs if inside else comp.outputs) if d.get("name") == port]
        if not decls:
            kind = "input" if inside else "output"
            raise _missing(node, f'connection source "{path}" not found: group '
                                 f'"{comp.path or comp.name}" has no {kind} named "{port}"')
        decl = decls[0]
        alias = _alias(decl, "source", "sourcemodule")
        if alias and not inside:
            if decl.get("sourcemodule"):
                warn_at(decl, f'sourcemodule is deprecated; write source="{alias}"')
            return self._source(comp, alias, decl)
        return self._port(comp, "in" if inside else "out", port, decl)

    def _targets(self, group: Group, path: str, node: Node) -> list[Buffer]:
        comp, port = self._split(group, path, node, "target")
        if isinstance(comp, ModuleInstance):
            _refuse_private_state(comp, port, path, node)
            inputs, outputs = self.buffers[comp]
            if port not in inputs:
                raise _missing(node, f'connection target "{path}" not found: module '
                                     f'{comp.path} has no input named "{port}" '
                                     f'(inputs: {", ".join(inputs) or "none"})')
            return [inputs[port]]
        inside = comp is group or comp in set(group.chain())
        decls = [d for d in (comp.outputs if inside else comp.inputs) if d.get("name") == port]
        if not decls:
            kind = "output" if inside else "input"
            raise _missing(node, f'connection target "{path}" not found: group '
                                 f'"{comp.path or comp.name}" has no {kind} named "{port}"')
        targets = []
        for decl in decls:
            alias = _alias(decl, "target", "targetmodule")
            if alias and not inside:
                if decl.get("targetmodule"):
                    warn_at(decl, f'targetmodule is deprecated; write target="{alias}"')
                elif "." not in alias:
                    raise decl.error(f'target="{alias}" must name a module input '
                                     f'(Module.INPUT)')
                targets.extend(self._targets(comp, alias, decl))
            else:
                targets.append(self._port(comp, "out" if inside else "in", port, decl))
        return targets

    # --- sizes ---------------------------------------------------------------------------
    def check_zero_delay_cycles(self) -> None:
        """Report a zero-delay cycle before sizing (whose errors would hide it)."""
        def feeders(buf: Buffer, seen: frozenset):
            for link in buf.incoming:
                if 0 not in link.delays or link.source in seen:
                    continue
                if link.source.kind == "output":
                    yield link.source.owner, link.node
                else:
                    yield from feeders(link.source, seen | {link.source})

        edges: dict = {}
        for inst in self.instances:
            for buf in self.buffers[inst][0].values():
                for source, node in feeders(buf, frozenset()):
                    edges.setdefault((source, inst), node)
        schedule(self.instances, edges)

    def resolve_sizes(self) -> None:
        self._drop_links_from_unconnected_ports()
        try:
            self._resolve_sizes()
        except ModelError:
            # A zero-delay cycle often shows first as sizes that cannot be resolved; name
            # the cycle, which is the cause.
            self.check_zero_delay_cycles()
            raise

    def _resolve_sizes(self) -> None:
        shared_sets: dict[tuple, frozenset] = {}
        for inst in self.instances:
            inputs, _ = self.buffers[inst]
            for buf in inputs.values():
                if not buf.incoming and not buf.optional:
                    raise inst.node.error(f'required input "{buf.name}" of {inst.path} is not '
                                          f'connected')
            names = tuple(n for n, b in inputs.items() if b.incoming)
            connected = shared_sets.get(names)      # one set for every module alike
            if connected is None:
                connected = shared_sets[names] = frozenset(names)
            inst.module._ik_connected = connected
        # A worklist: whenever a buffer gets its size, the owners of what it feeds are
        # looked at again, so sizing is linear in the size of the model.
        # When the worklist runs dry with outputs unsized (a loop through a delay), size_set
        # rules take the inputs that are sized, and the worklist goes on; this goes on until
        # no rule can size anything more (an output sized so may feed nothing, and another
        # loop elsewhere may still wait).
        queue = collections.deque(self.instances + list(self.ports.values()))
        queued = set(queue)

        def feed(sized):
            for buf in sized:
                for link in buf.outgoing:
                    owner = link.target if link.target.kind == "port" else link.target.owner
                    if owner not in queued:
                        queue.append(owner)
                        queued.add(owner)

        progress = True
        while progress:
            while queue:
                item = queue.popleft()
                queued.discard(item)
                feed(self._advance(item))
            progress = False
            for inst in self.instances:
                if any(b.shape is None for b in self.buffers[inst][1].values()):
                    sized = self._size_outputs(inst, partial=True)
                    if sized:
                        feed(sized)
                        progress = True
                        break
        pending = [b for inst in self.instances for b in self.buffers[inst][0].values()
                   if b.incoming and b.shape is None] + \
            [p for p in self.ports.values() if p.incoming and p.shape is None]
        self._check_sizes(pending)

    def _ready(self, buf: Buffer) -> bool:
        """Whether an input or port can be laid out: unsized, connected, all sources sized."""
        if buf.shape is not None or not buf.incoming:
            return False
        for link in buf.incoming:
            if link.source.shape is None:
                return False
        return True

    def _advance(self, item) -> list[Buffer]:
        """Size what can be sized now in a module or port; return the buffers newly sized."""
        if isinstance(item, Buffer):
            if self._ready(item):
                layout(item, None)
                return [item]
            return []
        for buf in self.buffers[item][0].values():
            if self._ready(buf):
                if buf.fixed:
                    fixed = self._fixed_shape(buf)
                    if fixed is WAIT:
                        continue
                    layout(buf, fixed)
                else:
                    layout(buf, None)
        return self._size_outputs(item)

    def _drop_links_from_unconnected_ports(self) -> None:
        changed = True
        while changed:
            changed = False
            for port in self.ports.values():
                if port.incoming or not port.outgoing:
                    continue
                for link in port.outgoing:
                    link.target.incoming.remove(link)
                port.outgoing = []
                changed = True

    def _fixed_shape(self, buf: Buffer):
        if not buf.fixed:
            return None
        inst = buf.owner
        try:
            return shape_expression(inst, buf.fixed, self._input_shapes(inst))
        except SizeError as e:
            raise inst.node.error(f'size of input "{buf.name}": {e}') from None

    def _input_shapes(self, inst: ModuleInstance) -> dict:
        inputs, _ = self.buffers[inst]
        return {name: (buf.shape if buf.incoming else ()) for name, buf in inputs.items()}

    def _size_outputs(self, inst: ModuleInstance, partial: bool = False) -> list[Buffer]:
        module = inst.module
        inputs, outputs = self.buffers[inst]
        shapes = self._input_shapes(inst)
        module._ik_input_shapes = shapes
        sized = []
        waiting = aliases = False
        for name, buf in outputs.items():
            if buf.shape is not None:
                continue
            spec = module._ik_outputs[name]
            if "alias" in spec.rule:
                aliases = True
                continue                # sized below, from the output it views
            try:
                shape = rule_shape(inst, spec, shapes, partial) if spec.rule else WAIT
                if shape is not WAIT and shape not in self._checked_shapes:
                    check_shape(shape)
                    self._checked_shapes.add(shape)
            except (SizeError, LimitError) as e:
                what = f'capacity of dynamic output "{name}" of {inst.path} ' \
                       f'("{spec.rule["capacity"]}")' if spec.dynamic else \
                       f'size of output "{name}"'
                raise inst.node.error(f"{what}: {e}") from None
            if shape is WAIT:
                waiting = True
            else:
                buf.shape = shape
                module._ik_output_shapes[name] = shape
                sized.append(buf)
        if waiting and type(module).set_sizes is not Module.set_sizes:
            try:
                module.set_sizes()
            except module_faults() as e:
                if is_interrupt(e):
                    raise
                raise inst.node.error(f"set_sizes failed: {fault_text(e)}") from None
            for name, buf in outputs.items():
                if buf.shape is None and module._ik_output_shapes.get(name) is not None:
                    shape = module._ik_output_shapes[name]
                    try:
                        check_shape(shape)
                    except LimitError as e:
                        raise inst.node.error(f'size of output "{name}": {e}') from None
                    buf.shape = shape
                    sized.append(buf)
        return sized + self._size_aliases(inst, outputs) if aliases else sized

    def _size_aliases(self, inst: ModuleInstance, outputs: dict) -> list[Buffer]:
        """Outputs that are aliases (Ikaros 3 ``alias="OUTPUT[1]"``) take the shape of the
        part of the output they view, once that output is sized."""
        module = inst.module
        sized, progress = [], True
        while progress:
            progress = False
            for name, buf in outputs.items():
                rule = module._ik_outputs[name].rule
                if buf.shape is not None or "alias" not in rule:
                    continue
                target_name, index = parse_alias(rule["alias"])
                target = outputs.get(target_name)
                where = f'output "{name}" of {inst.path}: alias "{rule["alias"]}"'
                if target is None or target is buf:
                    raise inst.node.error(f"{where} names no other output of the module")
                if target.dynamic:
                    raise inst.node.error(f"{where} views a dynamic output")
                if target.shape is None:
                    continue
                if len(index) > len(target.shape) or \
                        any(i >= n for i, n in zip(index, target.shape)):
                    raise inst.node.error(f"{where} is outside the shape "
                                          f"{list(target.shape)} of {target_name}")
                buf.shape = tuple(target.shape[len(index):]) or (1,)
                buf.alias = (target, index)
                module._ik_output_shapes[name] = buf.shape
                sized.append(buf)
                progress = True
        return sized

    def _check_sizes(self, pending: list[Buffer]) -> None:
        for inst in self.instances:
            _, outputs = self.buffers[inst]
            for name, buf in outputs.items():
                if buf.shape is None:
                    if buf.optional or not buf.outgoing:
                        buf.shape = (0,) if buf.optional else buf.shape
                    if buf.shape is None and buf.dynamic:
                        raise inst.node.error(unresolved_capacity(inst, buf))
                    if buf.shape is None:
                        rule = inst.module._ik_outputs[name].rule_text()
                        raise inst.node.error(f'the size of output "{name}" of {inst.path} '
                                              f'could not be resolved (rule: {rule}); check '
                                              f'that its inputs are connected')
        for buf in pending:
            waiting = [lk.source.path for lk in buf.incoming if lk.source.shape is None]
            owner = buf.owner
            raise owner.node.error(f'the size of {buf.kind} "{buf.path}" could not be resolved:'
                                   f' it waits for {", ".join(waiting)}')

    # --- everything ----------------------------------------------------------------------
    def build(self):
        """Build the network; raises ModelError naming the file, line and element."""
        with _collector_paused() as collector, collecting(self.diagnostics), \
                applied(self.limits or current_limits()):
            if self.model is None:
                with self.startup.step("read the model file"):
                    self.model = read_file(self.filename, self._text, root_tag="group")
            net = self._build()
            net.frozen_objects = collector.freeze()
            return net

    def _build(self):
        self._confined = access_now() is not None   # file parameters checked only then
        step = self.startup.step
        with step("groups and modules"):
            top = self.build_tree()
        with step("classes and ports"):
            for inst in self.instances:
                self.instantiate(inst)
                self.make_buffers(inst)
        with step("connections"):
            for order, (node, group) in enumerate(self.connections):
                self.connect(order, node, group)
            check_dynamic_connections(buf for inst in self.instances
                                      for buf in self.buffers[inst][1].values())
        with step("sizes"):
            self.resolve_sizes()
        with step("delays and schedule"):
            order, runs, edges = self._schedule()
            self._start_gating(runs)
        if self.predecessor is not None:
            self.adopting = adoptable(self.predecessor, self)
        return (self.network_factory or self.network_class)(self, top, order, runs, edges)

    def _start_gating(self, runs) -> None:
        """Each module's start-up steps, and the first tick of those that wait for them or
        for ``start_tick``."""
        steps = StartSteps(self.instances, runs)
        for inst in self.instances:
            inst.module._ik_start_steps = steps
            if inst.module_start != "at_tick" or inst.start_tick:
                inst.first_tick = first_tick(inst, steps)

    def _schedule(self):
        memo: dict = {}
        runs = []
        edges: dict = {}
        for inst in self.instances:
            for buf in self.buffers[inst][0].values():
                if buf.incoming:
                    into = runs_into(buf, memo)
                    if self.dialect == "2":
                        warn_shared_zero_delay(into)
                    for run in into:
                        runs.append(run)
                        if run.delay == 0:
                            edges.setdefault((run.source.owner, run.target.owner), run.node)
        return schedule(self.instances, edges), runs, edges


def _refuse_private_state(inst: ModuleInstance, port: str, path: str, node: Node) -> None:
    """A connection to or from a module's <state> item is an error (Ikaros 3)."""
    states = inst.module.description.states
    if states and any(st.name == port for st in states):
        raise node.error(f'connection endpoint "{path}": {inst.path}.{port} is private state '
                         f'and can not be connected')


# the module element's attributes that _run_settings reads
_RUN_SETTINGS = frozenset(("period", "phase", "async", "module_start", "start_tick"))


def _missing(node: Node, message: str) -> ModelError:
    """The error of a connection whose source or target does not exist (such connections
    are dropped when the load is lenient)."""
    error = node.error(message)
    error.missing_endpoint = True
    return error


def _remove(tree: Node, node: Node) -> bool:
    """Take an element out of the tree read from the file (not out of included files)."""
    for i, child in enumerate(tree.children):
        if child is node:
            del tree.children[i]
            return True
        if child.tag != INCLUDE and _remove(child, node):
            return True
    return False


_EMPTY_IS_A_VALUE = ("string", "matrix", "array")
def _confined(node: Node, name: str, what: str) -> None:
    """Refuse a file or folder outside the models folder in a confined build."""
    confinement = access_now()
    if confinement is not None:
        try:
            confinement.check(name, os.path.dirname(node.file or "."), what)
        except AccessRefused as e:
            raise node.error(str(e)) from None


def _count_modules(tree: Node) -> int:
    """The <module> elements of a model's own files (group files used as classes add
    theirs as they are built)."""
    count, pending = int(tree.tag == "module"), [tree]
    while pending:
        for child in pending.pop().children:
            count += child.tag == "module"
            if child.children:
                pending.append(child)
    return count


def _check_module_count(node: Node, count: int, growing: bool = False) -> None:
    try:
        check_module_count(count, growing)
    except LimitError as e:
        raise node.error(str(e)) from None


def _check_depth(node: Node, parent: Group | None) -> None:
    """Refuse groups nested deeper than the limit (across group files and classes too)."""
    limit = current_limits().max_group_depth
    depth = 0
    while parent is not None:
        depth += 1
        parent = parent.parent
    if depth >= limit:
        raise node.error(f"groups nest deeper than {limit} levels")


def _alias(decl: Node, key: str, legacy: str) -> str | None:
    if decl.get(legacy):
        return f"{decl.get(legacy)}.{decl.get(key)}"
    return decl.get(key)


def _placement(node: Node, offsets: dict, src_sel, dst_sel) -> tuple:
    """Source and target placement of a connection with ``sourceoffset``, ``targetoffset``
    or ``size``, checked against its selectors."""
    if any(v < 0 for v in offsets.values()):
        raise node.error("sourceoffset, targetoffset and size must not be negative")
    if src_sel is not None and ("sourceoffset" in offsets or "size" in offsets):
        raise node.error("a source selector cannot be combined with sourceoffset or size")
    if dst_sel is not None and "targetoffset" in offsets:
        raise node.error("a target selector cannot be combined with targetoffset")
    if "sourceoffset" in offsets or "size" in offsets:
        src_sel = ("offset", offsets.get("sourceoffset", 0), offsets.get("size"))
    elif src_sel is not None:
        src_sel = ("selector", src_sel)
    if "targetoffset" in offsets:
        dst_sel = ("offset", offsets["targetoffset"])
    elif dst_sel is not None:
        dst_sel = ("selector", dst_sel)
    return src_sel, dst_sel
