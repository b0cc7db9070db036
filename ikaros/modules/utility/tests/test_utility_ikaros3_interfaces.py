"""The utility classes whose Ikaros 3 interface grew (issue 36) accept, in an Ikaros 3 file,
every input, output and parameter that today's class file declares, with its defaults
(facts from the reference's IKAROS3-INTERFACES.md)."""
import pytest

from ikaros.testing import load_body as load

# class: (inputs, outputs, parameter defaults), as IKAROS3-INTERFACES.md lists them
INTERFACES = {
    "Arbiter": (["INPUT", "VALUE"],
                ["AMPLITUDES", "ARBITRATION", "SMOOTHED", "NORMALIZED", "OUTPUT"],
                {"metric": "1", "arbitration": "WTA", "softmax_exponent": 2,
                 "hysteresis_threshold": 5, "switch_time": 0, "alpha": 1,
                 "stack_inputs": True, "stack_values": False, "debug": False}),
    "Noise": (["INPUT"], ["OUTPUT"],
              {"type": "uniform", "min": -0.1, "max": 0.1, "mean": 0, "stddev": 0.1,
               "seed": -1}),
    "Randomizer": ([], ["OUTPUT"], {"size": "2,3", "min": 0, "max": 1, "seed": -1}),
    "RegressionStatistics": (["X", "Y", "SAMPLE"],
                             ["SCATTER_X", "SCATTER_Y", "SAMPLE_COUNT", "LINEAR_REGRESSION",
                              "MODEL_COMPARISON"],
                             {"max_samples": 1024, "labels": ""}),
    "RotationConverter": (["INPUT"], ["OUTPUT"],
                          {"input_format": "xyz", "output_format": "xyz",
                           "angle_unit": "degrees", "size_x": 4, "size_y": 4}),
    "System": ([], ["TICK", "TIME", "NOMINAL_TIME", "REAL_TIME", "UPTIME", "RUN_STATE",
                    "STATE", "TICK_DURATION", "ACTUAL_DURATION", "TICK_TIME_USAGE", "LAG",
                    "TICKS_PER_S", "CPU_USAGE", "TIME_USAGE", "IDLE_RATIO", "OVERLOAD",
                    "PROGRESS", "STOP_AFTER_KNOWN", "CPU_CORES", "MODULE_COUNT",
                    "CLASS_COUNT"], {}),
    "OneHotVector": (["INPUT"], ["OUTPUT"], {"value": 1, "output_size": 10}),
}
# an input each class needs connected, fed by a Constant
FED = {"Arbiter": {"INPUT": "1, 2"}, "Noise": {"INPUT": "1, 2"},
       "RegressionStatistics": {"X": "1", "Y": "2, 3", "SAMPLE": "1"},
       "RotationConverter": {"INPUT": "1, 2, 3"}, "OneHotVector": {"INPUT": "3"}}


@pytest.mark.parametrize("cls", sorted(INTERFACES))
def test_today_s_ikaros_3_interface_with_its_defaults(tmp_path, cls):
    inputs, outputs, defaults = INTERFACES[cls]
    body = f'<module class="{cls}" name="M"/>'
    for k, (port, data) in enumerate(FED.get(cls, {}).items()):
        body += (f'<module class="Constant" name="C{k}" data="{data}"/>'
                 f'<connection source="C{k}.OUTPUT" target="M.{port}" delay="0"/>')
    with load(tmp_path, body, dialect="3") as net:
        declared_inputs, declared_outputs = net.ports("M")
        assert set(inputs) <= {spec.name for spec in declared_inputs}
        assert set(outputs) <= {spec.name for spec in declared_outputs}
        for name, value in defaults.items():
            assert net.parameter(f"M.{name}") == value, name
        net.run(ticks=2)
        for name in outputs:
            net.output(f"M.{name}")
