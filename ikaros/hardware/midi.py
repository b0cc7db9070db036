"""MIDI ports: real ones through mido and python-rtmidi (CoreMIDI, ALSA, JACK, Windows MM),
and the ports of simulated devices in this process.

A port name of the form ``sim:NAME`` (``sim:launchpad``) starts simulator NAME in this
process (once: every port that names it shares the device until the last is closed); its
ports are listed with the real ones under their own names. Messages are MIDI bytes.
"""
from __future__ import annotations

import collections
import importlib
import threading

from ikaros.hardware import DeviceError
from ikaros.module import require

SIM_PREFIX = "sim:"
SIMULATORS = {"launchpad": "ikaros.hardware.launchpad_sim"}


class SimulatedDevice:
    """The base of simulated MIDI devices: what the host sends arrives in ``received``;
    what the device sends waits, for each open input port, until the port reads it."""

    name = "simulated device"

    def __init__(self):
        self._listeners: list[collections.deque] = []
        self._lock = threading.Lock()
        self.users = 0

    @property
    def input_name(self) -> str:
        """The port the host reads (the device's output)."""
        return f"{self.name} MIDI Out"

    @property
    def output_name(self) -> str:
        """The port the host writes to (the device's input)."""
        return f"{self.name} MIDI In"

    def received(self, message: bytes) -> None:
        """A message from the host."""
        raise NotImplementedError

    def send_to_host(self, message: bytes) -> None:
        with self._lock:
            for queue in self._listeners:
                queue.append(bytes(message))

    def listen(self) -> collections.deque:
        """A new queue that gets every message the device sends from now on."""
        queue: collections.deque = collections.deque()
        with self._lock:
            self._listeners.append(queue)
        return queue

    def stop_listening(self, queue: collections.deque) -> None:
        with self._lock:
            self._listeners = [q for q in self._listeners if q is not queue]


_running: dict[str, SimulatedDevice] = {}
_registry_lock = threading.Lock()


def simulated_device(spec: str) -> SimulatedDevice:
    """The simulated device that ``sim:NAME`` names, started if it is not running; the
    caller uses it until ``release_device``."""
    name = spec.strip()[len(SIM_PREFIX):].partition("?")[0]
    if name not in SIMULATORS:
        known = ", ".join(SIM_PREFIX + n for n in sorted(SIMULATORS))
        raise DeviceError(f"no simulated MIDI device called '{spec}' (known: {known})")
    with _registry_lock:
        device = _running.get(name)
        if device is None:
            device = _running[name] = importlib.import_module(SIMULATORS[name]).start()
        device.users += 1
        return device


def _attach(port_name: str, output: bool) -> SimulatedDevice | None:
    """The running simulated device with a port of this name (used until
    ``release_device``), or None."""
    with _registry_lock:
        for device in _running.values():
            if port_name == (device.output_name if output else device.input_name):
                device.users += 1
                return device
    return None


def release_device(device: SimulatedDevice) -> None:
    with _registry_lock:
        device.users -= 1
        if device.users <= 0:
            for name, running in list(_running.items()):
                if running is device:
                    del _running[name]


def running_devices() -> list[SimulatedDevice]:
    with _registry_lock:
        return list(_running.values())


def _mido():
    return require("mido", "mido", extra="midi")


def require_ports(name: str) -> None:
    """Fail now when ``name`` needs real MIDI ports and mido or python-rtmidi is missing."""
    _mido()
    if not name.strip().startswith(SIM_PREFIX):
        require("rtmidi", "python-rtmidi", extra="midi")


def _backend():
    """mido's python-rtmidi backend, or a MissingDependency naming what to install."""
    require("rtmidi", "python-rtmidi", extra="midi")
    return _mido().Backend("mido.backends.rtmidi")


def port_names(output: bool) -> list[str]:
    """The names of the real MIDI input (or output) ports, then those of the simulated
    devices running in this process. Without python-rtmidi, or when the MIDI system
    cannot be reached (no ALSA sequencer), there are no real ports."""
    try:
        backend = _backend()
        real = backend.get_output_names() if output else backend.get_input_names()
    except (ImportError, OSError, RuntimeError):     # no python-rtmidi; rtmidi's errors
        real = []
    simulated = [d.output_name if output else d.input_name for d in running_devices()]
    return list(real) + simulated


class Port:
    """An open MIDI port, real or simulated: ``pending()`` (an input's messages since the
    last call, as bytes), ``send(bytes)`` (an output), ``close()``."""

    def __init__(self, name: str, output: bool, device: SimulatedDevice | None = None,
                 port=None):
        self.name, self.output, self.device, self.port = name, output, device, port
        self._queue = device.listen() if device is not None and not output else None

    def pending(self) -> list[bytes]:
        if self.device is not None:
            messages = []
            while self._queue:
                messages.append(self._queue.popleft())
            return messages
        try:
            return [bytes(m.bytes()) for m in self.port.iter_pending()]
        except Exception as e:              # the device went away
            raise DeviceError(f"the MIDI port '{self.name}' cannot be read: {e}") from None

    def send(self, message: bytes) -> None:
        if self.device is not None:
            self.device.received(bytes(message))
            return
        try:
            self.port.send(_mido().Message.from_bytes(list(message)))
        except Exception as e:
            raise DeviceError(f"the MIDI port '{self.name}' cannot be written to: {e}") \
                from None

    def close(self) -> None:
        if self.device is not None:
            if self._queue is not None:
                self.device.stop_listening(self._queue)
            release_device(self.device)
            self.device = None
        elif self.port is not None:
            try:
                self.port.close()
            except Exception:
                pass
            self.port = None


def open_port(name: str, output: bool) -> Port:
    """Open the MIDI port ``name``: ``sim:NAME`` (a simulated device's port), or a real
    port's exact name. DeviceError when it cannot be opened."""
    if name.strip().startswith(SIM_PREFIX):
        device = simulated_device(name)
        return Port(device.output_name if output else device.input_name, output, device)
    device = _attach(name, output)
    if device is not None:
        return Port(name, output, device)
    backend = _backend()
    try:
        port = backend.open_output(name) if output else backend.open_input(name)
    except Exception as e:                  # rtmidi's errors, mido's IOError
        raise DeviceError(f"cannot open the MIDI port '{name}': {e}") from None
    return Port(name, output, port=port)


def find_port(names: list[str], wanted: str) -> str | None:
    """The first name that contains ``wanted`` (ignoring case), or None."""
    for name in names:
        if wanted.lower() in name.lower():
            return name
    return None


def open_wanted(wanted: str, output: bool, index: int = -1, warn=None) -> list[Port]:
    """Open the ports a model asks for: ``sim:NAME``; else the first port whose name
    contains ``wanted``; else port number ``index``; else (-1) every port. None found is an
    empty list; a port that cannot be opened is left out, with ``warn(message)``."""
    if wanted.strip().startswith(SIM_PREFIX):
        names = [wanted]
    else:
        available = port_names(output)
        if wanted:
            found = find_port(available, wanted)
            names = [found] if found else []
        elif index >= 0:
            names = available[index:index + 1]
        else:
            names = available
    ports = []
    for name in names:
        try:
            ports.append(open_port(name, output))
        except DeviceError as e:
            if warn is not None:
                warn(str(e))
    return ports
