"""Finding classes: the standard library, folders beside the model, ``path`` attributes, and
installed packages (entry point group ``ikaros.modules``)."""
from __future__ import annotations

import hashlib
import importlib
import importlib.util
import io
import os
import sys
import tokenize
from dataclasses import dataclass
from importlib.metadata import entry_points

from ..description import ClassDescription
from ..errors import ModelError
from ..interrupt import fault_text, is_interrupt, module_faults
from ..language.classfile import read_class_file
from ..language.diagnostics import warn, warn_at
from ..language.reader import read_file
from ..module import Module
from ..scripted import script_class, script_of

STDLIB = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "modules")
# The test-only classes of the original's kernel tests: found by name after every other
# class (so any class of that name elsewhere wins), never listed.
TESTSUPPORT = os.path.join(os.path.dirname(STDLIB), "testsupport")
ENTRY_POINT_GROUP = "ikaros.modules"


@dataclass
class ClassEntry:
    """Where a class is declared. ``python`` and ``ikc`` are files; ``group`` is an .ikg file
    used as a class; ``loaded`` is a class object from an entry point; ``implementation`` is
    the entry (a plugin's or the standard library's) that implements an .ikc found alone;
    ``script`` is the Python script of an .ikc whose code runs in a worker process."""
    name: str
    python: str | None = None
    ikc: str | None = None
    script: str | None = None
    group: str | None = None
    package: str | None = None        # the import name of a standard-library module file
    loaded: type | None = None
    implementation: "ClassEntry | None" = None
    _cls: type | None = None
    _desc: ClassDescription | None = None

    @property
    def is_group(self) -> bool:
        return self.group is not None and self.python is None and self.ikc is None \
            and self.loaded is None

    def module_class(self) -> type[Module]:
        """The Python class that runs instances."""
        if self._cls is None:
            self._cls = self._load()
        return self._cls

    def description(self) -> ClassDescription:
        if self._desc is None:
            self.module_class()
        return self._desc

    def _load(self) -> type[Module]:
        if self.implementation is not None:
            cls = self.implementation.module_class()
            _check_interface(self.ikc, cls.description)
            self._desc = cls.description
            return cls
        if self.script is not None:
            return self._scripted()
        cls = self.loaded
        if cls is None and self.python:
            module = _import_file(self.python, self.package)
            cls = getattr(module, self.name, None)
            if not (isinstance(cls, type) and issubclass(cls, Module)):
                raise ModelError(f'file does not define a Module subclass named "{self.name}"',
                                 self.python)
        if self.ikc:
            if cls is None:
                raise ModelError(f"class {self.name} is declared in "
                                 f"{os.path.basename(self.ikc)} but has no implementation "
                                 f"(no {self.name}.py beside it, no installed plugin and no "
                                 f"standard class of that name)")
            desc = read_class_file(self.ikc)
            if _declares_anything(cls):
                raise ModelError(f'class "{self.name}" is declared twice: in Python '
                                 f'({self.python}) and in its .ikc file; keep one', self.ikc)
            cls = type(self.name, (cls,), {"__module__": cls.__module__})
            cls.description = desc
            cls.ikc_description = True
        if cls is None:
            raise ModelError(f'class "{self.name}" has no code and no .ikc file')
        self._desc = cls.description
        if not self._desc.source:
            self._desc.source = self.python or self.ikc or getattr(cls, "__module__", "")
        return cls


    def _scripted(self) -> type[Module]:
        """The class of an .ikc whose code is a Python script (docs/python-scripts.md)."""
        root = read_file(self.ikc)
        if not os.path.isfile(self.script):
            raise ModelError(f'class {self.name} names the script '
                             f'python="{root.attrs.get("python")}", which does not exist '
                             f'({self.script})', self.ikc, root.line, root.label())
        try:
            cls = script_class(read_class_file(self.ikc), self.script, root.attrs)
        except ValueError as e:
            raise ModelError(str(e), self.ikc, root.line, root.label()) from None
        self._desc = cls.description
        self._desc.source = self._desc.source or self.ikc
        return cls


def _check_interface(ikc: str, implemented: ClassDescription) -> None:
    """An .ikc beside a model for a class implemented elsewhere: what the .ikc declares and
    the implementation lacks is an error (outputs, required inputs) or a warning (parameters
    and optional inputs, which nothing reads), naming the .ikc element."""
    declared = read_class_file(ikc)
    root = read_file(ikc)
    has = {"output": {s.name for s in implemented.outputs},
           "input": {s.name for s in implemented.inputs},
           "parameter": {s.name for s in implemented.parameters},
           "state": {s.name for s in implemented.states}}
    optional = {s.name for s in declared.inputs if s.optional}
    source = implemented.source or "the standard library"
    for tag in ("output", "input", "parameter", "state"):
        for element in root.elements(tag):
            name = element.get("name")
            if name in has[tag]:
                continue
            message = (f"the implementation of class {declared.name} ({source}) has no "
                       f'{tag} "{name}"')
            if tag == "output" or (tag == "input" and name not in optional):
                raise element.error(message)
            warn_at(element, f"{message}; ignored")


