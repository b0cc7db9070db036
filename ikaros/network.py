"""The network a user gets from ``ikaros.load`` and ``Group.build``: the kernel's network, and
what joins it to the parts above the kernel — recording (``record``, ``run(record=...)``) and
notebooks (an HTML table, the web UI in a cell, a progress bar). The kernel knows none of
them."""
from __future__ import annotations

import os
from typing import Sequence, cast

from . import notebook
from .errors import ModelError
from .experiments.memory import run_recorded
from .experiments.recorders import open_recorder
from .kernel.builder import Builder
from .kernel.codeclasses import CodeClassRegistry
from .kernel.network import Network as KernelNetwork
from .language.diagnostics import Diagnostics
from .limits import LimitError, Limits
from .links.split import SplitNetwork as KernelSplitNetwork, make_network


class Network(KernelNetwork):
    """A runnable model. Build one with ``ikaros.load``.

    ``tick`` is the number of ticks completed; the first tick is tick 0.
    """

    def run(self, ticks: int | None = None, real_time: bool = False,
            record: list[str] | str | None = None, every: int = 1):
        """Run ``ticks`` more ticks (as fast as possible, or on the tick_duration time base
        with ``real_time``). Without ``ticks``, run until the model's ``stop`` tick, end of
        file or an error. Returns ``tick``, the ticks completed so far.

        With ``record`` (glob patterns of output addresses; ``"*"`` for all) the outputs
        that match are kept every ``every``-th tick and returned as an xarray Dataset
        instead (see ``ikaros.experiments``)."""
        self._check_running()
        if record is not None:
            return run_recorded(self, ticks, record, every, real_time)
        if ticks is not None and ticks > 1 and notebook.in_notebook():   # a progress bar in the cell
            return notebook.run_with_progress(
                self, lambda: super(Network, self).run(ticks, real_time), ticks)
        return super().run(ticks, real_time)

    def show(self, width: int | str = "100%", height: int = 600):
        """Show the web UI's views of this network in a notebook cell (served on 127.0.0.1
        by a background thread that stops with the kernel)."""
        return notebook.show(self, width, height)

    def _repr_html_(self) -> str:
        return notebook.network_html(self)

    def record(self, filename: str, only: list[str] | str | None = None, every: int = 1,
               flush_seconds: float = 1.0, on_error: str = "stop",
               images: Sequence[str] | str = (), joint_states: Sequence[str] | str = ()):
        """Record outputs (all, or those matching the glob patterns ``only``) every
        ``every``-th tick into the HDF5 file ``filename``, from the next tick until the
        returned Recorder's ``close()`` or this network's ``close()``. A ``.mcap`` file
        holds the outputs as ROS 2 messages (experiments/mcap_recording.py): colour images
        and the gray images the views show as sensor_msgs/Image, the gray ones matching
        ``images`` too, the joint positions matching ``joint_states`` as
        sensor_msgs/JointState. The rows are flushed at least every ``flush_seconds``; when
        writing fails the run stops (``on_error="stop"``) or goes on without recording
        (``"continue"``)."""
        return open_recorder(self, filename, only=only, every=every,
                             flush_seconds=flush_seconds, on_error=on_error, images=images,
                             joint_states=joint_states)


Builder.network_class = Network       # every build makes one (the kernel does not know it)


class SplitNetwork(KernelSplitNetwork, Network):
    """A network whose groups with a ``process`` attribute run in other kernel processes
    (docs/links.md)."""


def load(filename: str, /, *, strict: bool = False, lenient: bool = False,
         quiet: bool = False, max_memory: int | str | None = None,
         load_state: str | bool | None = None, user_data: str | None = None,
         **overrides) -> Network:
    """Read, build and initialise a model file (.ikg). Other keyword arguments set
    attributes of the top group and win over the file. Raises ModelError naming the file,
    line and element of what is wrong.

    What the original Ikaros accepts but a clean file would not say is a warning, printed
    to stderr as ``file:line: warning: ...`` (not with ``quiet=True``) and kept in
    ``net.warnings``. ``strict=True`` makes every such warning an error; ``lenient=True``
    drops connections to modules or ports that do not exist, with a warning, as Ikaros 3
    does (they are errors by default). ``max_memory`` limits the memory of all buffers
    (bytes, or text such as ``"512M"``; default half the physical memory).
    ``load_state`` (a file name, or True for ``model.state`` beside the model) loads a
    state saved with ``net.save_state`` after init, as ``ikaros -L`` does; a state that does
    not fit raises StateError (a ValueError) and the network is closed.
    ``user_data`` (``ikaros -u DIR``) is the folder where modules write files with
    relative names (default: the model file's folder); a ``user_data`` attribute in the
    file is ignored, with a warning.
    """
    net = build_tree(None, filename, strict=strict, lenient=lenient, quiet=quiet,
                     max_memory=max_memory, user_data=user_data, **overrides)
    if load_state:
        try:
            net.load_state(None if load_state is True else load_state)
        except BaseException:
            net.close()
            raise
    return net


def build_tree(tree, filename: str, *, strict: bool = False, lenient: bool = False,
               quiet: bool = False, max_memory: int | str | None = None,
               classes: dict | None = None, user_data: str | None = None,
               **overrides) -> Network:
    """Build a model tree (``tree``, or the file ``filename`` read when it is None) as
    ``load`` does. ``classes`` are Module subclasses given in code, by class name."""
    try:
        limits = Limits().with_memory(max_memory)
    except LimitError as e:
        raise ModelError(f"max_memory: {e}") from None
    diagnostics = Diagnostics(strict=strict, lenient=lenient, quiet=quiet)
    registry = None
    if classes:
        registry = CodeClassRegistry([os.path.dirname(os.path.abspath(filename))], classes)
    return Builder(filename, overrides, model=tree, diagnostics=diagnostics, limits=limits,
                   registry=registry, network_factory=_network,
                   user_data=user_data).build()


def _network(*built) -> Network:
    """A Network, or one whose groups with a ``process`` attribute run in other kernel
    processes (docs/links.md)."""
    return cast(Network, make_network(*built, single=Network, split=SplitNetwork))
