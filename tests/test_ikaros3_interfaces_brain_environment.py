"""The classes of brain/ and environment/ that Ikaros 3 has too accept every input, output and
parameter of Ikaros 3's current interface, with its defaults in an Ikaros 3 file. The names
and defaults below are the facts of shared/reference/IKAROS3-INTERFACES.md (the original's
current .ikc files): inputs, outputs, and name=default for each parameter."""
import re

import numpy as np
import pytest

from ikaros.kernel.classes import ClassRegistry

INTERFACES = {
    "BalkeniusReactiveControl": (
        "SENSORS ODOUR",
        "MOTOR SENSORY NODES RAW_MOTOR",
        "behavior=0 weights=0,0,0,0,0,0 a=0.20 b=0.08 c=0.04 theta=0.05 motor_threshold=0 "
        "gain=1 max_motor=0.25 odour_channel=0"),
    "Cerebellum": (
        "INPUT STATE TARGET",
        "OUTPUT",
        "learning_rate=0.1 isi_mu=0 isi_sigma=0 isi_tau=0"),
    "Concentration": (
        "INPUT",
        "OUTPUT",
        "alpha=0.1 beta=0.0001 gamma=0.25"),
    "ConductanceNeuronPopulation": (
        "CURRENT EXCITATORY_CONDUCTANCE INHIBITORY_CONDUCTANCE RESET",
        "SPIKES SPIKE_COUNT FIRING_RATE VOLTAGE RECOVERY",
        "population_size=1 model=0 initial_voltage=-65 spike_threshold=0 "
        "excitatory_reversal_potential=0 inhibitory_reversal_potential=-80 "
        "maximum_internal_step=0.000025 hh_capacitance_density=1 hh_sodium_conductance=120 "
        "hh_potassium_conductance=36 hh_leak_conductance=0.3 hh_sodium_reversal_potential=50 "
        "hh_potassium_reversal_potential=-77 hh_leak_reversal_potential=-54.387 "
        "ml_capacitance_density=20 ml_calcium_conductance=4.4 ml_potassium_conductance=8 "
        "ml_leak_conductance=2 ml_calcium_reversal_potential=120 "
        "ml_potassium_reversal_potential=-84 ml_leak_reversal_potential=-60 "
        "ml_activation_midpoint=-1.2 ml_activation_slope=18 ml_recovery_midpoint=2 "
        "ml_recovery_slope=30 ml_recovery_time_constant=0.025"),
    "IntegrateAndFirePopulation": (
        "INPUT EXCITATION INHIBITION RESET",
        "SPIKES SPIKE_COUNT FIRING_RATE VOLTAGE ADAPTATION",
        "population_size=1 model=0 membrane_time_constant=0.02 membrane_resistance=100 "
        "resting_potential=-65 threshold=-50 reset_potential=-65 initial_potential=-65 "
        "refractory_period=0.002 slope_factor=2 adaptation_time_constant=0.1 "
        "subthreshold_adaptation=4 spike_adaptation=0.08 quadratic_gain=0.004 "
        "maximum_internal_step=0.0001"),
    "LeakyIntegrator": (
        "EXCITATION INHIBITION",
        "OUTPUT",
        "decay_type=0 decay_rate=0 excitation_gain=1 inhibition_gain=1"),
    "Nucleus": (
        "EXCITATION INHIBITION SHUNTING_INHIBITION",
        "X OUTPUT",
        "alpha=0 beta=1 gamma=1 delta=1 psi=1.0 sigma=0 seed=-1 theta=0 time_constant=1 "
        "epsilon=1 scale_inputs=yes output_offset=0 output_scale=1 activation_function=atan "
        "burst_duration=0 refractory_period=0 reset_level=0 burst_level=1 burst_time=0"),
    "PlanarArm": (
        "JOINT_COMMAND GRIPPER RESET",
        "JOINT_ANGLES JOINT_POSITIONS END_EFFECTOR MOVABLE_OBJECT LINK_CONTACTS "
        "GRIPPER_CONTACTS OBJECT_CONTACTS BLOCKED ENCLOSED ARM_LINES OBJECTS WALLS",
        "base_position=60,150 link_lengths=65,55,45 link_width=6 "
        "initial_joint_angles=0,-0.5,0.8 joint_min=-3.141593,-3.141593,-3.141593 "
        "joint_max=3.141593,3.141593,3.141593 max_joint_step=0.01 initial_gripper=1 "
        "palm_length=34 finger_length=32 gripper_width=5 finger_open_angle=0.45 "
        "finger_closed_angle=0.65 movable_object=205,150,12 circle_obstacle_count=2 "
        "circle_obstacles=245,105,18;245,205,18 line_obstacle_count=4 "
        "line_obstacles=20,20,280,20,5;280,20,280,280,5;280,280,20,280,5;20,280,20,20,5 "
        "world_width=300 world_height=300 solver_iterations=64"),
    "RatePopulation": (
        "INPUT EXCITATION INHIBITION MODULATION RESET",
        "OUTPUT ACTIVATION",
        "population_size=1 activation_function=0 time_constant=0.02 gain=1 bias=0 "
        "sigmoid_midpoint=0 minimum_output=0 maximum_output=100 initial_output=0"),
    "RingWorld": (
        "STIMULI AUDITORY_STIMULI DISTAL_STIMULI GAZE TRACKING",
        "FOVEA REWARD PUNISHMENT RETINA AUDITORY_MAP DISTAL_RETINA",
        "field_of_view=120 fixation_margin=4 retina_width=25"),
    "SalienceIntegrator": (
        "INPUT",
        "OUTPUT",
        "factors=1 decay=0.9"),
    "SpikeGenerator": (
        "RATE TRIGGER ENABLE RESET",
        "SPIKES SPIKE_COUNT FIRING_RATE EFFECTIVE_RATE PHASE",
        "population_size=1 mode=0 firing_rate=10 initial_phase=0 refractory_period=0 "
        "trigger_mode=0 seed=-1"),
    "SpikingPopulation": (
        "EXCITATION INHIBITION DIRECT_IN INTERNAL_TOPOLOGY EXCITATION_TOPOLOGY",
        "OUTPUT",
        "population_size=1 substeps=2 model_type=0 neuron_type=0 threshold=30 "
        "debugmode=false"),
    "WilsonCowan": (
        "EXTERNAL_EXCITATION EXTERNAL_INHIBITION",
        "EXCITATORY_RATE INHIBITORY_RATE EXCITATORY_TARGET INHIBITORY_TARGET",
        "model=1 excitatory_time_constant=0.01 inhibitory_time_constant=0.01 "
        "excitatory_self_weight=0.8 inhibitory_to_excitatory_weight=0.6 "
        "excitatory_to_inhibitory_weight=0.7 inhibitory_self_weight=0.4 "
        "excitatory_sigmoid_gain=0.15 inhibitory_sigmoid_gain=0.15 "
        "excitatory_sigmoid_midpoint=10 inhibitory_sigmoid_midpoint=10 "
        "excitatory_maximum_response=100 inhibitory_maximum_response=100 "
        "excitatory_response_maximum=1 inhibitory_response_maximum=1 "
        "excitatory_refractory_period=0.002 inhibitory_refractory_period=0.002 "
        "initial_excitatory_rate=0 initial_inhibitory_rate=0"),
    "World2D": (
        "MOTOR",
        "CREATURE OBJECTS WALLS POSE CONTACT WHISKERS ODOUR REINFORCEMENT REWARD PUNISHMENT "
        "EDIT_OBJECT_ENABLE EDIT_WALL_ENABLE EDIT_COLOR_ENABLE",
        "world_width=300 world_height=300 creature_x=150 creature_y=150 creature_heading=0 "
        "creature_radius=4 wheel_radius=1 wheel_base=6 max_motor_rpt=0.25 whisker_length=10 "
        "whisker_angle=0.7853981633974483 odour_decay=0.01 edit_tool=0 edit_type=0 "
        "edit_value=0 edit_opaque=1 edit_smell=0,0,0,0,0,0,0,0 edit_color=0,0,0 "
        "food=1,70,70,5,1,0.20,0.70,0.25,0,1,0,0,0,0,0,0,0;"
        "2,225,215,7,1,0.95,0.70,0.15,0,0,1,0,0,0,0,0,0 "
        "aversive=3,210,85,10,-1,0.85,0.20,0.18,1,0,0,0,0,0,0,0,1;"
        "4,112,120,12,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1;"
        "5,172,160,16,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1;"
        "6,95,220,14,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1;"
        "7,245,150,11,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1 "
        "walls=8,50,45,250,45,0.18,0.18,0.18,1,2,1;9,50,255,250,255,0.18,0.18,0.18,1,2,1;"
        "10,50,45,50,255,0.18,0.18,0.18,1,2,1;11,250,45,250,255,0.18,0.18,0.18,1,2,1;"
        "12,125,75,125,185,0.18,0.18,0.18,1,3,1;13,175,115,230,115,0.18,0.18,0.18,1,3,1"),
}


