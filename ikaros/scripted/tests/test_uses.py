"""Scripted modules where a researcher meets them: commands from the user interface, state
files and resets, a model built in Python code, and recordings."""
import os
import subprocess
import sys

import numpy as np
import pytest

import ikaros

IKC = '''<class name="Acc" python="acc.py">
    <parameter name="gain" type="number" default="1"/>
    <input name="INPUT"/>
    <output name="OUTPUT" size="INPUT.size"/>
</class>
'''

SCRIPT = '''count = 0


def tick(module):
    module.OUTPUT[:] += module.INPUT * module.gain
'''

COMMAND = '''

def command(module, name, x, y, value):
    print(f"{name} {x} {y} {value} gain={module.gain}")
    if name == "set":
        module.OUTPUT[:] = value
    if name == "half-set":
        module.OUTPUT[:] = 99
        raise ValueError("refused")
'''

MODEL = '''<group name="M">
    <module class="Constant" name="C" data="1 2 3"/>
    <module class="Acc" name="A"/>
    <connection source="C.OUTPUT" target="A.INPUT" delay="0"/>
</group>
'''


def _model(tmp_path, script=SCRIPT):
    (tmp_path / "Acc.ikc").write_text(IKC)
    (tmp_path / "acc.py").write_text(script)
    (tmp_path / "m.ikg").write_text(MODEL)
    return str(tmp_path / "m.ikg")


def _messages(net):
    return [m for _, _, path, m in net.log if path == "A"]


def test_a_command_reaches_the_script_with_its_details_and_the_parameters(tmp_path):
    with ikaros.load(_model(tmp_path, SCRIPT + COMMAND), quiet=True) as net:
        net.run(2)
        net.set_parameter("A.gain", 4)
        net.command("A", "set", 1, 2, [10, 20, 30])
        assert net.output("A.OUTPUT").tolist() == [10, 20, 30]
        assert _messages(net)[-1] == "set 1.0 2.0 [10, 20, 30] gain=4.0"
        net.command("A", "set", value=np.array([1.5, 0, 0]))
        assert net.output("A.OUTPUT").tolist() == [1.5, 0, 0]
        net.step()
        assert net.output("A.OUTPUT").tolist() == [5.5, 8, 12]


def test_a_failing_command_is_the_commands_error_and_changes_no_output(tmp_path):
    with ikaros.load(_model(tmp_path, SCRIPT + COMMAND), quiet=True) as net:
        net.run(2)
        with pytest.raises(RuntimeError, match=r"command\(\) of acc.py failed: ValueError: "
                                               r"refused\n(?s:.*)acc.py\", line 14, in command"):
            net.command("A", "half-set")
        assert net.output("A.OUTPUT").tolist() == [2, 4, 6]
        net.step()                                  # the run goes on from what it had
        assert net.output("A.OUTPUT").tolist() == [3, 6, 9]
        with pytest.raises(RuntimeError, match="the value of command set for A cannot be "
                                               "sent to acc.py"):
            net.command("A", "set", value=object())


@pytest.mark.parametrize("signature, seen", [
    ("module, name", "set"),
    ("module, name, x, y=0", "set 3.0 0.0"),
    ("*details", "set 3.0 0.0 None"),
])
def test_a_command_hook_takes_as_many_details_as_it_names(tmp_path, signature, seen):
    names = "details[1:]" if signature == "*details" else \
        "(" + ", ".join(p.split("=")[0] for p in signature.split(", ")[1:]) + ",)"
    script = SCRIPT + f"\n\ndef command({signature}):\n    print(*{names})\n"
    with ikaros.load(_model(tmp_path, script), quiet=True) as net:
        net.command("A", "set", 3)
        assert _messages(net)[-1] == seen


def test_a_script_without_a_command_hook_takes_no_commands(tmp_path):
    with ikaros.load(_model(tmp_path), quiet=True) as net:
        with pytest.raises(RuntimeError, match=r"A takes no commands \(acc.py defines no "
                                               r"command\(\) function\)"):
            net.command("A", "reset")


def test_a_command_hook_that_cannot_take_a_name_is_an_error_at_start(tmp_path):
    with pytest.raises(ikaros.ModelError, match=r"command\(\) in acc.py must take "
                                                r"\(module, name\)"):
        ikaros.load(_model(tmp_path, SCRIPT + "\n\ndef command(module):\n    pass\n"),
                    quiet=True)


def test_a_loaded_state_and_a_reset_are_what_the_script_accumulates_on(tmp_path):
    model = _model(tmp_path)
    state = str(tmp_path / "m.state")
    with ikaros.load(model, quiet=True) as net:
        net.run(3)
        assert net.output("A.OUTPUT").tolist() == [3, 6, 9]
        net.save_state(state)
    with ikaros.load(model, quiet=True, load_state=state) as net:
        assert net.output("A.OUTPUT").tolist() == [3, 6, 9]
        net.step()
        assert net.output("A.OUTPUT").tolist() == [4, 8, 12]
        net.reset_state()
        assert net.output("A.OUTPUT").tolist() == [0, 0, 0]
        net.step()
        assert net.output("A.OUTPUT").tolist() == [1, 2, 3]


