"""AsyncLifecycleTestModule: a slow tick that checks its view of the run stays still."""
import time

import numpy as np

from ikaros.module import Input, Output, Parameter, State

from ikaros.testsupport._internal import InternalModule


class AsyncLifecycleTestModule(InternalModule):
    """Each tick takes ``duration`` seconds and then adds 1 to ``completed`` (int state) and
    sets OUTPUT to it.
    With ``async="yes"`` the kernel runs the tick in the background while the network goes
    on; the tick checks that what it sees does not change meanwhile: its clock and its INPUT
    (optional) are the same at the end of the tick as at the start, or it reports
    ``ASYNC_RUNTIME_SNAPSHOT_CHANGED`` as a fatal error. When the run ends it prints
    ``ASYNC completed=n`` and, if n > 0 and nothing changed, ``ASYNC_RUNTIME_SNAPSHOT_STABLE``.
    Commands: ``mark`` prints ``COMMAND mark after completed=n``; ``fail`` raises
    ``COMMAND_FATAL <name>``."""

    duration = Parameter(0.01, "seconds each tick takes")
    INPUT = Input("anything; it must not change during a tick", optional=True)
    OUTPUT = Output("ticks completed", shape="1")
    completed = State(0, "ticks completed")

    def init(self):
        self._changed = False

    def tick(self):
        tick, seen = self.clock.tick, None if self.INPUT is None else self.INPUT.copy()
        time.sleep(self.duration)
        if self.clock.tick != tick or (seen is not None and
                                       not np.array_equal(seen, self.INPUT)):
            self._changed = True
            self.fatal_error(f"ASYNC_RUNTIME_SNAPSHOT_CHANGED during tick {tick}")
        self.completed += 1
        self.OUTPUT[0] = self.completed

    def command(self, name, x=0, y=0, value=None):
        if name == "fail":
            raise RuntimeError(f"COMMAND_FATAL {self.name}")
        self.print(f"COMMAND {name} after completed={self.completed}")

    def stop(self):
        self.print(f"ASYNC completed={self.completed}")
        if self.completed and not self._changed:
            self.print("ASYNC_RUNTIME_SNAPSHOT_STABLE")
