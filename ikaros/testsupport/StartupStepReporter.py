"""StartupStepReporter: prints its start-up steps."""
from ikaros.module import Input, Output

from ikaros.testsupport._internal import InternalModule


class StartupStepReporter(InternalModule):
    """Prints ``first=F all=A`` in init: its start-up steps, the first tick on which data
    from a module without inputs reaches its first input, and all its inputs (``never``
    where none does). OUTPUT is the number of ticks it ran."""

    INPUT = Input("anything", optional=True)
    OUTPUT = Output("ticks run", shape="1")

    def init(self):
        first, every = (("never" if s is None else str(s)) for s in self.start_steps())
        self.print(f"first={first} all={every}")

    def tick(self):
        self.OUTPUT[0] += 1
