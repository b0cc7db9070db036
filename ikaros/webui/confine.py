"""The editor's reach: what a model sent through the web UI may touch.

A model applied, opened or created in the web UI is built confined to the models folder
(``--models``) and the folder of the model the server started with (both chosen on the
command line): includes, ``external`` group files, class folders (``path=``) and file
parameters must be relative names inside them. The standard library's classes and those of
installed packages stay available. See docs/webui.md, "Who can do what".
"""
from __future__ import annotations

import os

from ..access import AccessRefused, Confinement, is_file_parameter


def editor_confinement(models_dir: str | None, start_folder: str | None) -> Confinement:
    """The confinement of the editor's builds."""
    return Confinement([models_dir, start_folder])


def check_parameter_value(confinement: Confinement, spec, value, model_file: str) -> None:
    """Refuse a file parameter set from the web UI that names a file outside the folders
    (raises AccessRefused)."""
    if isinstance(value, str) and value.strip() and is_file_parameter(spec):
        confinement.check(value.strip(), os.path.dirname(os.path.abspath(model_file)),
                          f'parameter "{spec.name}"')


__all__ = ["AccessRefused", "check_parameter_value", "editor_confinement"]
