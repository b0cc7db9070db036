"""The one API a module sees: the ``Module`` base class and its declarations.

A module is a Python class::

    class Scale(Module):
        \"\"\"Multiplies its input by a factor.\"\"\"
        factor = Parameter(1.0, "the gain")
        INPUT = Input("the signal")
        OUTPUT = Output("the scaled signal", shape="INPUT.shape")

        def tick(self):
            np.multiply(self.INPUT, self.factor, out=self.OUTPUT)

Inside ``init`` and ``tick`` inputs and outputs are NumPy arrays (float32) whose identity never
changes, and parameters are plain values. A module never writes to its inputs. An optional input
that is not connected is ``None``. The current tick and time are on ``self.clock``.
Attributes whose names start with ``_ik_`` belong to the kernel; other names are free.
"""
from __future__ import annotations

import builtins
import functools
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, overload

import numpy as np

from .crandom import RAND_MAX, CRandom  # noqa: F401  (part of the module API)
from .description import (ClassDescription, InputSpec, OutputSpec, ParameterSpec,
                          SIZE_RULE_KEYS, STATE_TYPES, StateSpec, canonical_type,
                          alias_rule, dynamic_rule)
from .dynamic import DynamicArray  # noqa: F401  (part of the module API)
from .errors import ModelError  # noqa: F401  (part of the module API: a build error)
# part of the module API: call it first thing in a thread that talks to a device, so that it
# runs at the priority a real-time run asks for (see ikaros/priority.py)
from .priority import device_thread  # noqa: F401

# Notification levels (lower is more severe), as in Ikaros.
EXCEPTION, END_OF_FILE, TERMINATE, FATAL_ERROR, WARNING, PRINT, DEBUG, TRACE = range(1, 9)
LEVEL_NAMES = {EXCEPTION: "exception", END_OF_FILE: "end_of_file", TERMINATE: "terminate",
               FATAL_ERROR: "fatal_error", WARNING: "warning", PRINT: "print", DEBUG: "debug",
               TRACE: "trace"}


class MissingDependency(ImportError):
    """A module needs an optional package that is not installed."""


def require(module_name: str, package: str, extra: str | None = None):
    """Import an optional dependency, or fail with the ``pip install`` that fixes it.

    Call it in ``configure`` (so a model that needs a missing package fails at load)::

        Image = require("PIL.Image", "Pillow", extra="image")
    """
    import importlib
    try:
        return importlib.import_module(module_name)
    except ImportError:
        fix = f"pip install 'ikaros[{extra}]'" if extra else f"pip install {package}"
        raise MissingDependency(f"this module needs the package {package}: {fix} "
                                f"(or pip install {package})") from None


def _python_name(port_name: str) -> str:
    name = re.sub(r"\W", "_", port_name)
    return "_" + name if name[:1].isdigit() else name


@functools.lru_cache(maxsize=None)
def attribute_name(port_name: str) -> str:
    """The Python attribute that holds a port: ``T-INPUT`` is ``self.T_INPUT``. A port
    added at build time with a name the module API uses (an InputFile column ``tick``) gets
    a trailing underscore: ``self.tick_``."""
    name = _python_name(port_name)
    return name + "_" if name in RESERVED else name


class Parameter:
    """Declares a parameter. The type follows the default unless given.

    Types: number, int, bool, string, list (one of ``options``), array, matrix.
    ``range=(lowest, highest)`` bounds a number (or every element of an array); either end
    may be None. Values that are nan or infinite are refused unless ``finite=False``.
    ``file=True`` marks a string that names a file or folder (a model from the web UI may
    name only files in its models folder; parameters named ``filename``, ``*_file``,
    ``directory`` and the like are taken as file names in any case).
    ``fixed=True`` marks a parameter the module uses once, when it is built or started (a
    buffer's capacity, a file to read): a change while the model runs is refused.
    ``default_v3`` is the default in a model file of dialect 3, for a parameter whose default
    Ikaros 3 changed (Constant's data).
    """

    def __init__(self, default: Any = None, description: str = "", *, type: str | None = None,
                 options: list[str] | str | None = None, control: str | None = None,
                 name: str | None = None, range: tuple | None = None, finite: bool = True,
                 file: bool = False, fixed: bool = False, default_v3: Any = None):
        if isinstance(options, str):
            options = [o.strip() for o in re.split(r"[,/]", options) if o.strip()]
        self.options = list(options or [])
        kind = canonical_type(type) if type else _infer_type(default, self.options)
        if kind is None:
            raise ValueError(f"unknown parameter type {type!r}")
        self.type: str = kind
        self.default = default
        self.description = description
        self.control = control
        self.name = name
        self.range = tuple(range) if range is not None else None
        self.finite = finite
        self.file = file
        self.fixed = fixed
        self.default_v3 = default_v3

    def __set_name__(self, owner, name):
        self.name = self.name or name

    if TYPE_CHECKING:       # for type checkers: on a module, the parameter is its value
        @overload
        def __get__(self, instance: None, owner: type) -> Parameter: ...
        @overload
        def __get__(self, instance: object, owner: type) -> Any: ...
        def __get__(self, instance, owner): ...

    def spec(self) -> ParameterSpec:
        return ParameterSpec(self.name or "", self.type, self.default, self.description,
                             self.options, self.control, self.range, self.finite, self.file,
                             fixed=self.fixed, default_v3=self.default_v3)


