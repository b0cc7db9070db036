from ikaros.module import Module, Output, Parameter


class Fail(Module):
    """Fails at tick ``at``: with a fatal error, an exception, or end of file (for tests)."""
    at = Parameter(2, "the tick at which to fail", type="int")
    how = Parameter("fatal", "fatal, raise or eof", options="fatal,raise,eof")
    OUTPUT = Output("the tick", size="1")

    def tick(self):
        self.OUTPUT[0] = self.clock.tick
        if self.clock.tick == self.at:
            if self.how == "fatal":
                self.fatal_error("broken at tick %d" % self.at)
            elif self.how == "raise":
                raise RuntimeError("boom")
            else:
                self.end_of_file()

    def stop(self):
        self.print("stopped at tick %d" % self.clock.tick)
