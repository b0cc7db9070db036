"""A Phidgets InterfaceKit (analogue sensor inputs, digital inputs and digital outputs) through
the current Phidget22 library (``pip install phidget22``, which also needs the libphidget22
driver of the Phidgets web site on some systems).

In Phidget22 every input and output is a channel object of its own (VoltageRatioInput or
VoltageInput for the sensor ports, DigitalInput, DigitalOutput) matched to the board by its
serial number and channel index. Sensor values are given in the InterfaceKit's 0..1000 units
(the voltage ratio times 1000, or the voltage times 200 for 0..5 V).
"""
from __future__ import annotations

from typing import Any, Callable

from ikaros.hardware import DeviceError

INSTALL_HINT = "pip install 'ikaros[phidgets]' (or pip install phidget22)"
ANY_SERIAL = -1


def load_library() -> dict[str, Any]:
    """The Phidget22 channel classes, or DeviceError with the pip install that provides them."""
    try:
        from Phidget22.Devices.DigitalInput import DigitalInput
        from Phidget22.Devices.DigitalOutput import DigitalOutput
        from Phidget22.Devices.VoltageInput import VoltageInput
        from Phidget22.Devices.VoltageRatioInput import VoltageRatioInput
        from Phidget22.PhidgetException import PhidgetException
    except ImportError:
        raise DeviceError(f"the Phidgets module needs the Phidget22 library: {INSTALL_HINT}") \
            from None
    return dict(DigitalInput=DigitalInput, DigitalOutput=DigitalOutput,
                VoltageInput=VoltageInput, VoltageRatioInput=VoltageRatioInput,
                PhidgetException=PhidgetException)


class InterfaceKit:
    """The channels of one InterfaceKit board. ``library`` is what :func:`load_library` returns
    (tests pass stand-ins with the same methods)."""

    def __init__(self, serial: int, analog: int, digital_in: int, digital_out: int,
                 ratiometric: bool = True, sensitivity: float = 10.0,
                 attach_timeout_ms: int = 2000, library: dict[str, Any] | None = None):
        self.library = library or load_library()
        self.serial = serial
        self.where = "any serial number" if serial == ANY_SERIAL else f"serial number {serial}"
        self.ratiometric = ratiometric
        self.analog, self.digital_in, self.digital_out = [], [], []
        try:
            kind = "VoltageRatioInput" if ratiometric else "VoltageInput"
            first_timeout = attach_timeout_ms
            for group, kind_name, count in ((self.analog, kind, analog),
                                            (self.digital_in, "DigitalInput", digital_in),
                                            (self.digital_out, "DigitalOutput", digital_out)):
                for index in range(count):
                    group.append(self._open(kind_name, index, first_timeout))
                    first_timeout = max(first_timeout, 1000)
            for channel in self.analog:
                trigger = sensitivity / 1000.0 if ratiometric else sensitivity / 200.0
                self._call(channel.setVoltageRatioChangeTrigger if ratiometric else
                           channel.setVoltageChangeTrigger, trigger)
        except DeviceError:
            self.close()
            raise

    def _open(self, kind: str, index: int, timeout_ms: int):
        channel = self.library[kind]()
        if self.serial != ANY_SERIAL:
            channel.setDeviceSerialNumber(self.serial)
        channel.setChannel(index)
        try:
            channel.openWaitForAttachment(timeout_ms)
        except self.library["PhidgetException"] as error:
            channel.close()
            raise DeviceError(f"no Phidgets InterfaceKit with {self.where} answered on "
                              f"{kind} channel {index} within {timeout_ms} ms: "
                              f"{getattr(error, 'details', error)}") from None
        return channel

    def _call(self, method: Callable, *args):
        try:
            return method(*args)
        except self.library["PhidgetException"] as error:
            raise DeviceError(f"the Phidgets InterfaceKit with {self.where}: "
                              f"{getattr(error, 'details', error)}") from None

    def info(self) -> str:
        """Name, serial number and version of the board."""
        channel = (self.analog + self.digital_in + self.digital_out)[0]
        return (f"{self._call(channel.getDeviceName)}, serial number "
                f"{self._call(channel.getDeviceSerialNumber)}, version "
                f"{self._call(channel.getDeviceVersion)}")

    def attached(self) -> bool:
        return all(c.getAttached() for c in self.analog + self.digital_in + self.digital_out)

    def sensor_values(self) -> list[float]:
        """The analogue inputs in 0..1000."""
        if self.ratiometric:
            return [1000.0 * self._call(c.getVoltageRatio) for c in self.analog]
        return [200.0 * self._call(c.getVoltage) for c in self.analog]

    def digital_inputs(self) -> list[bool]:
        return [bool(self._call(c.getState)) for c in self.digital_in]

    def set_outputs(self, states: dict[int, bool]) -> None:
        """Set the digital outputs ``states`` names (index -> on)."""
        for index, state in states.items():
            self._call(self.digital_out[index].setState, bool(state))

    def safe_state(self) -> None:
        """Every digital output off."""
        self.set_outputs({index: False for index in range(len(self.digital_out))})

    def close(self) -> None:
        for channel in self.analog + self.digital_in + self.digital_out:
            try:
                channel.close()
            except Exception:
                pass
        self.analog, self.digital_in, self.digital_out = [], [], []