INTERRUPT = '''from ikaros.module import Module


class Interrupt(Module):
    def init(self):
        raise KeyboardInterrupt
'''

INIT_FAILS = '''def init():
    raise ValueError("no start")


def tick():
    pass
'''


def _my_workers(descendants: bool = False) -> list[int]:
    """The worker processes of this process (or of its descendants) that still run."""
    parents, workers = {}, []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/stat") as f:
                state, parent = f.read().rsplit(")", 1)[1].split()[:2]
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                command = f.read()
        except (FileNotFoundError, ProcessLookupError):
            continue
        parents[int(pid)] = int(parent)
        if state != "Z" and b"scripted/worker.py" in command:
            workers.append(int(pid))

    def mine(pid):
        while (pid := parents.get(pid, 0)) > 1:
            if pid == os.getpid():
                return True
            if not descendants:
                return False
        return False
    return [pid for pid in workers if mine(pid)]


def _three(tmp_path, middle: str) -> str:
    _model(tmp_path)
    (tmp_path / "Interrupt.py").write_text(INTERRUPT)
    (tmp_path / "Fails.ikc").write_text('<class name="Fails" python="fails.py"/>')
    (tmp_path / "fails.py").write_text(INIT_FAILS)
    (tmp_path / "three.ikg").write_text(f'''<group name="M">
    <module class="Constant" name="C" data="1 2 3"/>
    <module class="Acc" name="A"/>
    <module class="{middle}" name="X"/>
    <module class="Acc" name="B"/>
    <connection source="C.OUTPUT" target="A.INPUT"/>
    <connection source="C.OUTPUT" target="B.INPUT"/>
</group>
''')
    return str(tmp_path / "three.ikg")


def test_workers_start_together_and_a_failed_start_leaves_none(tmp_path):
    assert _my_workers() == []
    with pytest.raises(ikaros.ModelError, match=r'<module name="X">: init failed: '
                                                r'ScriptError: init\(\) of fails.py failed'):
        ikaros.load(_three(tmp_path, "Fails"), quiet=True)
    assert _my_workers() == []


def test_ctrl_c_while_the_modules_start_leaves_no_worker(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        ikaros.load(_three(tmp_path, "Interrupt"), quiet=True)
    assert _my_workers() == []


def test_a_model_in_code_with_a_scripted_class_from_a_folder(tmp_path):
    _model(tmp_path)
    model = ikaros.Group("M")
    model.module("Constant", "C", data="1 2 3")
    model.module("Acc", "A", gain=2, path=str(tmp_path))
    model.connect("C.OUTPUT", "A.INPUT", delay=0)
    net = model.build()
    (worker,) = _my_workers()
    net.run(2)
    net.set_parameter("A.gain", 0.5)
    net.step()
    assert net.output("A.OUTPUT").tolist() == [4.5, 9, 13.5]
    shared = net.modules["A"].module._ik_shared.path
    net.close()
    assert _my_workers() == [] and not os.path.exists(shared)


def test_a_recording_has_the_scripted_modules_outputs(tmp_path):
    model = _model(tmp_path)
    recording = str(tmp_path / "run.h5")
    done = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-q", "-s", "3", "--record",
                           recording, model], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    ds = ikaros.open_recording(recording)
    assert ds["A.OUTPUT"].values.tolist() == [[1, 2, 3], [2, 4, 6], [3, 6, 9]]


def test_a_sweep_in_local_processes_over_a_scripts_parameter(tmp_path):
    table = ikaros.sweep(_model(tmp_path), {"A.gain": [1, 3]}, ticks=2,
                         record=["A.OUTPUT"], workers=2, progress=False)
    assert table["status"].tolist() == ["ok", "ok"]
    assert table[["A.OUTPUT[0]", "A.OUTPUT[2]"]].values.tolist() == [[2, 6], [6, 18]]
    assert _my_workers(descendants=True) == []


def test_the_command_line_lists_and_describes_a_scripted_class_beside_a_model(tmp_path):
    model = _model(tmp_path)

    def ikaros_command(*options):
        done = subprocess.run([sys.executable, "-m", "ikaros", *options, model],
                              capture_output=True, text=True, timeout=60)
        assert done.returncode == 0, done.stderr
        return done.stdout.splitlines()
    assert any(line.split() == ["Acc"] for line in ikaros_command("--classes"))
    described = ikaros_command("--class", "Acc")
    assert described[0] == "Acc"
    assert "  gain (number, default '1'): " in described
    assert described[-2:] == [f"Source: {tmp_path / 'Acc.ikc'}",
                              f"Script: {tmp_path / 'acc.py'} (runs in a worker process "
                              f"per module)"]
