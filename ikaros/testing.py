"""Helpers for testing modules and models with pytest."""
from __future__ import annotations

import os

from .kernel.network import Network


def load_body(folder, body: str, /, **overrides) -> Network:
    """Write ``body`` (module and connection elements) inside ``<group name="Test">`` to
    ``folder/model.ikg`` and load it; keyword arguments override top-group attributes::

        net = load_body(tmp_path, '<module class="Constant" name="C" data="1 2"/>')
    """
    from . import load
    path = os.path.join(str(folder), "model.ikg")
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'<group name="Test">\n{body}\n</group>\n')
    return load(path, **overrides)