class Input:
    """Declares an input. ``optional`` inputs may stay unconnected (then they are None).
    With ``use_label`` the input takes the ``label`` of its one labelled connection
    (``input_label``); a model may also set it with ``INPUT.use_label="yes"``."""

    def __init__(self, description: str = "", *, optional: bool = False, flatten: bool = False,
                 stack: bool = False, size: str | None = None, name: str | None = None,
                 use_label: bool = False):
        self.spec_ = InputSpec(name or "", description, optional, flatten, stack, size,
                               use_label)

    def __set_name__(self, owner, name):
        self.spec_.name = self.spec_.name or name

    if TYPE_CHECKING:       # for type checkers: on a module, the input is its array
        @overload
        def __get__(self, instance: None, owner: type) -> Input: ...
        @overload
        def __get__(self, instance: object, owner: type) -> np.ndarray: ...
        def __get__(self, instance, owner): ...

    def spec(self) -> InputSpec:
        return self.spec_


class Output:
    """Declares an output and its size rule.

    ``shape`` is an Ikaros 3 shape expression (``"INPUT.shape"``, ``"@rows, @cols"``,
    ``"3"``); the Ikaros 2 rules ``size``, ``size_x``, ``size_y``, ``size_param``,
    ``size_param_x``, ``size_param_y``, ``size_set``, ``size_set_x`` and ``size_set_y`` are
    accepted as keywords too. Without a rule the module sets the size in ``set_sizes``.

    ``dynamic=True`` with a ``capacity`` (a shape expression, like ``shape``) declares an
    Ikaros 3 dynamic output: the module sees a ``DynamicArray`` whose shape it changes at
    run time, never beyond the capacity.

    ``alias="OUTPUT"`` or ``alias="OUTPUT[1]"`` (Ikaros 3) declares a view of another
    output of the module: the same memory, the whole output or the part at those indices
    (``OUTPUT[1]`` of a 3x4 output is its second row, 4 elements; indexing every axis gives
    one element). It has no size rule of its own.
    """

    def __init__(self, description: str = "", *, shape: str | None = None,
                 optional: bool = False, persistent: bool = False, name: str | None = None,
                 dynamic: bool = False, capacity: str | None = None,
                 alias: str | None = None, **size_rule: str):
        unknown = set(size_rule) - set(SIZE_RULE_KEYS)
        if unknown:
            raise TypeError(f"unknown output size rule {sorted(unknown)}")
        rule = {k: str(v) for k, v in size_rule.items()}
        if shape is not None:
            rule["shape"] = str(shape)
        wrong = dynamic_rule(dynamic, capacity, rule) or alias_rule(alias, dynamic, rule)
        if wrong:
            raise TypeError(wrong)
        if dynamic:
            rule["capacity"] = str(capacity)
        if alias is not None:
            rule["alias"] = alias
        self.spec_ = OutputSpec(name or "", description, rule, optional, persistent,
                                dynamic=dynamic)

    def __set_name__(self, owner, name):
        self.spec_.name = self.spec_.name or name

    if TYPE_CHECKING:       # for type checkers: on a module, the output is its array
        @overload
        def __get__(self, instance: None, owner: type) -> Output: ...
        @overload
        def __get__(self, instance: object, owner: type) -> np.ndarray: ...
        def __get__(self, instance, owner): ...

        def __set__(self, instance: object, value: np.ndarray) -> None: ...

    def spec(self) -> OutputSpec:
        return self.spec_


