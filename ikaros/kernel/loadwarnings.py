"""A module's warning before the first tick (in its configure or init) is a load-time model
warning: it names the file, the line of the module's element and the module, is kept with
the load's other warnings, and is refused under --strict. Warnings during ticks stay
messages of the run (the network's log)."""
from __future__ import annotations

from typing import Callable

from ..language.diagnostics import Diagnostics, ModelWarning
from ..module import WARNING, Module

Notify = Callable[[int, Module, str], None]


def module_warning(diagnostics: Diagnostics, module: Module, message: str) \
        -> ModelWarning | None:
    """Give ``message`` as a model warning at the module's element (None: given before)."""
    node = module.element
    element = node.label()
    if module.path != module.name:
        element += f" ({module.path})"
    return diagnostics.warn(message, node.file, node.line, element, module.path)


def configuring(diagnostics: Diagnostics, otherwise: Notify) -> Notify:
    """A module's notify while it is configured (before the network exists): a warning is a
    model warning, anything else goes to ``otherwise``."""
    def notify(level: int, module: Module, message: str) -> None:
        if level == WARNING:
            module_warning(diagnostics, module, message)
        else:
            otherwise(level, module, message)
    return notify
