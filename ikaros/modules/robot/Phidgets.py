"""Phidgets: a Phidgets InterfaceKit board (analogue and digital inputs, digital outputs)."""
import threading

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Phidgets(Module):
    """Reads and writes a Phidgets InterfaceKit through the current Phidget22 library (an
    optional package: ``pip install 'ikaros[phidgets]'``; a model that uses this class fails
    at load with that command when it is missing). ANALOG_OUTPUTS are the board's
    ``analog_inputs`` sensor inputs in the InterfaceKit's 0..1000 units (the voltage ratio
    times 1000 with ``ratiometric``, else the voltage times 200), updated when they change by
    more than ``sensitivity`` units; DIGITAL_OUTPUTS are its ``digital_inputs`` digital inputs
    (0 or 1); DIGITAL_INPUTS, when connected, sets its ``digital_outputs`` digital outputs
    (on above 0.5): an output is written when its value changes. ATTACHED is 1 while the board is
    attached. The board is found by ``serial`` (-1: any board) within ``attach_timeout`` ms, or
    the load fails naming the serial number; ``info`` prints its name and version. Nothing is
    written before the first tick, nor from an element of DIGITAL_INPUTS that has not yet
    received a value from its source (``Module.input_ready``). The safe state is every digital
    output off: when the run ends, at interpreter exit, on the ``safe_state`` command, and
    after ``watchdog`` seconds without a tick (paused, stopped, hung: the model's outputs are
    written again when ticks resume). Ikaros 2 used the older Phidget21 library and had no
    safe state; the channel counts, attach_timeout and watchdog are new (Phidget22 opens each
    channel on its own)."""

    serial = Parameter(176729, "serial number of the board (-1: any)", type="int")
    info = Parameter(True, "print the board's name, serial number and version at the start")
    sensitivity = Parameter(10.0, "smallest change of an analogue input (0..1000 units) that "
                            "updates it")
    ratiometric = Parameter(True, "read the sensor inputs as voltage ratios (ratiometric "
                            "sensors) rather than voltages")
    analog_inputs = Parameter(8, "number of analogue sensor inputs of the board", type="int")
    digital_inputs = Parameter(8, "number of digital inputs of the board", type="int")
    digital_outputs = Parameter(8, "number of digital outputs of the board", type="int")
    attach_timeout = Parameter(2000, "how long to wait for the board, ms", type="int")
    watchdog = Parameter(1.0, "seconds without a tick before every digital output is switched "
                         "off (0: never)")

    DIGITAL_INPUTS = Input("the states of the board's digital outputs, on above 0.5",
                           optional=True)

    ATTACHED = Output("1 while the board is attached", size="1")
    ANALOG_OUTPUTS = Output("the analogue sensor inputs, 0..1000", size_param="analog_inputs")
    DIGITAL_OUTPUTS = Output("the digital inputs, 0 or 1", size_param="digital_inputs")

    def configure(self):
        from ikaros.hardware import phidgets
        phidgets.load_library()                 # a missing library fails at load

    def init(self):
        from ikaros.hardware import safety
        from ikaros.hardware.phidgets import InterfaceKit
        self._board = self._exit_key = self._watchdog = None
        self._lock = threading.Lock()
        self._written: dict[int, bool] = {}
        if self.DIGITAL_INPUTS is not None and self.DIGITAL_INPUTS.size > self.digital_outputs:
            raise ValueError(f"DIGITAL_INPUTS has {self.DIGITAL_INPUTS.size} values but the "
                             f"board has {self.digital_outputs} digital outputs")
        self._board = InterfaceKit(int(self.serial), int(self.analog_inputs),
                                   int(self.digital_inputs), int(self.digital_outputs),
                                   bool(self.ratiometric), float(self.sensitivity),
                                   int(self.attach_timeout))
        self._exit_key = safety.on_exit(f"the Phidgets board {self._board.where}",
                                        self._safe_state)
        self._watchdog = safety.Watchdog(float(self.watchdog), self._safe_state,
                                         f"{self.path}-watchdog")
        if self.info:
            self.print(self._board.info())
        self._read()

    def _read(self):
        self.ATTACHED[0] = 1.0 if self._board.attached() else 0.0
        if self.ATTACHED[0]:
            self.ANALOG_OUTPUTS[...] = self._board.sensor_values()
            self.DIGITAL_OUTPUTS[...] = self._board.digital_inputs()

    def tick(self):
        with self._lock:
            if self._watchdog.kick():           # made safe while idle: write everything again
                self._written.clear()
            if self.DIGITAL_INPUTS is not None:
                ready = self.input_ready("DIGITAL_INPUTS")
                states = np.asarray(self.DIGITAL_INPUTS).reshape(-1) > 0.5
                changed = {i: bool(on) for i, on in enumerate(states)
                           if ready[i] and self._written.get(i) != bool(on)}
                self._board.set_outputs(changed)
                self._written.update(changed)
            self._read()

    def command(self, name, x=0, y=0, value=None):
        if name == "safe_state":
            self._safe_state()

    def _safe_state(self):
        """Every digital output off (called by stop, the watchdog and at exit)."""
        with self._lock:
            if self._board is not None:
                self._board.safe_state()
                self._written = {i: False for i in range(int(self.digital_outputs))}

    def stop(self):
        from ikaros.hardware import safety
        board = getattr(self, "_board", None)
        safety.shut_down(getattr(self, "_watchdog", None), self._safe_state,
                         getattr(self, "_exit_key", None), board, None, lambda error: self.error(
                             f"the digital outputs could not be switched off: {error}"))
        self._board = None