class State:
    """Declares a private state item (Ikaros 3 ``<state>``), kept by save, load and reset of
    the state and never connectable. A scalar (``type`` float, double, int, bool or string,
    following the default unless given) is an attribute that starts at ``default``; a
    matrix (``shape=`` an output size rule) is an array the kernel sizes and allocates like
    an output::

        count = State(0, "ticks seen")
        MEMORY = State(description="the last input", shape="INPUT.shape")
    """

    def __init__(self, default: Any = None, description: str = "", *,
                 type: str | None = None, shape: str | None = None, name: str | None = None):
        if shape is not None:
            type = type or "matrix"
        elif type is None:
            type = {bool: "bool", int: "int", float: "float", str: "string"}.get(
                builtins.type(default))
        if type not in STATE_TYPES:
            raise TypeError(f"state type must be one of {', '.join(STATE_TYPES)}, not {type!r}")
        if type == "matrix":
            if shape is None:
                raise TypeError("a matrix state needs a shape")
            self.spec_ = StateSpec(name or "", type, None, description, {"shape": str(shape)})
            return
        python = {"float": (float, int), "double": (float, int), "int": (int,),
                  "bool": (bool,), "string": (str,)}[type]
        if default is None:
            default = {"string": "", "bool": False}.get(type, 0)
        if not isinstance(default, python) or (type != "bool" and isinstance(default, bool)):
            raise TypeError(f"the default {default!r} is not a {type}")
        if type in ("float", "double"):
            default = float(default)
        self.spec_ = StateSpec(name or "", type, default, description)

    def __set_name__(self, owner, name):
        self.spec_.name = self.spec_.name or name

    def spec(self) -> StateSpec:
        return self.spec_



def _infer_type(default: Any, options: list[str]) -> str:
    if options:
        return "list"
    if isinstance(default, bool):
        return "bool"
    if isinstance(default, (int, np.integer)):
        return "int"
    if isinstance(default, (float, np.floating)):
        return "number"
    if isinstance(default, np.ndarray):
        return "matrix" if default.ndim >= 2 else "array"
    if isinstance(default, (list, tuple)):
        return "matrix" if default and isinstance(default[0], (list, tuple)) else "array"
    return "string"


@dataclass(frozen=True)
class InputPart:
    """What one connection contributes to an input: its ``label`` (the connection's
    ``label`` attribute, None without one), its ``source`` (the path of the output or group
    port it reads, as ``"C.OUTPUT"``), the ``shape`` of its values (a delay window adds a
    leading axis, one row per delay, in the order listed) and ``index``, the flat positions
    in the input that hold them. ``name`` is the label, or the source without one.
    ``arrives`` is the first tick on which it brings data from its source (see
    ``Module.input_ready``)."""
    label: str | None
    source: str
    shape: tuple
    index: Any
    arrives: int = 0

    @property
    def name(self) -> str:
        return self.label if self.label is not None else self.source

    def values(self, data: np.ndarray) -> np.ndarray:
        """This part's values in ``data`` (the input's array), in its own shape (a copy)."""
        return np.asarray(data).reshape(-1)[self.index].reshape(self.shape)


class Clock:
    """The kernel's clock as modules see it: read ``tick`` and ``time`` inside ``tick()``.
    ``lag`` is how many seconds late the tick started in real-time mode (its deadline is
    ``tick * tick_duration`` after the time base started); 0 in the other modes. ``run``
    is what the kernel tells about the run (its mode, stop tick, module and class counts,
    the last tick's compute time: see System), or None outside a network."""
    # (__weakref__: a standard module may keep per-network state keyed by the shared clock)
    __slots__ = ("tick", "tick_duration", "time", "real_time", "lag", "run", "__weakref__")

    def __init__(self, tick_duration: float = 0.0):
        self.tick = -1                  # first tick 0 (Ikaros 3 file: 1); one less in init
        self.tick_duration = tick_duration
        self.time = 0.0                 # nominal time: tick * tick_duration
        self.real_time = 0.0            # seconds since the run started
        self.lag = 0.0                  # seconds behind the real-time deadline
        self.run = None                 # the kernel's RunFacts


