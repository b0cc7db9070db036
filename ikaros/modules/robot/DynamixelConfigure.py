"""DynamixelConfigure: sets control-table values of Dynamixel servos (ids, baud rates, limits)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DynamixelConfigure(Module):
    """A utility for setting up Dynamixel servos. At start it scans the bus (ids
    0..``max_servo_id``, Protocol 1.0 and 2.0 unless ``protocol`` is fixed) and prints every
    servo found with its model, id and baud rate. Nothing is written until SET rises from 0
    to above 0 while ACTIVE is above 0; then, for every servo found (or those in
    ``servo_id``), ``value`` is written to the control-table field named ``field`` (e.g.
    ``ID``, ``Baud Rate``, ``Return Delay Time``, ``CW Angle Limit``) or, when ``field`` is
    empty, to the field at address ``adress``, with the field's size (torque is switched off
    first: Protocol 2.0 servos refuse EEPROM writes while it is on). Writing an id to more
    than one servo at once is refused. A baud rate is written as the servo's code (AX/MX 1.0:
    1 = 1 Mbaud, 34 = 57600; Protocol 2.0: 1 = 57600, 3 = 1 Mbaud); the module reads the
    servo back at the new rate to check it. With ``reset_mode`` the servos are reset to
    their factory settings instead (Protocol 2.0 keeps id and baud rate; Protocol 1.0 resets
    all, the id becomes 1). ``force_model`` gives the model number to assume for servos whose
    model has no control table. RESET_MODE and CHANGE_MODE show which of the two SET does.
    The command ``scan`` scans again. Unlike Ikaros 2 it writes only on the rising edge of SET
    (not every tick while SET is on); field, servo_id and protocol are additions."""

    device = Parameter("/dev/cu.usbserial-A7005Lxn", "the serial device of the bus, or sim:dynamixel?...")
    baud_rate = Parameter(1000000, "baud rate of the bus")
    max_servo_id = Parameter(32, "the highest id the scan pings")
    adress = Parameter(0, "control-table address to write (when field is empty)")
    value = Parameter(1, "the value to write")
    field = Parameter("", "name of the control-table field to write, e.g. ID or Baud Rate")
    servo_id = Parameter("", "the servos to change (empty: every servo found)", type="array")
    force_model = Parameter(0, "model number to assume for a servo of an unknown model (0: none)")
    reset_mode = Parameter(False, "SET resets the servos to their factory settings")
    protocol = Parameter("auto", "protocol version (auto: ping with 1.0, then 2.0)", options="auto/1/2")

    SET = Input("a rising edge (while ACTIVE) writes value, or resets")
    ACTIVE = Input("above 0 arms SET")
    RESET_MODE = Output("1 when SET resets the servos", size="1")
    CHANGE_MODE = Output("1 when SET writes value", size="1")

    def init(self):
        from ikaros.hardware.simulators import open_device_string
        self._simulator = None
        self._bus = None
        self._device, self._simulator = open_device_string(str(self.device))
        self._last_set = 0.0
        self._scan()

    def _scan(self):
        from ikaros.hardware.dynamixel.servos import open_bus, release_bus
        if self._bus is not None:
            release_bus(self._bus)
            self._bus = None
        self._bus, self._tables = open_bus(self._device, int(self.baud_rate), self.protocol, None,
                                           int(self.max_servo_id), force_model=int(self.force_model))
        for ident, table in self._tables.items():
            self.print(f"servo {ident}: {table.model} (model number {table.model_number}) on {self._bus}")

    def _targets(self):
        wanted = [int(i) for i in np.asarray(self.servo_id).reshape(-1)]
        missing = [i for i in wanted if i not in self._tables]
        if missing:
            raise ValueError(f"servo {', '.join(map(str, missing))} was not found on {self._bus}")
        return wanted or list(self._tables)

    def tick(self):
        self.RESET_MODE[0] = float(bool(self.reset_mode))
        self.CHANGE_MODE[0] = float(not self.reset_mode)
        rising = self.SET.reshape(-1)[0] > 0 >= self._last_set
        self._last_set = float(self.SET.reshape(-1)[0])
        if rising and self.ACTIVE.reshape(-1)[0] > 0:
            self._apply()

    def _apply(self):
        bus, targets = self._bus, self._targets()
        if self.reset_mode:
            for ident in targets:
                bus.factory_reset(ident)
                self.print(f"servo {ident} on {bus}: reset to factory settings")
            return
        for ident in targets:
            table = self._tables[ident]
            f = table.field(self.field) if self.field else next(
                (f for f in table.fields.values() if f.address == int(self.adress)), None)
            if f is None:
                raise ValueError(f"the {table.model} (servo {ident}) has no field at address {self.adress}")
            if f.access != "RW":
                raise ValueError(f"'{f.name}' of the {table.model} (servo {ident}) is read-only")
            if f.name == "ID" and len(targets) > 1:
                raise ValueError("writing an id to several servos at once would give them all the same id; "
                                 "choose one with servo_id")
            value = int(self.value)
            if not 0 <= value < 1 << (8 * f.size):
                raise ValueError(f"value {value} does not fit in '{f.name}' ({f.size} bytes)")
            bus.write(ident, table.role("TORQUE_ENABLE").field.address, b"\x00")
            error = bus.write(ident, f.address, value.to_bytes(f.size, "little"))
            if error:
                from ikaros.hardware.dynamixel.servos import ServoGroup
                raise ValueError(f"servo {ident} on {bus} refused {f.name} = {value}: "
                                 f"{ServoGroup(bus, self._tables).error_text(ident, error)}")
            self.print(f"servo {ident} on {bus}: {f.name} = {value}")

    def command(self, name, x=0, y=0, value=None):
        if name == "scan":
            self._scan()

    def stop(self):
        from ikaros.hardware.dynamixel.servos import release_bus
        if self._bus is not None:
            release_bus(self._bus)
            self._bus = None
        if self._simulator is not None:
            self._simulator.stop()
            self._simulator = None
