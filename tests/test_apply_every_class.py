"""Apply keeps every module live (issue 37: after the editor's Apply, Add went on adding the
inputs of the network that had been replaced).

For every standard class that runs without a device (a simulator stands in where the class
has one): a model with one module of the class, each input fed by a signal that changes
every tick, runs 4 ticks; it is applied (unchanged, or with a module added before all
others, which moves every buffer) and runs 4 more ticks. Every output and input after each
of those ticks must equal what an uninterrupted run of 8 ticks from a fresh load gives
(to float32 rounding: OpenCV's vector code rounds by where an array lies in memory), with
and without the compiled tick. The input shapes and parameters are those of the class's
example model where it has one (examples/modules), else the smallest shape that builds.
"""
import math
import os
import shutil
import socket
import wave

import numpy as np
import pytest

import ikaros
from ikaros.kernel.classes import stdlib_classes
from ikaros.language.node import Node
from ikaros.language.reader import read_file
from ikaros.language.writer import write_file

pytestmark = pytest.mark.slow

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(ROOT, "examples", "modules")
BEFORE, AFTER = 4, 4

WAVE = '''import numpy as np
from ikaros import Module, Output, Parameter


class Wave(Module):
    """scale * (0.5 + 0.4 sin(0.9 tick + 1.7 i + start)) in element i: new values every tick."""
    shape = Parameter("4", "the output's shape, e.g. 3,8,8", type="string")
    start = Parameter(0.0, "where the wave starts")
    scale = Parameter(1.0, "the size of the values")
    OUTPUT = Output("the signal")

    def configure(self):
        self.set_output_shape("OUTPUT", tuple(int(s) for s in self.shape.split(",")))

    def tick(self):
        i = np.arange(self.OUTPUT.size).reshape(self.OUTPUT.shape)
        self.OUTPUT[...] = self.scale * (0.5 + 0.4 * np.sin(0.9 * self.clock.tick + 1.7 * i
                                                            + self.start))
'''

# classes that need a device no simulator of ours stands in for, or whose data comes from
# outside the model at times of its own (their simulators are tested in their own tests)
NEEDS_A_DEVICE = {
    "InputSound": "a microphone", "SoundOutput": "a sound card", "InputVideo": "a camera",
    "InputVideoAV": "a camera", "InputVideoStream": "a camera stream",
    "NetworkCamera": "a network camera", "Kinect": "a Kinect", "MidiInterface": "a MIDI port",
    "Phidgets": "a Phidgets board", "YARPPort": "a YARP network",
    "TheEyeTribe": "an Eye Tribe tracker (frames arrive in their own time)",
    "TouchBoard": "a Touch Board (lines arrive in their own time)",
}
# the simulators the robot classes open by name
SIMULATED = {
    "Dynamixel": {"device": "sim:dynamixel?ids=1-3&protocol=1", "servo_id": "1 2 3"},
    "DynamixelConfigure": {"device": "sim:dynamixel?ids=1-3&protocol=1", "field": "LED",
                           "max_servo_id": "3", "protocol": "1"},     # (no pings that time out)
    "Epuck": {"port": "sim:epuck"},
    "SSC32": {"port": "sim:ssc32"},
    "FadeCandy": {"address": "sim:opc", "start_server": "no"},
    "HeadServos": {"port": "sim:dynamixel?ids=2-3&protocol=2&model=MX-106(2.0)"},
    "EpiServos": {"simulate": "yes"},
    "DynamixelController": {"Simulate": "yes", "robot": "EpiWhite"},
    "UM7": {"port": "sim:um7"},
}
# classes without an example whose inputs need a particular shape or scale, or parameters
INPUTS = {
    "CalibrateCameraPosition": {"INPUT": ((2, 28), 1)},
    "CameraRectification": {"INPUT": ((8, 8), 1), "CAMERA_MATRIX": ((3, 3), 1),
                            "DISTORTION": ((5,), 0.01)},
    "ColorMatch": {"INPUT": ((3, 8, 8), 1)},
    "ColorTransform": {"INPUT": ((3, 8, 8), 1)},
    "WhiteBalance": {"INPUT": ((3, 8, 8), 1)},
    "SaliencyMap": {"INPUT0": ((8, 8), 1), "REINFORCEMENT": ((1,), 1)},
    "WilsonCowan": {"EXTERNAL_EXCITATION": ((1,), 20), "EXTERNAL_INHIBITION": ((1,), 20)},
    "OneHotVector": {"INPUT": ((1,), 4)},
    "Dynamixel": {"GOAL_POSITION": ((3,), 100), "TORQUE_LIMIT": ((3,), 1)},
    "RegressionStatistics": {"X": ((4,), 1), "Y": ((4,), 1)},
    "Epuck": {"VELOCITY": ((2,), 1)},
    "SSC32": {"INPUT": ((3,), 1)},
    "FadeCandy": {"STRIP_RED": ((8,), 1), "STRIP_BLUE": ((8,), 1)},
    "DynamixelConfigure": {"SET": ((1,), 2), "ACTIVE": ((1,), 2)},
}
ELEMENTS = {"FadeCandy": [Node("channel", {"name": "STRIP", "channel": "0", "size": "8"})]}
PARAMETERS = {"Idle": {"init": "0", "duration": "0"},
              "WhiteBalance": {"x0": "2", "x1": "5", "y0": "2", "y1": "5"},
              "InputAudioFile": {"filename": "sound.wav", "block_size": "4"},
              "Replay": {"filename": "recording.h5", "signal": "Ramp.OUTPUT"}}
