"""A Dynamixel bus through ROBOTIS ``dynamixel-sdk``: ping, scan, read, write, sync and bulk.

Every failure raises :class:`ikaros.hardware.DeviceError` naming the servo and the bus, e.g.
``servo 7 on /dev/ttyUSB0 (Protocol 2.0, 1000000 baud) does not answer (reading Present
Position, address 132)``; a missing or corrupt status packet raises its subclass
:class:`NoReply`. Sync and bulk reads give what came back: a servo whose reply is lost is
asked again on its own (with a retry), and left out when it still does not answer. The
status error byte of the last packet from each servo is kept in :attr:`DynamixelBus.errors`.
"""
from __future__ import annotations

import os
import termios
import threading

from ikaros.hardware import DeviceError
from ikaros.hardware.serial_port import describe_error, require

_SDK_HINT = "the Dynamixel bus"
RETRIES = 1                     # a packet lost to noise is asked for once more


class NoReply(DeviceError):
    """A servo does not answer, or its answer is corrupt (a lost or broken status packet)."""


def _sdk():
    return require("dynamixel_sdk", "The Dynamixel bus")


def _port_handler_class():
    sdk = _sdk()

    class PortHandler(sdk.PortHandler):
        """The SDK's port, with a short blocking read instead of a busy spin, and a settable
        latency (the SDK assumes the 16 ms of an FTDI adapter's latency timer)."""
        latency_ms = 16.0

        def setupPort(self, cflag_baud):
            done = super().setupPort(cflag_baud)
            self.ser.timeout = 0.0005
            return done

        def setPacketTimeout(self, packet_length):
            self.packet_start_time = self.getCurrentTime()
            self.packet_timeout = self.tx_time_per_byte * packet_length + 2.0 * self.latency_ms + 2.0

    return PortHandler


