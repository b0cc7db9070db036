"""A module whose stop() raises."""
from ikaros.module import Module, Output


class StopFails(Module):
    """Raises in stop."""
    OUTPUT = Output("nothing", size_x="1")

    def stop(self):
        raise RuntimeError("stop broke")
