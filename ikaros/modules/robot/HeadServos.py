"""HeadServos: the two servos of a pan-tilt head on one Dynamixel bus (Ikaros 3)."""
import os

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.robot._servo_chain import SERIAL_LATENCY, latency, ChainDriver, limits


class HeadServos(Module):
    """Drives a pan-tilt head of two Dynamixel servos on one bus, as Ikaros 3's HeadServos:
    element 0 is the neck tilt, element 1 the neck pan, in degrees (180 is a servo's centre),
    with the models, ids and limits of the robot type ``Head``
    (``ikaros/hardware/dynamixel/robots/types/Head.json``, or ``robots/types/Head.json`` beside
    the model: the Epi's neck, two MX-106(2.0) with ids 2 and 3 on Protocol 2.0 at 1 Mbaud).
    ``port`` is the serial device; a name without a folder is taken in /dev (Ikaros 3's default
    ``cu.usbserial-A40129WB`` is a macOS adapter's name); ``sim:dynamixel?...`` runs the
    simulator. At the start both servos must answer; their goal is set to where they are.
    Every tick TORQUE_ENABLE and then the goals (clipped to the limits; none to a servo whose
    TORQUE_ENABLE is 0) are written and the present positions read back; when the run ends,
    however it ends, and when no tick has come for 1 s, torque goes off. This project's
    reading: Ikaros 3 gives the interface only; the head's servos are those of the Epi's neck."""

    port = Parameter("cu.usbserial-A40129WB", "the serial device of the head's bus (a name without a folder is in "
                     "/dev), or sim:dynamixel?... for the simulator")

    serial_latency = Parameter(-1.0, SERIAL_LATENCY)

    GOAL_POSITION = Input("goal positions: neck tilt, neck pan (degrees)")
    TORQUE_ENABLE = Input("1: torque on, 0: off, per servo")

    PRESENT_POSITION = Output("present positions: neck tilt, neck pan (degrees)", size="2")

    def init(self):
        from ikaros.hardware.dynamixel.robot_config import robot_with_ports
        from ikaros.modules.io._files import model_folder
        port = str(self.port).strip()
        if not port.startswith("sim:") and "/" not in port and "\\" not in port:
            port = os.path.join("/dev", port)
        robot = robot_with_ports("Head", {"head": port}, model_folder(self))
        self._driver = ChainDriver(self, robot, False, *limits(robot), writes={"Goal Position", "Torque Enable"},
                                   latency_ms=latency(self))
        self._driver.start()
        self.PRESENT_POSITION[:] = self._driver.present

    def tick(self):
        self._driver.step("GOAL_POSITION", torque_name="TORQUE_ENABLE")
        self.PRESENT_POSITION[:] = self._driver.present

    def stop(self):
        driver = getattr(self, "_driver", None)
        if driver is not None:
            driver.stop()