# Names the module API uses: a Python class may not give them to a parameter or port; one
# from an .ikc file or added at build time is held in an attribute with a trailing "_".
RESERVED = {"name", "path", "clock", "element", "init", "tick", "command", "stop", "configure",
            "set_sizes", "add_input", "add_output", "input_shape", "output_shape",
            "set_output_shape", "connected", "input_parts", "input_label", "notify", "print",
            "warning", "error", "fatal_error", "end_of_file", "description", "parameter_names",
            "state", "start_steps", "dialect", "input_ready", "c_random"}


def parameter_attribute(name: str) -> str:
    """The Python attribute that holds a parameter. A name the module API uses (an .ikc
    parameter called ``tick``) gets a trailing underscore: ``self.tick_``."""
    return name + "_" if name in RESERVED else name


_NONE_CONNECTED: frozenset[str] = frozenset()


def _class_ports(cls) -> tuple[dict, dict]:
    """A module class's inputs and outputs by name, made once per class description (a
    model of 10,000 modules then makes no dicts for them)."""
    ports = cls.__dict__.get("_ik_ports")
    if ports is None or ports[0] is not cls.description:
        desc = cls.description
        outputs = {s.name: s for s in desc.outputs}
        for st in desc.states:
            if st.type == "matrix":     # sized, allocated and bound like an output
                outputs[st.name] = OutputSpec(st.name, st.description, dict(st.rule),
                                              private=True)
        ports = (desc, {s.name: s for s in desc.inputs}, outputs)
        cls._ik_ports = ports
    return ports[1], ports[2]


