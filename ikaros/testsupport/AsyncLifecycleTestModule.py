"""AsyncLifecycleTestModule: a slow tick for asynchronous runs."""
import time

from ikaros.module import Output, Parameter

from ikaros.testsupport._internal import InternalModule


class AsyncLifecycleTestModule(InternalModule):
    """Each tick sleeps ``duration`` seconds, then adds 1 to OUTPUT (the ticks completed).
    Prints ``ASYNC completed=n`` when the run ends. With ``async="yes"`` the kernel
    runs the tick in the background and publishes OUTPUT when it is done."""

    duration = Parameter(0.01, "seconds each tick takes")
    OUTPUT = Output("ticks completed", shape="1")

    def init(self):
        self._completed = 0

    def tick(self):
        time.sleep(self.duration)
        self._completed += 1
        self.OUTPUT[0] = self._completed

    def stop(self):
        self.print(f"ASYNC completed={self._completed}")