def _declares_anything(cls: type[Module]) -> bool:
    d = cls.description
    return bool(d.parameters or d.inputs or d.outputs or d.states)


def _import_file(path: str, package: str | None):
    if package:
        try:
            return importlib.import_module(package)
        except module_faults() as e:  # a broken module file is a model error naming it
            if is_interrupt(e):
                raise
            raise _import_error(e, path) from None
    key = "ikaros_user_" + hashlib.sha1(os.path.abspath(path).encode()).hexdigest()[:12] + \
        "_" + os.path.splitext(os.path.basename(path))[0]
    if key in sys.modules:
        return sys.modules[key]
    spec = importlib.util.spec_from_file_location(key, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[key] = module
    try:
        spec.loader.exec_module(module)
    except module_faults() as e:
        del sys.modules[key]
        if is_interrupt(e):
            raise
        raise _import_error(e, path) from None
    return module


def _import_error(e: BaseException, path: str) -> ModelError:
    """A module file that cannot be imported, with the package it misses if that is why."""
    missing = getattr(e, "name", None) if isinstance(e, ImportError) else None
    hint = f" (the package may be installed with: pip install {missing})" if missing else ""
    return ModelError(f"cannot import: {fault_text(e)}{hint}", path)


def _scan(folder: str, recursive: bool, package_root: str | None = None) -> dict[str, ClassEntry]:
    """Class files in a folder: ``Name.py``, ``Name.ikc`` and ``Name.ikg``, keyed by name."""
    found: dict[str, ClassEntry] = {}
    if not os.path.isdir(folder):
        return found
    walker = os.walk(folder) if recursive else [(folder, [], os.listdir(folder))]
    for dirpath, dirnames, files in walker:
        dirnames[:] = sorted(d for d in dirnames
                             if not d.startswith(("_", ".")) and d != "tests")
        for file in sorted(files):
            stem, ext = os.path.splitext(file)
            if ext not in (".py", ".ikc", ".ikg") or stem.startswith(("_", "test_", ".")):
                continue
            full = os.path.join(dirpath, file)
            entry = found.setdefault(stem, ClassEntry(stem))
            kind = {"py": "python", "ikc": "ikc", "ikg": "group"}[ext[1:]]
            existing = getattr(entry, kind)
            if existing and os.path.dirname(existing) != dirpath:
                raise ModelError(f'class "{stem}" is found in more than one place: {existing} '
                                 f'and {full}', full)
            if kind == "python":
                entry.python = full
                if package_root:
                    rel = os.path.relpath(full, package_root)[:-3].replace(os.sep, ".")
                    entry.package = "ikaros.modules." + rel
            elif kind == "ikc":
                entry.ikc = full
            else:
                entry.group = full
    # A Python file that is not next to a class's .ikc and does not define the class is a
    # helper, not a class; such files are filtered when loaded.
    return found


_stdlib_cache: dict[str, ClassEntry] | None = None
_entry_point_cache: dict[str, ClassEntry] | None = None


def stdlib_classes() -> dict[str, ClassEntry]:
    global _stdlib_cache
    if _stdlib_cache is None:
        _stdlib_cache = _scan(STDLIB, recursive=True, package_root=STDLIB)
    return _stdlib_cache


def entry_point_classes() -> dict[str, ClassEntry]:
    """Classes installed by other packages under the ``ikaros.modules`` entry point group.

    An entry point names a Module subclass (``Name = "pkg.mod:Name"``) or a package whose
    folder holds class files (``anything = "pkg.modules"``).
    """
    global _entry_point_cache
    if _entry_point_cache is None:
        _entry_point_cache = {}
        for ep in entry_points(group=ENTRY_POINT_GROUP):
            try:
                obj = ep.load()
            except Exception as e:
                print(f"ikaros: warning: entry point {ep.name} = {ep.value} failed to load: {e}",
                      file=sys.stderr)
                continue
            if isinstance(obj, type) and issubclass(obj, Module):
                _entry_point_cache[ep.name] = ClassEntry(ep.name, loaded=obj)
            elif hasattr(obj, "__path__"):
                for folder in obj.__path__:
                    _entry_point_cache.update(_scan(folder, recursive=True))
    return _entry_point_cache


class ClassRegistry:
    """Looks classes up: first the model's own folders, then installed packages, then the
    standard library."""

    def __init__(self, folders: list[str] = ()):
        self.folders = [os.path.abspath(f) for f in folders]
        self._folder_cache: dict[str, dict[str, ClassEntry]] = {}
        self._found: dict[tuple, ClassEntry | None] = {}

    def _in_folder(self, folder: str) -> dict[str, ClassEntry]:
        folder = os.path.abspath(folder)
        if folder not in self._folder_cache:
            self._folder_cache[folder] = _scan(folder, recursive=False)
        return self._folder_cache[folder]

    def find(self, name: str, extra_folders: list[str] = (),
             skip_files: tuple = ()) -> ClassEntry | None:
        """The class called ``name``; ``extra_folders`` (a module's ``path``) are searched
        first. Group files in ``skip_files`` (the files being built) are passed over, so a
        model named after a class can use that class."""
        key = (name, tuple(extra_folders), skip_files)
        if key not in self._found:
            self._found[key] = self._find(name, extra_folders, skip_files)
        return self._found[key]

    def _find(self, name: str, extra_folders, skip_files) -> ClassEntry | None:
        for folder in list(extra_folders) + self.folders:
            entry = self._in_folder_found(folder, name, skip_files)
            if entry is not None:
                return entry
        return entry_point_classes().get(name) or stdlib_classes().get(name) or \
            self._in_folder_found(TESTSUPPORT, name, skip_files)

    def _in_folder_found(self, folder: str, name: str, skip_files) -> ClassEntry | None:
        """The class ``name`` as the files of one folder declare it, or None."""
        entry = self._in_folder(folder).get(name)
        if entry is None or (entry.is_group and entry.group in skip_files):
            return None
        if entry.python and not _defines_class(entry.python, entry.name):
            entry.python = None         # a script beside the model, not a module
        if entry.group and (entry.python or entry.ikc):
            raise ModelError(f'class "{name}" is declared by two class files in one '
                             f'folder: {entry.python or entry.ikc} and {entry.group}; '
                             f'keep one', entry.group)
        if entry.ikc and entry.python is None:
            return self._implemented(entry)
        if entry.python or entry.group:
            return entry
        return None

    def _implemented(self, entry: ClassEntry) -> ClassEntry:
        """An .ikc alone declares an interface: a plugin or the standard library may
        implement it. An .ikc whose <group> root holds modules is a group class (Ikaros 3)."""
        if _is_composite(entry.ikc):
            entry.group, entry.ikc = entry.ikc, None
            return entry
        entry.script = script_of(entry.ikc, read_file(entry.ikc).attrs,
                                 lambda path: _defines_class(path, entry.name))
        if entry.script is not None:
            return entry
        found = entry_point_classes().get(name := entry.name) or stdlib_classes().get(name)
        if found is not None and not found.is_group:
            entry.implementation = found
        return entry

    def all(self) -> dict[str, ClassEntry]:
        merged = dict(stdlib_classes())
        merged.update(entry_point_classes())
        for folder in self.folders:
            for name in self._in_folder(folder):
                entry = self.find(name)
                if entry is not None:
                    merged[name] = entry
        return merged


def _is_composite(ikc: str) -> bool:
    root = read_file(ikc)
    return root.tag == "group" and next(root.elements("module"), None) is not None


def _defines_class(path: str, name: str) -> bool:
    """Whether a user folder's Python file defines a Module class called ``name`` (a cheap
    text check, so helper scripts and scripts for other programs beside a model are not
    imported: a module of this project uses ikaros). The file is read as Python reads it
    (its coding declaration, else UTF-8); one that cannot be read so is looked at as bytes
    (importing it then says what is wrong with it, naming it)."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError:
        return False
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(raw).readline)
        text = raw.decode(encoding)
    except (SyntaxError, UnicodeDecodeError):
        return f"class {name}(".encode() in raw and b"ikaros" in raw
    return f"class {name}(" in text and "ikaros" in text


def classes(folders: list[str] = ()) -> dict[str, ClassDescription]:
    """{class name: class description} of every class found (group files are left out)."""
    out = {}
    for name, entry in sorted(ClassRegistry(folders).all().items()):
        if entry.is_group:
            continue
        try:
            desc = entry.description()
        except ModelError as e:     # a broken class beside a model does not hide the rest
            warn(f"class {name} left out: {e.reason}", e.filename, e.line)
            continue
        if not desc.internal:
            out[name] = desc
    return out