class Module:
    """Base class of every module. Override ``tick`` (and ``init``, ``command``, ``stop``)."""

    description: ClassDescription   # set for every subclass by __init_subclass__
    ikc_description: bool = False   # True when the description came from an .ikc file

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        params, inputs, outputs, states = {}, {}, {}, {}
        renamed = set()     # reserved parameter names held in NAME_ (``init_ = Parameter(
        for klass in reversed(cls.__mro__):     # name="init")``), as for .ikc classes
            for key, value in vars(klass).items():
                if isinstance(value, Parameter):
                    spec = value.spec()
                    params[spec.name] = spec
                    if key == parameter_attribute(spec.name) != spec.name:
                        renamed.add(spec.name)
                elif isinstance(value, Input):
                    inputs[value.spec().name] = value.spec()
                elif isinstance(value, Output):
                    outputs[value.spec().name] = value.spec()
                elif isinstance(value, State):
                    states[value.spec().name] = value.spec()
        for name in [p for p in params if p not in renamed] + list(states) + \
                [_python_name(n) for n in list(inputs) + list(outputs)]:
            if name in RESERVED:
                raise TypeError(f"{cls.__name__}: '{name}' is a reserved name in the module API")
        state = getattr(cls, "state", ())
        if not isinstance(state, tuple) or not all(isinstance(n, str) and n.isidentifier()
                                                   for n in state):
            raise TypeError(f"{cls.__name__}.state must be a tuple of attribute names (the "
                            f"module's state kept by save, load and reset of the state)")
        twice = sorted((set(state) & set(states)) | {n for n in state if state.count(n) > 1}
                       | (set(states) & (set(params) | set(inputs) | set(outputs))))
        if twice:
            raise TypeError(f"{cls.__name__}: the state {', '.join(twice)} is declared twice "
                            f"(as state, parameter, input or output; a state item is bound "
                            f"to one variable)")
        doc = " ".join((cls.__doc__ or "").split())
        cls.description = ClassDescription(cls.__name__, doc, list(params.values()),
                                           list(inputs.values()), list(outputs.values()),
                                           list(states.values()))
        cls.ikc_description = False

    # --- set by the kernel before configure() --------------------------------------------
    name: str = ""
    path: str = ""
    element: Any = None             # the model-file element of this module (a language Node)
    user_data: str | None = None    # where files with relative names are written (-u DIR)
    # The Ikaros version the model file was written for: "2" (the paper's system, the default)
    # or "3". A class that Ikaros 2 and 3 compute differently reads it to give a file the
    # behaviour of its own version (docs/language.md says how the kernel decides it).
    dialect: str = "2"
    # The kernel's input buffers (set when they are made), which give input_parts and
    # input_label.
    _ik_input_buffers: dict = {}
    clock: Clock

    def __init__(self):
        self.clock = Clock()
        self._ik_notify: Callable[[int, "Module", str], None] = _print_notification
        # the class's ports, shared by its modules until add_input/add_output copies them
        self._ik_inputs: dict[str, InputSpec]
        self._ik_outputs: dict[str, OutputSpec]
        self._ik_inputs, self._ik_outputs = _class_ports(type(self))
        for st in self.description.states:
            if st.type != "matrix":
                setattr(self, st.name, st.default)
        self._ik_input_shapes: dict[str, tuple | None] = {}
        self._ik_output_shapes: dict[str, tuple | None] = {}
        self._ik_connected: frozenset[str] = _NONE_CONNECTED   # set by the kernel
        self._ik_start_steps = None     # the network's kernel.gating.StartSteps
        self._ik_arrivals: dict[str, np.ndarray] = {}    # input_ready's first ticks
        self._ik_c_random: CRandom | None = None          # the network's, set by the kernel

    @property
    def c_random(self) -> CRandom:
        """The C library's ``rand()`` as Ikaros 2 drew from it (glibc's, never seeded, so
        seed 1), one stream shared by all modules of a network: a class that draws from it
        in an Ikaros 2 file in the original's order gives the original's random numbers."""
        if self._ik_c_random is None:
            self._ik_c_random = CRandom()
        return self._ik_c_random

    # --- life cycle: override these ------------------------------------------------------
    def configure(self) -> None:
        """Build time, after parameters are set: add inputs or outputs that depend on them."""

    def set_sizes(self) -> None:
        """Build time, repeated until sizes settle: set output shapes the rules cannot give."""

    def init(self) -> None:
        """Called once before the first tick, in schedule order. Values written to outputs
        here are the value of tick -1: a delay-1 connection delivers them on tick 0."""

    def tick(self) -> None:
        """Called once per tick."""

    def command(self, name: str, x: float = 0, y: float = 0, value: Any = None) -> None:
        """A command from the user interface, called between ticks."""

    def stop(self) -> None:
        """Called once when the run ends."""

    def _ik_before_init(self) -> None:
        """Kernel-internal: called for every module of the schedule before the first
        ``init`` runs, to start what takes long in the background (a scripted module's
        worker process), so that all modules start theirs at once."""

    def _ik_not_initialised(self) -> None:
        """Kernel-internal: the start-up failed before this module's ``init`` ran or
        completed: release what ``_ik_before_init`` took. Safe to call more than once."""

    # --- build-time API ------------------------------------------------------------------
    def add_input(self, name: str, *, optional: bool = False, flatten: bool = False,
                  stack: bool = False, description: str = "", use_label: bool = False) -> None:
        """Add an input in ``configure`` (for inputs that depend on parameters)."""
        if self._ik_inputs is _class_ports(type(self))[0]:
            self._ik_inputs = dict(self._ik_inputs)
        self._ik_inputs[name] = InputSpec(name, description, optional, flatten, stack,
                                          use_label=use_label)

    def add_output(self, name: str, shape: tuple | int | str | None = None,
                   description: str = "", *, capacity: tuple | int | str | None = None
                   ) -> None:
        """Add an output in ``configure``; a tuple shape fixes its size now. With
        ``capacity`` (a tuple or a shape expression) and no shape it is a dynamic output."""
        if self._ik_outputs is _class_ports(type(self))[1]:
            self._ik_outputs = dict(self._ik_outputs)
        if capacity is not None:
            if shape is not None:
                raise TypeError("a dynamic output is sized by its capacity, not by a shape")
            text = capacity if isinstance(capacity, str) else ",".join(
                str(int(c)) for c in np.atleast_1d(capacity))
            self._ik_outputs[name] = OutputSpec(name, description, {"capacity": text},
                                                dynamic=True)
            return
        rule = {"shape": shape} if isinstance(shape, str) else {}
        self._ik_outputs[name] = OutputSpec(name, description, rule)
        if shape is not None and not isinstance(shape, str):
            self.set_output_shape(name, shape)

    def input_shape(self, name: str) -> tuple | None:
        """The shape of an input once known (None before; () for an unconnected one)."""
        return self._ik_input_shapes.get(name)

    def output_shape(self, name: str) -> tuple | None:
        return self._ik_output_shapes.get(name)

    def set_output_shape(self, name: str, shape: tuple | int) -> None:
        """Set an output's shape (in ``configure`` or ``set_sizes``)."""
        if name not in self._ik_outputs:
            raise KeyError(f"{self.path or self.name} has no output named {name}")
        self._ik_output_shapes[name] = (int(shape),) if isinstance(shape, (int, float, np.number)) \
            else tuple(int(s) for s in shape)

    def connected(self, name: str) -> bool:
        """Whether an input has at least one connection."""
        return name in self._ik_connected

    def start_steps(self) -> tuple[int | None, int | None]:
        """The module's start-up steps (Ikaros 3): the first tick on which data from a
        module without inputs reaches its first input, and all its inputs; (0, 0) without
        inputs, None where it never does. ``module_start="first_data"`` or ``"all_data"``
        on the element starts the module's ticks there. Known from ``init`` on."""
        steps = self._ik_start_steps
        return (0, 0) if steps is None else steps.of(self)

    def input_parts(self, name: str) -> list[InputPart]:
        """What each connection into an input contributes (from ``init`` on), in the order
        the connections are declared: label, source, shape and place in the input. Empty for
        an unconnected input."""
        buffer = self._ik_input_buffers.get(name)
        return buffer.parts() if buffer is not None else []

    def input_ready(self, name: str) -> np.ndarray:
        """Which elements of an input (flat, as booleans) hold data from their source on this
        tick: an element's connection has delivered what its source computed from data that
        began at modules without inputs (the source's start-up step, ``start_steps``, plus
        the connection's delay; a source that a loop feeds counts from its first step). Before
        that an element holds the zeros of the start, not a value the model asked for; an
        unconnected element is never ready. Drivers use it so that nothing moves at start-up."""
        arrives = self._ik_arrivals.get(name)
        if arrives is None:
            buffer = self._ik_input_buffers.get(name)
            size = buffer.size if buffer is not None else 0
            arrives = np.full(size, np.iinfo(np.int64).max, dtype=np.int64)
            for part in self.input_parts(name):
                arrives[np.asarray(part.index).reshape(-1)] = part.arrives
            self._ik_arrivals[name] = arrives
        return self.clock.tick >= arrives

    def input_label(self, name: str) -> str | None:
        """The label an input takes when it ``use_label``s (the class declares it, or the
        model says ``INPUT.use_label="yes"``) and exactly one of its connections has a
        ``label`` (from ``init`` on); None otherwise."""
        buffer = self._ik_input_buffers.get(name)
        return buffer.label() if buffer is not None else None

    # --- notifications -------------------------------------------------------------------
    def notify(self, level: int, message: str) -> None:
        self._ik_notify(level, self, message)

    def print(self, message: str) -> None:
        """Print a message through the kernel's log."""
        self._ik_notify(PRINT, self, str(message))

    def warning(self, message: str) -> None:
        self._ik_notify(WARNING, self, str(message))

    def error(self, message: str) -> None:
        """Report an error; the run goes on."""
        self._ik_notify(EXCEPTION, self, str(message))

    def fatal_error(self, message: str) -> None:
        """Report an error that stops the run after the current tick (exit status 1)."""
        self._ik_notify(FATAL_ERROR, self, str(message))

    def end_of_file(self, message: str = "end of file") -> None:
        """Stop the run cleanly after the current tick (exit status 0)."""
        self._ik_notify(END_OF_FILE, self, str(message))


def _print_notification(level: int, module: Module, message: str) -> None:
    print(f"{LEVEL_NAMES.get(level, level)}: {message} ({module.path or module.name})")


def compiled(function: Callable) -> staticmethod:
    """Marks a module's compiled tick: a function of the module's arrays and parameters,
    written in the subset of Python that numba compiles, that computes what ``tick``
    computes. Its arguments are named after the module's inputs and outputs (flat float32
    arrays; an unconnected optional input is an empty array) and its number, int and bool
    parameters (float32 values, read before every tick). With numba installed
    (``ikaros[fast]``) the kernel runs it instead of ``tick``, many modules per call::

        @compiled
        def compiled_tick(INPUT, OUTPUT, rate):
            for i in range(OUTPUT.size):
                OUTPUT[i] += rate * (INPUT[i] - OUTPUT[i])

    See docs/writing-modules.md."""
    setattr(function, "_ik_compiled", True)
    return staticmethod(function)
