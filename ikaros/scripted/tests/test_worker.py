"""Scripted modules with real worker processes: parameters, crashes, interpreters, and
that no worker outlives its run, however the run ends."""
import os
import signal
import subprocess
import sys
import time

import pytest

import ikaros
from ikaros.module import WARNING

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))

IKC = '''<class name="Probe" python="probe.py">
    <parameter name="gain" type="number" default="1"/>
    <parameter name="folder" type="string" default=""/>
    <parameter name="fail_tick" type="number" default="-5"/>
    <input name="INPUT"/>
    <output name="OUTPUT" size="INPUT.size"/>
</class>
'''

SCRIPT = '''import os, signal, time


def init(module):
    with open(os.path.join(module.folder, "pid"), "w") as f:
        f.write(str(os.getpid()))
    print("probe ready", flush=True)


def tick(module):
    if module.tick == module.fail_tick:
        raise RuntimeError("failing as asked")
    if module.tick == module.fail_tick + 100:
        os.kill(os.getpid(), signal.SIGKILL)
    if module.tick == module.fail_tick + 200:
        os.write(2, b"written to fd 2\\n")
    time.sleep(0.002)
    module.OUTPUT[:] = module.INPUT * module.gain


def shutdown(module):
    with open(os.path.join(module.folder, "shutdown"), "w") as f:
        f.write(f"after tick {module.tick}")
'''

MODEL = '''<group name="M" folder="{folder}" stop="{stop}" tick_duration="0.01">
    <module class="Constant" name="C" data="1 2"/>
    <module class="Probe" name="S" {attrs}/>
    <connection source="C.OUTPUT" target="S.INPUT" delay="0"/>
</group>
'''


def _model(tmp_path, attrs="", stop=-1):
    (tmp_path / "Probe.ikc").write_text(IKC)
    (tmp_path / "probe.py").write_text(SCRIPT)
    path = tmp_path / "m.ikg"
    path.write_text(MODEL.format(folder=tmp_path, stop=stop, attrs=attrs))
    return str(path)


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def _gone_soon(pid: int, seconds: float = 5.0) -> bool:
    deadline = time.monotonic() + seconds
    while _alive(pid):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


def _worker_pid(tmp_path) -> int:
    return int((tmp_path / "pid").read_text())


def test_a_parameter_change_reaches_the_script_before_its_next_tick(tmp_path):
    with ikaros.load(_model(tmp_path), quiet=True) as net:
        net.step()
        assert net.output("S.OUTPUT").tolist() == [1, 2]
        net.set_parameter("S.gain", 5)
        net.step()
        assert net.output("S.OUTPUT").tolist() == [5, 10]


def test_close_runs_shutdown_and_ends_the_worker(tmp_path):
    net = ikaros.load(_model(tmp_path), quiet=True)
    net.run(3)
    pid = _worker_pid(tmp_path)
    assert _alive(pid)
    assert not os.path.exists(net.modules["S"].module._ik_shared.path)    # mapped, not named
    net.close()
    assert (tmp_path / "shutdown").read_text() == "after tick 2"
    assert not _alive(pid)


def test_a_fatal_error_ends_the_worker_after_shutdown(tmp_path):
    net = ikaros.load(_model(tmp_path, 'fail_tick="1"'), quiet=True)
    with pytest.raises(ikaros.RunError, match=r"tick\(\) of probe.py failed: RuntimeError: "
                                              r"failing as asked"):
        net.run(5)
    assert (tmp_path / "shutdown").read_text() == "after tick 1"
    assert not _alive(_worker_pid(tmp_path))


def test_a_worker_killed_by_a_signal_is_a_fatal_error_naming_it(tmp_path):
    net = ikaros.load(_model(tmp_path, 'fail_tick="-99"'), quiet=True)
    with pytest.raises(ikaros.RunError, match=r"the worker process of S \(probe.py\) was "
                                              r"killed by signal 9 \(SIGKILL\)"):
        net.run(5)
    assert not _alive(_worker_pid(tmp_path))


def test_what_the_process_writes_to_its_stderr_is_a_warning(tmp_path):
    with ikaros.load(_model(tmp_path, 'fail_tick="-198"'), quiet=True) as net:
        net.run(4)
        deadline = time.monotonic() + 5
        while not any(m == "written to fd 2" for *_, m in net.log):
            assert time.monotonic() < deadline
            time.sleep(0.02)
        assert (WARNING, "S", "written to fd 2") in [entry[1:] for entry in net.log]