# outputs that measure the computer's clock, not the model (the simulated robots' outputs
# too: their simulators move in real time)
CLOCK = {"System": {"REAL_TIME", "TICKS_PER_SECOND", "TICKS_PER_S", "CPU_USAGE", "UPTIME",
                    "ACTUAL_DURATION", "TICK_TIME_USAGE", "TIME_USAGE", "IDLE_RATIO",
                    "OVERLOAD", "LAG"},
         "ROS2Subscriber": {"AGE"}}


# outputs that count the model's modules, which the changed model has one more of
COUNTS = {"System": {"MODULE_COUNT", "CLASS_COUNT"}}


def _timed(cls: str, port: str) -> bool:
    """Whether ``port`` is an output of the harness's module whose values depend on time."""
    module, _, name = port.rpartition(".")
    if module != "M":
        return False
    outputs = stdlib_classes()[cls].description().outputs
    return name in CLOCK.get(cls, ()) or (cls in SIMULATED and
                                          any(o.name == name for o in outputs))
SHAPES = ((4,), (8, 8), (3, 8, 8))


def _free_port(kind=socket.SOCK_STREAM) -> str:
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return str(s.getsockname()[1])


def _channels(cls: str) -> dict:
    """Ports and topics of this machine nobody else uses now, for the classes that open
    one (other test runs may be running beside this one)."""
    if cls in ("ROS2Publisher", "ROS2Subscriber"):
        return {"topic": f"/ikaros_apply_{os.getpid()}", "domain_id": str(100 + os.getpid() % 100)}
    if cls in ("IPCServer", "IPCClient"):
        return {"port": _free_port()}
    if cls == "OscInterface":
        port = _free_port(socket.SOCK_DGRAM)
        return {"inport": port, "outport": port}
    return {}


def _classes():
    return sorted(set(stdlib_classes()) - set(NEEDS_A_DEVICE))


def _find(node: Node, cls: str):
    for child in node.elements():
        if child.tag == "module" and child.get("class") == cls:
            return child
        if child.tag == "group":
            found = _find(child, cls)
            if found is not None:
                return found
    return None


def _from_example(cls: str):
    """(the example's top attributes, its module element, {input: (shape, scale)}) or None."""
    path = os.path.join(EXAMPLES, f"{cls}_example.ikg")
    if not os.path.exists(path):
        return None
    tree = read_file(path)
    element = _find(tree, cls)
    with ikaros.load(path, quiet=True) as net:
        inst = next(i for i in net.schedule if i.node.line == element.line)
        inputs = {n: (b.shape, 1) for n, b in net._buffers[inst][0].items() if b.incoming}
    tops = {k: v for k, v in tree.attrs.items() if k not in ("name", "description")}
    return tops, element, inputs


def _harness(cls: str, folder: str, tops: dict, element: Node, inputs: dict,
             stem: str = "harness") -> str:
    top = Node("group", dict(tops, name="Harness"))
    module = element.copy()
    module.attrs.update({"name": "M", **SIMULATED.get(cls, {}), **PARAMETERS.get(cls, {}),
                         **_channels(cls)})
    for k, (name, (shape, scale)) in enumerate(inputs.items()):
        top.children.append(Node("module", {"class": "Wave", "name": f"W{k}", "start": str(k),
                                            "shape": ",".join(map(str, shape)),
                                            "scale": str(scale)}))
    top.children.append(module)
    for k, name in enumerate(inputs):
        top.children.append(Node("connection", {"source": f"W{k}.OUTPUT",
                                                "target": f"M.{name}", "delay": "0"}))
    path = os.path.join(folder, f"{stem}.ikg")
    write_file(top, path)
    return path


