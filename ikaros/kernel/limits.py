"""The memory check of a build, made before the arena is allocated (see ikaros.limits)."""
from __future__ import annotations

import math

from ..limits import BYTES_PER_ELEMENT, LimitError, check_bytes, format_bytes
from .memory import Arena


def check_memory(arena: Arena, requests: list, deepest: dict) -> None:
    """Refuse buffers and delay rings that together pass the memory limit, naming the
    largest of them; and a machine that cannot give the memory."""
    ring_bytes = {src: (depth - 1) * math.prod(src.shape) * BYTES_PER_ELEMENT
                  for src, depth in deepest.items() if depth >= 2}
    total = arena.planned_bytes() + sum(ring_bytes.values())
    try:
        check_bytes(total, "the model's buffers and delay rings")
        try:
            import numpy as np
            np.empty(total // BYTES_PER_ELEMENT + 1, dtype=np.float32)   # freed at once
        except MemoryError:
            raise LimitError(f"the model's buffers and delay rings need "
                             f"{format_bytes(total)}, more memory than this process can "
                             f"get") from None
    except LimitError as e:
        sizes = [(math.prod(buf.shape) * BYTES_PER_ELEMENT, buf, "buffer")
                 for buf, _ in requests]
        sizes += [(n, src, "delay ring") for src, n in ring_bytes.items()]
        nbytes, buf, kind = max(sizes, key=lambda item: item[0])
        raise buf.node.error(f"{e}; the largest is the {kind} of {buf.path} "
                             f"({format_bytes(nbytes)})") from None