def _numbers(text) -> np.ndarray:
    return np.array([float(v) for v in re.split(r"[,;\s]+", str(text).strip()) if v],
                    dtype=np.float64)


def _agrees(want: str, spec) -> bool:
    """Whether the class's default in an Ikaros 3 file is the interface's."""
    ours = spec.default_v3 if spec.default_v3 is not None else spec.default
    if spec.options:
        index = int(want) if re.fullmatch(r"\d+", want) else spec.options.index(want)
        return spec.options.index(ours) == index if isinstance(ours, str) else ours == index
    if spec.type == "bool":
        return bool(ours) == (want.lower() in ("yes", "true", "1"))
    if spec.type in ("array", "matrix"):
        got = _numbers(ours if not isinstance(ours, np.ndarray) else ours.ravel().tolist())
        return np.array_equal(got, _numbers(want))
    if spec.type == "string":
        return str(ours) == want
    return float(ours) == float(want)


@pytest.mark.parametrize("name", sorted(INTERFACES))
def test_the_class_has_ikaros3s_interface(name):
    inputs, outputs, parameters = INTERFACES[name]
    description = ClassRegistry([]).find(name).description()
    assert set(inputs.split()) <= {i.name for i in description.inputs}
    assert set(outputs.split()) <= {o.name for o in description.outputs}
    specs = {p.name: p for p in description.parameters}
    for item in parameters.split():
        parameter, want = item.split("=", 1)
        assert parameter in specs, parameter
        assert _agrees(want, specs[parameter]), (parameter, want)
