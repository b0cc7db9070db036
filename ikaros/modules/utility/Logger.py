"""Logger: kept so Ikaros 2 models that use it still load; it does nothing."""
from ikaros.module import Module


class Logger(Module):
    """Does nothing. In Ikaros 2 this module sent an anonymous start-up message about the run
    to the Ikaros web site; here it sends nothing over the network and writes nothing
    anywhere outside the model: no files, no output, no messages. It has no parameters,
    inputs or outputs, like the original, so models that include it load and run
    unchanged."""

    def tick(self):
        pass
