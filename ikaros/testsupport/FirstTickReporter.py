"""FirstTickReporter: prints the number of its first tick."""
from ikaros.module import Input, Output

from ikaros.testsupport._internal import InternalModule


class FirstTickReporter(InternalModule):
    """Prints ``FIRST_TICK tick=t`` on the first tick it runs, and its INPUT's first
    element (if connected) as ``data=v``. OUTPUT is the number of ticks it ran."""

    INPUT = Input("anything", optional=True)
    OUTPUT = Output("ticks run", shape="1")

    def tick(self):
        if self.OUTPUT[0] == 0:
            data = f" data={self.INPUT.flat[0]:g}" if self.INPUT is not None and \
                self.INPUT.size else ""
            self.print(f"FIRST_TICK tick={self.clock.tick}{data}")
        self.OUTPUT[0] += 1
