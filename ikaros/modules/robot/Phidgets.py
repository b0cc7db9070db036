"""Phidgets: a Phidgets InterfaceKit board (analogue and digital inputs, digital outputs)."""
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
    (on above 0.5) on every tick. ATTACHED is 1 while the board is attached. The board is
    found by ``serial`` (-1: any board) within ``attach_timeout`` ms, or the load fails
    naming the serial number; ``info`` prints its name and version. Nothing is written before
    the first tick, and every digital output is switched off when the run ends (and at
    interpreter exit). Ikaros 2
    used the older Phidget21 library; the channel counts and attach_timeout are new
    (Phidget22 opens each channel on its own)."""

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
        self._board = self._exit_key = None
        if self.DIGITAL_INPUTS is not None and self.DIGITAL_INPUTS.size > self.digital_outputs:
            raise ValueError(f"DIGITAL_INPUTS has {self.DIGITAL_INPUTS.size} values but the "
                             f"board has {self.digital_outputs} digital outputs")
        self._board = InterfaceKit(int(self.serial), int(self.analog_inputs),
                                   int(self.digital_inputs), int(self.digital_outputs),
                                   bool(self.ratiometric), float(self.sensitivity),
                                   int(self.attach_timeout))
        self._exit_key = safety.on_exit(f"the Phidgets board {self._board.where}",
                                        self._board.safe_state)
        if self.info:
            self.print(self._board.info())
        self._read()

    def _read(self):
        self.ATTACHED[0] = 1.0 if self._board.attached() else 0.0
        if self.ATTACHED[0]:
            self.ANALOG_OUTPUTS[...] = self._board.sensor_values()
            self.DIGITAL_OUTPUTS[...] = self._board.digital_inputs()

    def tick(self):
        if self.DIGITAL_INPUTS is not None:
            self._board.set_outputs(np.asarray(self.DIGITAL_INPUTS).reshape(-1) > 0.5)
        self._read()

    def stop(self):
        from ikaros.hardware import DeviceError, safety
        board, self._board = getattr(self, "_board", None), None
        if board is None:
            return
        safety.cancel(self._exit_key)
        try:
            board.safe_state()
        except DeviceError as error:
            self.error(f"the digital outputs could not be switched off: {error}")
        finally:
            board.close()
