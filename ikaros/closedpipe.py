"""A reader that closes the pipe early (``ikaros --classes | head``) ends a command quietly,
as Unix tools do: no ``BrokenPipeError`` traceback, exit status 141 (128 + SIGPIPE, what a
shell reports for a tool that SIGPIPE ended). A run whose printed lines find the pipe closed
ends after its tick (``print_line`` tells the kernel)."""
from __future__ import annotations

import os
import sys
from typing import Callable

EXIT_CLOSED_PIPE = 141

_closed = False


def _silence_stdout() -> None:
    """Point standard output where writes succeed (the interpreter flushes it at exit)."""
    global _closed
    _closed = True
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())
    os.close(devnull)


def print_line(text: str) -> bool:
    """Write one line to standard output at once; False when its reader has gone."""
    if _closed:
        return False
    try:
        print(text + "\n", end="", flush=True)
        return True
    except BrokenPipeError:
        _silence_stdout()
        return False


def run_command(main: Callable[..., int], *args) -> int:
    """``main(*args)``, its output flushed; a closed standard output ends it quietly."""
    try:
        code = main(*args)
        sys.stdout.flush()
    except BrokenPipeError:
        _silence_stdout()
    return EXIT_CLOSED_PIPE if _closed else code
