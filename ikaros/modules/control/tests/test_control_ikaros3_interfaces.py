"""Today's Ikaros 3 interfaces of PIDController, KalmanFilter and Delta (the original's current
.ikc files, as listed in the reference's IKAROS3-INTERFACES): in an Ikaros 3 file each class
has every input, output and parameter, with the original's defaults."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

# class: (inputs {name: optional}, outputs, parameters {name: Ikaros 3 default}); a matrix
# parameter whose default is 0 is given as "0 matrix"
INTERFACES = {
    "PIDController": (
        {"INPUT": False, "SETPOINT": False, "RESET": True},
        ["OUTPUT", "DELTA", "FILTERED_SETPOINT", "FILTERED_INPUT", "FILTERED_ERROR_P",
         "FILTERED_ERROR_I", "FILTERED_ERROR_D", "INTEGRAL"],
        {"Kb": 0, "Kp": 0.1, "Ki": 0, "Kd": 0, "derivative_mode": "measurement", "Fs": 0,
         "Fm": 0, "Fp": 0, "Fi": 0, "Fd": 0, "Fc": 0, "Cmax": 1000, "Cmin": -1000,
         "output_rate_limit": 0}),
    "KalmanFilter": (
        {"INPUT": True, "INPUT_VALID": True, "OBSERVATION": False, "OBSERVATION_VALID": True,
         "RESET": True},
        ["STATE", "INNOVATION", "KALMAN_GAIN", "GATED", "NORMALIZED_INNOVATION"],
        {"process_noise": 1, "observation_noise": 1, "state_size": 1, "input_size": 1,
         "innovation_gate": 0, "inversion_jitter": 0, "A": "0 matrix", "B": "0 matrix",
         "H": "0 matrix", "Q": "0 matrix", "R": "0 matrix", "INITIAL_STATE": "0 matrix",
         "INITIAL_P": "0 matrix"}),
    "Delta": (
        {"CS": True, "US": True},
        ["CR"],
        {"alpha": 0.1, "inverse": False}),
}

# the smallest model of each class, with its required inputs connected
MODELS = {
    "PIDController": ('<module class="Constant" name="C" data="1, 2, 3"/>\n'
                      '<module class="PIDController" name="M"/>\n'
                      '<connection source="C.OUTPUT" target="M.INPUT"/>\n'
                      '<connection source="C.OUTPUT" target="M.SETPOINT"/>'),
    "KalmanFilter": ('<module class="Constant" name="C" data="1"/>\n'
                     '<module class="KalmanFilter" name="M"/>\n'
                     '<connection source="C.OUTPUT" target="M.OBSERVATION"/>'),
    "Delta": '<module class="Delta" name="M"/>',
}


@pytest.mark.parametrize("cls", sorted(INTERFACES))
@pytest.mark.parametrize("dialect", ["2", "3"])
def test_every_port_of_today_s_interface(tmp_path, cls, dialect):
    inputs, outputs, _ = INTERFACES[cls]
    net = load(tmp_path, MODELS[cls], dialect=dialect)
    try:
        declared_inputs, declared_outputs = net.ports("M")
        optional = {spec.name: spec.optional for spec in declared_inputs}
        for name, is_optional in inputs.items():
            assert name in optional, name
            assert optional[name] or not is_optional, name     # optional where the original is
        assert set(outputs) <= {spec.name for spec in declared_outputs}
    finally:
        net.close()


@pytest.mark.parametrize("cls", sorted(INTERFACES))
def test_every_parameter_with_its_ikaros_3_default(tmp_path, cls):
    _, _, parameters = INTERFACES[cls]
    net = load(tmp_path, MODELS[cls], dialect="3")
    try:
        for name, default in parameters.items():
            value = net.parameter(f"M.{name}")
            if default == "0 matrix":
                assert not np.any(value), name
            else:
                assert value == default, name
    finally:
        net.close()


def test_output_sizes_in_an_ikaros_3_file(tmp_path):
    # KalmanFilter: STATE @state_size, INNOVATION OBSERVATION.size, KALMAN_GAIN (STATE.size,
    # OBSERVATION.size), GATED and NORMALIZED_INNOVATION 1; PIDController: INPUT.shape
    net = load(tmp_path, '<module class="Constant" name="Z" data="1, 2"/>\n'
                         '<module class="KalmanFilter" name="M" state_size="3"/>\n'
                         '<connection source="Z.OUTPUT" target="M.OBSERVATION"/>\n' +
               MODELS["PIDController"].replace('name="M"', 'name="P"').replace("M.", "P."),
               dialect="3")
    try:
        shapes = {name: net.output(f"M.{name}").shape for name in INTERFACES["KalmanFilter"][1]}
        assert shapes == {"STATE": (3,), "INNOVATION": (2,), "KALMAN_GAIN": (3, 2),
                          "GATED": (1,), "NORMALIZED_INNOVATION": (1,)}
        assert all(net.output(f"P.{name}").shape == (3,)
                   for name in INTERFACES["PIDController"][1])
    finally:
        net.close()
