"""The script's side, without a worker: the module proxy, hooks, returned values and
global names."""
import numpy as np
import pytest

from ikaros.scripted.proxy import ModuleProxy, copy_returned
from ikaros.scripted.script import Script, ScriptError


def _proxy(inputs=None, outputs=None, parameters=None, logged=None):
    inputs = {"INPUT": np.array([1, 2, 3], np.float32)} if inputs is None else inputs
    outputs = {"OUTPUT": np.zeros(3, np.float32)} if outputs is None else outputs
    parameters = {"gain": 2.0} if parameters is None else parameters
    sink = logged if logged is not None else []
    return ModuleProxy("S", "Main.S", inputs, outputs, parameters,
                       lambda level, text: sink.append((level, text)))


def _script(tmp_path, text, proxy=None, use_global_names=False, name="s.py"):
    path = tmp_path / name
    path.write_text(text)
    return Script(str(path), proxy or _proxy(), use_global_names)


def test_the_proxy_gives_ports_and_parameters_by_key_and_attribute():
    module = _proxy()
    assert module.inputs["INPUT"].tolist() == [1, 2, 3] and module.INPUT.tolist() == [1, 2, 3]
    assert module.outputs["OUTPUT"] is module.OUTPUT
    assert module.parameters["gain"] == 2.0 and module.gain == 2.0 and module.tick == -1
    module.set_parameters({"gain": 5.0})
    assert module.gain == 5.0 and module.parameters["gain"] == 5.0


def test_inputs_are_read_only_and_outputs_are_written_in_place():
    outputs = {"OUTPUT": np.zeros(3, np.float32)}
    module = _proxy(outputs=outputs)
    with pytest.raises(ValueError, match="read-only"):
        module.INPUT[0] = 9
    module.OUTPUT[:] = [4, 5, 6]
    assert outputs["OUTPUT"].tolist() == [4, 5, 6]
    with pytest.raises(TypeError):
        module.inputs["OTHER"] = np.zeros(1)


def test_an_unknown_name_is_an_attribute_error_naming_the_module():
    with pytest.raises(AttributeError, match="module Main.S has no input, output or "
                                             "parameter named 'nothing'"):
        _proxy().nothing


def test_the_logging_methods_send_their_level():
    logged = []
    module = _proxy(logged=logged)
    module.log("a")
    module.warning("b")
    module.error("c")
    module.debug(4)
    assert logged == [("print", "a"), ("warning", "b"), ("error", "c"), ("debug", "4")]


def test_returned_values_are_copied_into_the_outputs():
    outputs = {"A": np.zeros(2, np.float32), "B": np.zeros((2, 2), np.float32)}
    copy_returned("Main.S", outputs, {"A": [1.5, 2], "B": 7})
    assert outputs["A"].tolist() == [1.5, 2] and outputs["B"].tolist() == [[7, 7], [7, 7]]
    copy_returned("Main.S", outputs, None)
    with pytest.raises(ValueError, match=r"tick\(\) of Main.S returned shape \(3,\) for "
                                         r"output A, which has shape \(2,\)"):
        copy_returned("Main.S", outputs, {"A": [1, 2, 3]})
    with pytest.raises(ValueError, match="returned a value for 'C', which is not an output "
                                         r"\(outputs: A, B\)"):
        copy_returned("Main.S", outputs, {"C": 1})
    with pytest.raises(TypeError, match="returned a list; it may return None or a dict"):
        copy_returned("Main.S", outputs, [1, 2])


def test_hooks_take_the_module_or_nothing(tmp_path):
    script = _script(tmp_path, "calls = []\n"
                               "def init():\n    calls.append('init')\n"
                               "def tick(module):\n    module.OUTPUT[:] = module.INPUT * 2\n")
    script.call("init")
    script.call("tick")
    script.call("shutdown")             # none: nothing happens
    assert script.namespace["calls"] == ["init"]
    assert script.module.OUTPUT.tolist() == [2, 4, 6]
    assert script.has("init") and not script.has("shutdown")


def test_a_script_without_tick_is_an_error_naming_it(tmp_path):
    with pytest.raises(ScriptError, match=r"s.py defines no tick\(\) function"):
        _script(tmp_path, "def init(module):\n    pass\n")


def test_a_hook_with_two_arguments_is_an_error(tmp_path):
    with pytest.raises(ScriptError, match=r"tick\(\) in s.py must take no argument or one "
                                          r"\(the module\), not \(inputs, outputs\)"):
        _script(tmp_path, "def tick(inputs, outputs):\n    pass\n")


def test_a_syntax_error_names_the_file_and_line(tmp_path):
    with pytest.raises(ScriptError) as e:
        _script(tmp_path, "x = 1\ndef tick(:\n")
    assert str(e.value).startswith("s.py failed to load: SyntaxError")
    assert f'File "{tmp_path / "s.py"}", line 2' in e.value.traceback_text


def test_a_failing_hook_has_the_scripts_traceback_only(tmp_path):
    script = _script(tmp_path, "def helper():\n    raise KeyError('k')\n\n"
                               "def tick(module):\n    helper()\n")
    with pytest.raises(ScriptError) as e:
        script.call("tick")
    assert str(e.value) == "tick() of s.py failed: KeyError: 'k'"
    lines = e.value.traceback_text.splitlines()
    assert lines[0] == "Traceback (most recent call last):"
    assert lines[1] == f'  File "{tmp_path / "s.py"}", line 5, in tick'
    assert lines[3] == f'  File "{tmp_path / "s.py"}", line 2, in helper'
    assert lines[-1] == "KeyError: 'k'"
    assert "script.py" not in e.value.traceback_text


def test_logging_helpers_are_globals(tmp_path):
    logged = []
    script = _script(tmp_path, "log('loading')\ndef tick():\n    warning('w')\n    error('e')\n",
                     _proxy(logged=logged))
    script.call("tick")
    assert logged == [("print", "loading"), ("warning", "w"), ("error", "e")]


def test_global_names_are_the_ports_and_parameters(tmp_path):
    module = _proxy(outputs={"OUTPUT": np.zeros(3, np.float32),
                             "COUNT": np.zeros(1, np.float32)})
    script = _script(tmp_path, "def tick():\n    global COUNT\n"
                               "    OUTPUT[:] = INPUT * gain\n    COUNT = COUNT + 1\n",
                     module, use_global_names=True)
    script.call("tick")
    module.set_parameters({"gain": 10.0})
    script.call("tick")
    assert module.OUTPUT.tolist() == [10, 20, 30] and module.COUNT.tolist() == [2]
    assert script.namespace["COUNT"] is module.outputs["COUNT"]


def test_a_global_the_script_defines_clashes_with_a_parameter(tmp_path):
    with pytest.raises(ScriptError, match="use_global_names: s.py defines gain, which is "
                                          "also the parameter gain of Main.S"):
        _script(tmp_path, "gain = 3\ndef tick():\n    pass\n", use_global_names=True)


def test_ports_and_parameters_with_one_global_name_clash(tmp_path):
    module = _proxy(parameters={"INPUT": 1.0})
    with pytest.raises(ScriptError, match="use_global_names: the parameter INPUT and the "
                                          "input INPUT of Main.S are both the global INPUT"):
        _script(tmp_path, "def tick():\n    pass\n", module, use_global_names=True)


def test_without_global_names_a_script_may_use_any_name(tmp_path):
    script = _script(tmp_path, "gain = 3\nINPUT = 'mine'\ndef tick():\n    pass\n")
    assert script.namespace["gain"] == 3 and script.namespace["INPUT"] == "mine"