class DynamixelBus:
    """One serial bus of Dynamixel servos speaking one protocol version (1 or 2)."""

    def __init__(self, device: str, baud_rate: int = 1000000, protocol: int = 2,
                 latency_ms: float | None = None):
        self.device = device
        self.baud_rate = int(baud_rate)
        self.protocol = int(protocol)
        self.errors: dict[int, int] = {}
        self.lock = threading.RLock()       # drivers sharing the bus take turns under it
        self._sdk = _sdk()
        self._port = _port_handler_class()(device)
        if latency_ms is None:          # a simulator on a pseudo-terminal may wait for the CPU
            latency_ms = 20.0 if os.path.realpath(device).startswith("/dev/pts/") else 16.0
        self._port.latency_ms = latency_ms
        self._handler = self._sdk.PacketHandler(float(self.protocol))
        self._open()

    def __repr__(self) -> str:
        return f"{self.device} (Protocol {self.protocol}.0, {self.baud_rate} baud)"

    def _open(self) -> None:
        serial = require("serial", _SDK_HINT)
        try:
            if not self._port.setBaudRate(self.baud_rate):
                raise DeviceError(f"the Dynamixel bus at '{self.device}' cannot run at {self.baud_rate} baud")
        except serial.SerialException as error:
            raise DeviceError(f"cannot open the Dynamixel bus at '{self.device}': {describe_error(error)}") from None

    def set_protocol(self, protocol: int) -> None:
        self.protocol = int(protocol)
        self._handler = self._sdk.PacketHandler(float(self.protocol))

    def close(self) -> None:
        try:
            if self._port.is_open:
                self._port.closePort()
        except Exception:
            pass

    # --- error handling ---------------------------------------------------------------------
    def _call(self, ident, what, function, *args, retries: int = RETRIES):
        """Run an SDK call; retry on a lost or corrupt packet; raise DeviceError on failure."""
        serial = require("serial", _SDK_HINT)
        sdk = self._sdk
        # The SDK marks the port busy from sending to receiving; a transaction cut short (an
        # exception, Ctrl-C) would leave it marked. Calls are serialised, so none is under way.
        self._port.is_using = False
        for attempt in range(retries + 1):
            try:
                if attempt:
                    self._port.clearPort()
                result = function(*args)
            except (serial.SerialException, OSError, termios.error) as error:
                raise DeviceError(f"the Dynamixel bus {self} was lost ({what}): {error}") from None
            code = result if isinstance(result, int) else result[-2]   # (.., result, error)
            if code == sdk.COMM_SUCCESS:
                return result
            lost = code in (sdk.COMM_RX_TIMEOUT, sdk.COMM_RX_CORRUPT, sdk.COMM_RX_FAIL)
            if not lost:
                break
        reason = {sdk.COMM_RX_TIMEOUT: "does not answer", sdk.COMM_RX_CORRUPT: "answered with a corrupt packet",
                  sdk.COMM_RX_FAIL: "does not answer", sdk.COMM_TX_FAIL: "could not be sent to",
                  sdk.COMM_PORT_BUSY: "is busy"}.get(code, self._handler.getTxRxResult(code))
        who = f"servo {ident}" if ident is not None else "the servos"
        raise (NoReply if lost else DeviceError)(f"{who} on {self} {reason} ({what})")

    def _clear(self) -> int:
        self._port.clearPort()
        return self._sdk.COMM_SUCCESS

    def _keep_error(self, ident: int, error: int) -> None:
        self.errors[ident] = int(error)

    # --- single servos ----------------------------------------------------------------------
    def ping(self, ident: int) -> int | None:
        """The model number of servo ``ident``, or None when nothing answers."""
        number, code, error = self._handler.ping(self._port, ident)
        if code != self._sdk.COMM_SUCCESS:
            return None
        self._keep_error(ident, error)
        if self.protocol == 1:          # Protocol 1.0 ping has no model number: read it
            return int.from_bytes(self.read(ident, 0, 2), "little")
        return number

    def scan(self, ids) -> dict[int, int]:
        """id -> model number of every servo that answers among ``ids``."""
        ids = list(ids)
        if self.protocol == 2 and len(ids) > 8:
            found, code = self._handler.broadcastPing(self._port)
            if code == self._sdk.COMM_SUCCESS or found:
                return {i: found[i][0] for i in sorted(found) if i in ids}
        found = {}
        for ident in ids:
            number = self.ping(ident)
            if number is not None:
                found[ident] = number
        return found

    def read(self, ident: int, address: int, length: int, register: str | None = None) -> bytes:
        """``length`` bytes at ``address`` (``register`` names them in messages)."""
        what = f"reading {register or f'{length} bytes at address {address}'}"
        data, code, error = self._call(ident, what, self._handler.readTxRx, self._port, ident, address, length)
        self._keep_error(ident, error)
        return bytes(data)

    def write(self, ident: int, address: int, data: bytes, register: str | None = None) -> int:
        """Write and wait for the status; returns its error byte."""
        what = f"writing {register or f'{len(data)} bytes at address {address}'}"
        code, error = self._call(ident, what, self._handler.writeTxRx,
                                 self._port, ident, address, len(data), list(data))
        self._keep_error(ident, error)
        return error

    def reboot(self, ident: int) -> None:
        self._call(ident, "reboot", self._handler.reboot, self._port, ident)

    def factory_reset(self, ident: int, keep_id: bool = True) -> None:
        """Reset the control table to the factory values (Protocol 2.0 can keep the id and baud
        rate: option 0x02; Protocol 1.0 resets everything, the id becomes 1)."""
        if self.protocol == 1:
            self._call(ident, "factory reset", self._handler.factoryReset, self._port, ident)
        else:
            self._call(ident, "factory reset", self._handler.factoryReset, self._port, ident,
                       0x02 if keep_id else 0xFF)

    # --- many servos in one packet -----------------------------------------------------------
    def sync_write(self, address: int, length: int, values: dict[int, bytes]) -> None:
        """One packet that writes ``length`` bytes at ``address`` of each servo (no answer)."""
        if not values:
            return
        params = []
        for ident, data in values.items():
            params.append(ident)
            params.extend(data[:length])
        self._call(None, f"sync write at {address}", self._handler.syncWriteTxOnly, self._port,
                   address, length, params, len(params))

    def sync_read(self, address: int, length: int, ids, register: str | None = None) -> dict[int, bytes]:
        """``length`` bytes at ``address`` from each servo that answers: one sync read packet in
        Protocol 2.0, one read per servo in Protocol 1.0 (which has no sync read). A servo whose
        reply is lost is asked again on its own; one that still does not answer is left out."""
        ids = list(ids)
        what = f"sync read of {register or f'{length} bytes at address {address}'}"
        if self.protocol == 1:
            return self._ask_each([(ident, address, length) for ident in ids], {}, register)
        self._call(None, what, self._handler.syncReadTx, self._port, address, length, ids, len(ids), False)
        got = self._collect([(ident, length) for ident in ids], what)
        return self._ask_each([(i, address, length) for i in ids if i not in got], got, register)

    def bulk_read(self, requests: list[tuple[int, int, int]], register: str | None = None) -> dict[int, bytes]:
        """(id, address, length) per servo, in one bulk read packet (Protocol 1.0: MX series
        only); a servo whose reply is lost is asked again on its own, and left out when it
        still does not answer."""
        params = []
        what = f"bulk read of {register or 'several registers'}"
        if self.protocol == 1:                  # the SDK adds the leading 0x00
            for ident, address, length in requests:
                params += [length, ident, address]
            self._call(None, what, self._handler.bulkReadTx, self._port, params, len(params))
        else:
            for ident, address, length in requests:
                params += [ident, address & 0xFF, address >> 8, length & 0xFF, length >> 8]
            self._call(None, what, self._handler.bulkReadTx, self._port, params, len(params), False)
        got = self._collect([(ident, length) for ident, _, length in requests], what)
        return self._ask_each([r for r in requests if r[0] not in got], got, register)

    def _ask_each(self, requests: list[tuple[int, int, int]], got: dict[int, bytes],
                  register: str | None) -> dict[int, bytes]:
        """Read each (id, address, length) on its own into ``got``; leave out who does not answer."""
        for ident, address, length in requests:
            try:
                got[ident] = self.read(ident, address, length, register)
            except NoReply:
                pass
        return got

    def bulk_write(self, requests: list[tuple[int, int, bytes]]) -> None:
        """(id, address, data) per servo, in one bulk write packet (Protocol 2.0)."""
        if self.protocol != 2:
            for ident, address, data in requests:
                self.write(ident, address, data)
            return
        params = []
        for ident, address, data in requests:
            params += [ident, address & 0xFF, address >> 8, len(data) & 0xFF, len(data) >> 8] + list(data)
        self._call(None, "bulk write", self._handler.bulkWriteTxOnly, self._port, params, len(params))

    def _collect(self, expected: list[tuple[int, int]], what: str) -> dict[int, bytes]:
        """The status packets of a sync or bulk read, in order, up to the first that does not
        come (the servos after it wait for it: on a real bus as in the simulator)."""
        out = {}
        for ident, length in expected:
            try:
                data, code, error = self._call(ident, what, self._handler.readRx, self._port, ident, length,
                                               retries=0)
            except NoReply:
                self._call(None, "clearing the port", self._clear)
                break
            self._keep_error(ident, error)
            out[ident] = bytes(data)
        return out
