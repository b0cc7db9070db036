"""User modules' compiled ticks (``@compiled`` in ikaros/module.py).

For each class the kernel writes a small runner module into a cache folder: one numba
function, cached on disk, that runs the class's compiled tick for a table of instances
(each row: the instance's zero-delay copies as a range of the network's instructions, its
first parameter slot, then offset and size of each array argument). It notes the row it
is at, so that an error (an index out of range) names its module. The runner's file name
carries a hash of the class's compiled tick, so editing the tick compiles a new runner; the
first build after that waits for numba (about a second), later ones load from the cache.
"""
from __future__ import annotations

import hashlib
import importlib.util
import inspect
import os
import sys
import tempfile
import textwrap

from ...module import attribute_name
from .emit import Fragment

NUMERIC = ("number", "int", "bool")
_runners: dict = {}          # (class, layout) -> the runner function


def compiled_tick(cls):
    """The class's ``@compiled`` function, or None (also when a subclass overrides ``tick``
    of the class that declared it)."""
    for klass in cls.__mro__:
        value = vars(klass).get("compiled_tick")
        if value is not None:
            function = getattr(value, "__func__", value)
            if not getattr(function, "_ik_compiled", False) or cls.tick is not klass.tick:
                return None
            return function
    return None


def layout(module, function) -> tuple | None:
    """The tick's arguments as ("array", port) or ("param", name), or None when one of
    them is neither a port nor a number, int or bool parameter."""
    params = {spec.name: spec for spec in module.description.parameters}
    ports = set(module._ik_inputs) | set(module._ik_outputs)
    out = []
    for name in inspect.signature(function).parameters:
        port = next((p for p in ports if attribute_name(p) == name), None)
        if port is not None:
            out.append(("array", port))
        elif name in params and params[name].type in NUMERIC:
            out.append(("param", name))
        else:
            return None
    return tuple(out)


def user_fragment(module, inputs: dict, outputs: dict, args: tuple):
    """The instance's row (without its copy range) and its parameter loader."""
    frag = Fragment()
    names = [name for kind, name in args if kind == "param"]
    first = frag.slots(len(names))
    row = [first]
    for kind, name in args:
        if kind == "array":
            buf = inputs.get(name) or outputs.get(name)
            if buf is None or buf.array is None:
                row += [0, 0]
            else:
                row += [buf.offset, buf.size]
    frag.rows.append(tuple(row))

    def load(params, base):
        try:
            for k, name in enumerate(names):
                params[base + first + k] = float(getattr(module, name))
        except (TypeError, ValueError):
            return False
        return True
    return frag, load


def _folder() -> str:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    for folder in (os.path.join(base, "ikaros", "compiled"),
                   os.path.join(tempfile.gettempdir(), f"ikaros-compiled-{os.getuid()}")):
        try:
            os.makedirs(folder, exist_ok=True)
            if os.access(folder, os.W_OK):
                return folder
        except OSError:
            continue
    raise OSError("no writable folder for the compiled ticks of user modules")


def _source(cls, args: tuple, function) -> str:
    call, column = [], 3
    for kind, _ in args:
        if kind == "array":
            call.append(f"block[r[{column}]:r[{column}] + r[{column + 1}]]")
            column += 2
    params = iter(range(len(args)))
    parts, arrays = [], iter(call)
    for kind, _ in args:
        parts.append(next(arrays) if kind == "array" else f"params[r[2] + {next(params)}]")
    return textwrap.dedent(f'''\
        # written by ikaros for {cls.__module__}.{cls.__qualname__}.compiled_tick
        import sys
        from numba import njit
        from ikaros.kernel.compiled.kernel import execute

        tick = njit(cache=True, boundscheck=True)(
            sys.modules[{cls.__module__!r}].{cls.__qualname__}.compiled_tick)


        @njit(cache=True)
        def run(block, rows, first, last, params, code, cparams, pool, flags, where):
            for k in range(first, last):
                where[0] = k
                r = rows[k]
                if r[0] < r[1]:
                    execute(block, code, r[0], r[1], cparams, pool, flags)
                tick({", ".join(parts)})
            return 0
        ''')


def runner(cls, args: tuple, function):
    """The numba runner of a class's compiled tick for this argument layout."""
    key = (cls, args)
    if key not in _runners:
        source = _source(cls, args, function)
        try:
            body = inspect.getsource(function)
        except (OSError, TypeError):
            body = function.__code__.co_code.hex()
        digest = hashlib.sha1((source + body).encode()).hexdigest()[:16]
        path = os.path.join(_folder(), f"{cls.__name__}_{digest}.py")
        if not os.path.exists(path):
            partial = f"{path}.{os.getpid()}.tmp"
            with open(partial, "w", encoding="utf-8") as f:
                f.write(source)
            os.replace(partial, path)
        name = f"ikaros_compiled_{cls.__name__}_{digest}"
        spec = importlib.util.spec_from_file_location(name, path)
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
        _runners[key] = module.run
    return _runners[key]
