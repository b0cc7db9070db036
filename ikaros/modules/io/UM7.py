"""UM7: orientation, rates and accelerations from a Redshift Labs UM7 sensor."""
import numpy as np

from ikaros.hardware import DeviceError, um7
from ikaros.hardware.simulators import open_device_string
from ikaros.module import Module, Output, Parameter, require

GYRO = [um7.DREG_GYRO_PROC_X + k for k in range(3)]
ACCEL = [um7.DREG_ACCEL_PROC_X + k for k in range(3)]


class UM7(Module):
    """Reads a CH Robotics / Redshift Labs UM7 orientation sensor on a serial port (Ikaros
    3's class, written here from its interface and the UM7 datasheet's binary protocol):
    ROLL, PITCH and YAW are its Euler angles in degrees (registers 0x70 and 0x71, 16-bit
    counts / 91.02222), EulerAngles the three together, ProcessedGyro the processed rates in
    degrees a second (0x61 to 0x63) and ProcessedAccel the processed accelerations (0x65 to
    0x67), as the sensor sends them. A thread reads every packet the sensor sends; with
    ``poll`` (the default) each tick asks for those registers (two batch reads, nothing
    written to the sensor's settings), so the outputs hold the answers to the previous
    tick's requests, or the newest broadcast; without it the module only listens to what
    the sensor broadcasts at the rates set in it. The outputs keep their last values until
    new ones come (0 before the first). ``port="sim:um7"`` runs the sensor simulator in this
    process (see docs/robots.md). A port that cannot be opened is an error at load; a
    sensor that stops answering, or whose port goes away, stops the run with an error
    naming the port. Needs pyserial (``pip install 'ikaros[robots]'``)."""

    port = Parameter("/dev/cu.usbserial-AU04OIL4", "the serial device of the UM7, or sim:um7 "
                     "for the simulator", fixed=True)
    baud_rate = Parameter(um7.BAUD_RATE, "the sensor's baud rate (factory setting 115200)",
                          type="int", fixed=True)
    poll = Parameter(True, "ask for the data every tick; no: only listen to the sensor's "
                     "broadcasts")
    ROLL = Output("roll in degrees", size="1")
    PITCH = Output("pitch in degrees", size="1")
    YAW = Output("yaw in degrees", size="1")
    ProcessedGyro = Output("the processed rates about x, y and z, degrees a second",
                           size="3")
    ProcessedAccel = Output("the processed accelerations along x, y and z", size="3")
    EulerAngles = Output("roll, pitch and yaw in degrees", size="3")

    def configure(self):
        if not self.port.strip().startswith("sim:"):
            require("serial", "pyserial", extra="robots")

    def init(self):
        self._sensor = self._simulator = None
        path, self._simulator = open_device_string(self.port)
        try:
            self._sensor = um7.UM7(path, self.baud_rate)
        except Exception:
            self.stop()
            raise

    def tick(self):
        sensor = self._sensor
        if sensor.error:
            raise DeviceError(sensor.error)
        if self.poll:
            sensor.request(um7.DREG_GYRO_PROC_X, 8)            # gyro and accel, with times
            sensor.request(um7.DREG_EULER_PHI_THETA, 2)        # roll, pitch; yaw
        self._floats(GYRO, self.ProcessedGyro)
        self._floats(ACCEL, self.ProcessedAccel)
        roll_pitch = sensor.register(um7.DREG_EULER_PHI_THETA)
        if roll_pitch is not None:
            counts = um7.high_low(roll_pitch)
            self.EulerAngles[:2] = np.array(counts) / um7.ANGLE_SCALE
        yaw = sensor.register(um7.DREG_EULER_PSI)
        if yaw is not None:
            self.EulerAngles[2] = um7.high_low(yaw)[0] / um7.ANGLE_SCALE
        self.ROLL[0], self.PITCH[0], self.YAW[0] = self.EulerAngles

    def _floats(self, addresses, out):
        for k, address in enumerate(addresses):
            value = self._sensor.register(address)
            if value is not None:
                out[k] = um7.float_register(value)

    def stop(self):
        if getattr(self, "_sensor", None) is not None:
            self._sensor.close()
            self._sensor = None
        if getattr(self, "_simulator", None) is not None:
            self._simulator.stop()
            self._simulator = None