def test_an_interpreter_that_cannot_run_the_worker_is_named_with_its_output(tmp_path):
    fake = tmp_path / "fakepython"
    fake.write_text("#!/bin/sh\necho 'ModuleNotFoundError: no numpy here' >&2\nexit 4\n")
    fake.chmod(0o755)
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(_model(tmp_path, f'python_executable="{fake}"'), quiet=True)
    assert e.value.reason == (f"init failed: ScriptError: the worker process of S ({fake}) "
                              f"ended with exit code 4 before its script started\n"
                              f"ModuleNotFoundError: no numpy here")


def test_a_missing_interpreter_is_named(tmp_path):
    missing = tmp_path / "no" / "python"
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(_model(tmp_path, f'python_executable="{missing}"'), quiet=True)
    assert e.value.reason == (f"init failed: ScriptError: the Python interpreter {missing} "
                              f"(python_executable) for S cannot be started: No such file "
                              f"or directory")


def _cli(tmp_path, *extra):
    env = dict(os.environ, PYTHONPATH=REPO + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.Popen([sys.executable, "-m", "ikaros", "-b", "-r", *extra,
                             _model(tmp_path, stop=100000)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            start_new_session=True)
    for line in proc.stdout:            # the script's init has run
        if "probe ready" in line:
            return proc
    raise AssertionError(f"the model did not start (exit {proc.wait()})")


@pytest.mark.parametrize("how", ["SIGTERM", "Ctrl-C"])
def test_ending_the_command_runs_shutdown_and_leaves_no_worker(tmp_path, how):
    proc = _cli(tmp_path)
    pid = _worker_pid(tmp_path)
    time.sleep(0.1)
    if how == "Ctrl-C":      # a terminal sends SIGINT to the worker too, which ignores it
        os.killpg(proc.pid, signal.SIGINT)
    else:
        proc.send_signal(signal.SIGTERM)
    output = proc.communicate(timeout=10)[0]
    assert "ikaros: interrupted" in output
    assert (tmp_path / "shutdown").read_text().startswith("after tick ")
    assert _gone_soon(pid)


def test_a_killed_kernel_leaves_no_worker(tmp_path):
    proc = _cli(tmp_path)
    pid = _worker_pid(tmp_path)
    proc.kill()
    proc.wait(timeout=5)
    proc.stdout.close()
    assert _gone_soon(pid)


def test_settings_are_inherited_and_states_are_not_the_scripts(tmp_path):
    """on_error from a group around the module; a <state> of the class is the kernel's,
    not one of the script's outputs; with on_error="log" what the failing tick wrote to
    an accumulating output is dropped."""
    (tmp_path / "Acc.ikc").write_text('<class name="Acc" python="acc.py">\n'
                                      '    <output name="OUTPUT" size="1"/>\n'
                                      '    <state name="MEMORY" shape="2"/>\n</class>\n')
    (tmp_path / "acc.py").write_text("def tick(module):\n"
                                     "    assert list(module.outputs) == ['OUTPUT']\n"
                                     "    module.OUTPUT[0] += 1\n"
                                     "    if module.tick == 1:\n"
                                     "        raise ValueError('x')\n")
    # an Ikaros 2 file (its Ikaros 3 class file beside it would make it Ikaros 3's): the
    # second tick is tick 1
    (tmp_path / "m.ikg").write_text('<group name="M" on_error="log" dialect="2"><group name="G">'
                                    '<module class="Acc" name="A"/></group></group>')
    with ikaros.load(str(tmp_path / "m.ikg"), quiet=True) as net:
        seen = []
        for _ in range(4):
            net.step()
            seen.append(net.output("G.A.OUTPUT").tolist())
        assert seen == [[1], [1], [2], [3]] and net.parameter("G.A.on_error") == "log"


def test_a_model_applied_again_keeps_its_worker_until_the_script_changes(tmp_path):
    """The editor's Apply: a scripted module that did not change goes on with its worker
    (its init does not run again, and the old network does not end it); when its script
    has changed, the new network's module starts a worker of its own and the old one ends."""
    net = ikaros.load(_model(tmp_path, 'gain="3"'), quiet=True)
    net.run(2)
    old_pid = _worker_pid(tmp_path)
    new = net.apply(net.model)
    try:
        assert _worker_pid(tmp_path) == old_pid and _alive(old_pid)
        assert new.output("S.OUTPUT").tolist() == [3, 6]
        new.set_parameter("S.gain", 2)
        new.step()
        assert new.output("S.OUTPUT").tolist() == [2, 4]
        (tmp_path / "probe.py").write_text(SCRIPT.replace("module.INPUT * module.gain",
                                                          "module.INPUT * module.gain + 1"))
        newer = new.apply(new.model)
    except BaseException:
        new.close()
        raise
    try:
        new_pid = _worker_pid(tmp_path)
        assert new_pid != old_pid and _gone_soon(old_pid) and _alive(new_pid)
        newer.step()
        assert newer.output("S.OUTPUT").tolist() == [3, 5]
    finally:
        newer.close()
    assert not _alive(new_pid)


def _class(tmp_path, ikc_body: str, script: str, model_body: str) -> str:
    (tmp_path / "K.ikc").write_text(f'<class name="K" python="k.py">\n{ikc_body}\n</class>\n')
    (tmp_path / "k.py").write_text(script)
    (tmp_path / "m.ikg").write_text(f'<group name="M">\n{model_body}\n</group>\n')
    return str(tmp_path / "m.ikg")


def test_an_alias_output_views_what_the_script_writes(tmp_path):
    model = _class(tmp_path, '<output name="OUTPUT" size_x="3" size_y="2"/>\n'
                             '<output name="ROW" alias="OUTPUT[1]"/>',
                   "def tick(module):\n"
                   "    assert sorted(module.outputs) == ['OUTPUT']\n"
                   "    module.OUTPUT[:] = [[1, 2, 3], [4, 5, 6]]\n",
                   '<module class="K" name="S"/>')
    with ikaros.load(model, quiet=True) as net:
        net.step()
        assert net.output("S.ROW").tolist() == [4, 5, 6]


def test_a_dynamic_output_is_refused_at_the_class_file(tmp_path):
    model = _class(tmp_path, '<output name="OUTPUT" dynamic="yes" capacity="4"/>',
                   "def tick():\n    pass\n", '<module class="K" name="S"/>')
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(model, quiet=True)
    assert "a class written as a Python script cannot have dynamic outputs (OUTPUT)" in \
        str(e.value) and "K.ikc:1" in str(e.value)


def test_an_input_fed_by_a_dynamic_output_is_refused(tmp_path):
    support = os.path.join(REPO, "ikaros", "testsupport")
    model = _class(tmp_path, '<input name="INPUT"/>\n<output name="OUTPUT" size="1"/>',
                   "def tick():\n    pass\n",
                   f'<module class="DynamicMatrixSource" name="D" path="{support}"/>\n'
                   '<module class="K" name="S"/>\n'
                   '<connection source="D.OUTPUT" target="S.INPUT"/>')
    with pytest.raises(ikaros.ModelError, match="init failed: ScriptError: the input INPUT "
                                                "of S is fed by a dynamic output, which a "
                                                "class written as a Python script cannot "
                                                "take"):
        ikaros.load(model, quiet=True)


def test_the_worker_does_not_need_ikaros(tmp_path):
    """The worker runs with an interpreter in which ``import ikaros`` fails."""
    blocker = tmp_path / "blocker" / "ikaros"
    blocker.mkdir(parents=True)
    (blocker / "__init__.py").write_text("raise ImportError('the worker imported ikaros')\n")
    python = tmp_path / "python-without-ikaros"
    python.write_text(f'#!/bin/sh\nPYTHONPATH="{blocker.parent}" exec "{sys.executable}" "$@"\n')
    python.chmod(0o755)
    model = _class(tmp_path, '<input name="INPUT"/>\n<output name="OUTPUT" size="1"/>',
                   "import sys\n\ndef tick(module):\n"
                   "    assert 'ikaros' not in sys.modules\n"
                   "    module.OUTPUT[0] = module.INPUT.sum()\n",
                   '<module class="Constant" name="C" data="1 2"/>\n'
                   f'<module class="K" name="S" python_executable="{python}"/>\n'
                   '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>')
    with ikaros.load(model, quiet=True) as net:
        net.step()
        assert net.output("S.OUTPUT").tolist() == [3]
