"""Helpers for tests of modules that look at image sequences: a ``Frames`` module, written
into the test's folder, plays frames saved in a .npy file, one per tick."""
import numpy as np

from ikaros.testing import load_body

FRAMES_MODULE = '''
import numpy as np
from ikaros import Module, Output, Parameter


class Frames(Module):
    """Plays the frames of a .npy file, frame k on the (k+1)-th tick (in either dialect)."""
    file = Parameter("", "the .npy file")
    OUTPUT = Output("the frame")

    def configure(self):
        self._frames = np.load(self.file)
        self.set_output_shape("OUTPUT", self._frames.shape[1:])

    def init(self):
        self.OUTPUT[...] = self._frames[0]
        self._played = 0

    def tick(self):
        self.OUTPUT[...] = self._frames[min(self._played, len(self._frames) - 1)]
        self._played += 1
'''


def load_sequence(tmp_path, frames, body: str, **overrides):
    """Load a model with a ``Frames`` module named F that plays ``frames`` (frame k on tick
    k), and the elements in ``body`` (which connect F.OUTPUT where they need it)."""
    (tmp_path / "Frames.py").write_text(FRAMES_MODULE)
    np.save(tmp_path / "frames.npy", np.asarray(frames, np.float32))
    return load_body(tmp_path, f'<module class="Frames" name="F" file="{tmp_path}/frames.npy"/>'
                     f'\n{body}', **overrides)


def run_sequence(tmp_path, frames, module: str, *names: str, connect="INPUT", **overrides):
    """Run ``module`` (an element named M) on the frames, input ``connect`` fed with delay 0,
    and return, per tick, copies of the named outputs of M (``overrides`` as load_body's)."""
    net = load_sequence(tmp_path, frames, module + f'\n<connection source="F.OUTPUT" '
                        f'target="M.{connect}" delay="0"/>', **overrides)
    results = []
    with net:
        for _ in range(len(frames)):
            net.step()
            results.append([net.output(f"M.{n}").copy() for n in names])
    return results
