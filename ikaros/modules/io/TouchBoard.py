"""TouchBoard: electrode values from a Bare Conductive Touch Board over USB serial."""
import numpy as np

from ikaros.module import Module, Output, Parameter, require


class TouchBoard(Module):
    """Reads a Bare Conductive Touch Board running its DataStream firmware over a serial
    port (pyserial: ``pip install pyserial``). The board writes lines of twelve (or
    thirteen) numbers, one per electrode, for each kind of data; OUTPUT holds the newest
    line of the kind ``data`` names (FDAT: the filtered electrode data, by default; DIFF: the
    baseline minus the data, larger when touched; BVAL: the baselines; TTHS and RTHS: the
    touch and release thresholds), for the first ``electrodes`` electrodes (11, as in Ikaros
    2). TOUCHED holds the newest TOUCH line: 1 for each electrode that is touched. Outputs
    keep their values between lines. A port that cannot be opened is a load error; a board
    that stops sending leaves the values as they were and is reported once."""

    port = Parameter("/dev/cu.usbmodem14201", "the serial port of the board")
    baud_rate = Parameter(57600, "the serial speed (DataStream: 57600)", type="int")
    data = Parameter("FDAT", "the kind of line OUTPUT shows",
                     options="FDAT,DIFF,BVAL,TTHS,RTHS")
    electrodes = Parameter(11, "how many electrodes OUTPUT and TOUCHED hold (1 to 13)",
                           type="int")
    OUTPUT = Output("the newest values of the chosen kind, one per electrode",
                    size_param="electrodes")
    TOUCHED = Output("1 for each electrode that is touched, else 0", size_param="electrodes")

    def configure(self):
        self._serial = require("serial", "pyserial")
        if not 1 <= self.electrodes <= 13:
            raise ValueError(f"electrodes={self.electrodes} must be from 1 to 13")

    def init(self):
        from ikaros.hardware.touchboard import DataStreamReader
        try:
            self._port = self._serial.Serial(self.port, self.baud_rate, timeout=0)
        except (self._serial.SerialException, OSError) as e:
            raise ValueError(f'cannot open the Touch Board\'s port "{self.port}": {e}') \
                from None
        self._reader = DataStreamReader()
        self._silent_ticks = 0

    def tick(self):
        try:
            waiting = self._port.read(self._port.in_waiting or 1)
        except (self._serial.SerialException, OSError) as e:
            self.fatal_error(f'the Touch Board\'s port "{self.port}" failed: {e}')
            return
        lines = self._reader.feed(waiting)
        self._silent_ticks = 0 if lines else self._silent_ticks + 1
        if self._silent_ticks == 200:
            self.warning(f'the Touch Board on "{self.port}" has sent nothing for 200 ticks')
        n = self.electrodes
        for label, values in lines:
            row = np.zeros(n, np.float32)
            row[:min(n, len(values))] = values[:n]
            if label == self.data:
                self.OUTPUT[...] = row
            elif label == "TOUCH":
                self.TOUCHED[...] = row

    def stop(self):
        self._port.close()