def _cases(cls: str, folder: str) -> list[str]:
    """The harness models to try, first the one most like the class's own example."""
    example = _from_example(cls)
    if example is not None:
        return [_harness(cls, folder, *example)]
    element = Node("module", {"class": cls}, [e.copy() for e in ELEMENTS.get(cls, ())])
    description = stdlib_classes()[cls].description()
    if any(p.name == "seed" for p in description.parameters):
        element.attrs["seed"] = "1"
    if cls in INPUTS:
        return [_harness(cls, folder, {}, element, INPUTS[cls])]
    required = [i.name for i in description.inputs if not i.optional]
    return [_harness(cls, folder, {}, element, {n: (shape, 1) for n in required},
                     f"harness{k}") for k, shape in enumerate(SHAPES)]


def _trace(path: str, compiled: str, apply: str | None) -> list[dict]:
    """Every output and input after each of the last AFTER ticks of BEFORE + AFTER."""
    net = ikaros.load(path, quiet=True, compiled=compiled)
    try:
        for _ in range(BEFORE):
            net.step()
        if apply is not None:
            tree = net.model.copy()
            if apply == "changed":
                tree.children.insert(0, Node("module", {"class": "Constant", "name": "First",
                                                        "data": "1 2 3 4 5 6 7"}))
            net = net.apply(tree)
        rows = []
        for _ in range(AFTER):
            net.step()
            rows.append({f"{inst.path}.{name}": net.output(f"{inst.path}.{name}")
                         for inst in net.schedule if inst.path != "First"
                         for name in list(inst.module._ik_outputs) +
                         list(inst.module._ik_inputs)})
        return rows
    finally:
        net.close()


def _files(folder: str) -> None:
    """The files the harness models read: the examples' data, a sound, a recording."""
    for item in os.listdir(EXAMPLES):
        if os.path.isfile(os.path.join(EXAMPLES, item)) and not item.endswith(".ikg"):
            shutil.copy(os.path.join(EXAMPLES, item), folder)
    with wave.open(os.path.join(folder, "sound.wav"), "wb") as f:
        f.setnchannels(1)
        f.setsampwidth(2)
        f.setframerate(8000)
        f.writeframes(b"".join(int(8000 * math.sin(k / 3)).to_bytes(2, "little", signed=True)
                               for k in range(400)))
    model = ikaros.Group("Rec")
    model.module("Sweep", "Ramp", min=0, max=1, step=0.125)
    with model.build(quiet=True) as net:
        recorder = net.record(os.path.join(folder, "recording.h5"), only="Ramp.*")
        net.run(ticks=20)
        recorder.close()


@pytest.mark.parametrize("compiled", ["no", "yes"])
@pytest.mark.parametrize("cls", _classes())
def test_every_output_follows_its_inputs_after_apply(cls, compiled, tmp_path):
    if compiled == "yes":
        pytest.importorskip("numba", reason="the compiled tick needs numba")
    folder = str(tmp_path)
    _files(folder)
    with open(os.path.join(folder, "Wave.py"), "w") as f:
        f.write(WAVE)
    errors = []
    for path in _cases(cls, folder):
        try:
            fresh = _trace(path, compiled, None)
        except (ikaros.ModelError, ikaros.RunError) as e:
            errors.append(str(e))
            continue
        for change in ("unchanged", "changed"):
            applied = _trace(path, compiled, change)
            for tick, (want, got) in enumerate(zip(fresh, applied), start=BEFORE + 1):
                for port, value in want.items():
                    if _timed(cls, port) or (change == "changed" and port.startswith("M.") and
                                             port[2:] in COUNTS.get(cls, ())):
                        continue
                    np.testing.assert_allclose(
                        got[port], value, rtol=1e-6, atol=1e-9,
                        err_msg=f"{change} model, tick {tick}: {port}, after a fresh load")
        return
    pytest.fail(f"no harness model of {cls} runs:\n" + "\n".join(errors))

