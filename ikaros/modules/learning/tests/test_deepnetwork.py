"""DeepNetwork (PyTorch) learns XOR and a linear map to a small loss, responds to INPUT with
the layers its JSON file describes (checked against the same weights applied in NumPy),
saves and loads its weights, and refuses a wrong description with a message naming it."""
import json

import numpy as np
import pytest

from ikaros.errors import ModelError
from ikaros.testing import load_body

torch = pytest.importorskip("torch")

XOR = {"layers": [{"units": 8, "activation": "tanh"}, {"units": 1, "activation": "sigmoid"}],
       "loss": "mse", "optimizer": "adam"}


def model(tmp_path, spec, patterns, targets, effort="1", inputs=None,
          spec_filename="spec.json", **params):
    (tmp_path / "spec.json").write_text(json.dumps(spec) if isinstance(spec, dict) else spec)
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    rows = lambda a: "; ".join(" ".join(str(v) for v in row) for row in np.atleast_2d(a))
    body = f'''
<module class="ListIterator" name="Patterns" listdata="{rows(patterns)}" repeat="yes"/>
<module class="ListIterator" name="Targets" listdata="{rows(targets)}" repeat="yes"/>
<module class="ListIterator" name="Inputs" listdata="{rows(patterns if inputs is None else inputs)}" repeat="yes"/>
<module class="Constant" name="Effort" data="{effort}"/>
<module class="DeepNetwork" name="M" spec_filename="{spec_filename}" seed="1" {attrs}/>
<connection source="Inputs.OUTPUT" target="M.INPUT" delay="0"/>
<connection source="Patterns.OUTPUT" target="M.T_INPUT" delay="0"/>
<connection source="Targets.OUTPUT" target="M.T_TARGET" delay="0"/>
<connection source="Effort.OUTPUT" target="M.EFFORT" delay="0"/>
'''
    return load_body(tmp_path, body)


def test_learns_xor(tmp_path):
    patterns, targets = [[0, 0], [0, 1], [1, 0], [1, 1]], [[0], [1], [1], [0]]
    with model(tmp_path, XOR, patterns, targets, learning_rate="0.1") as net:
        losses = []
        for _ in range(600):
            net.step()
            losses.append(float(net.output("M.LOSS")[0]))
        outputs = []
        for _ in range(4):                       # the four patterns in turn
            net.step()
            outputs.append(float(net.output("M.OUTPUT")[0]))
    assert np.mean(losses[:4]) > 0.1
    assert np.mean(losses[-4:]) < 0.01
    assert np.allclose(outputs, [0, 1, 1, 0], atol=0.15)


def test_learns_a_linear_map(tmp_path):
    a = np.array([[0.5, -1.0, 0.25], [2.0, 0.0, -0.5]])
    rng = np.random.default_rng(1)
    x = rng.uniform(-1, 1, (16, 3)).round(3)
    spec = {"layers": [{"units": 2}], "optimizer": "sgd"}
    with model(tmp_path, spec, x, x @ a.T, learning_rate="0.2") as net:
        net.run(ticks=1500)
        losses = []
        for _ in range(16):
            net.step()
            losses.append(float(net.output("M.LOSS")[0]))
    assert max(losses) < 1e-4


def test_output_is_the_described_layers_applied_to_input(tmp_path):
    spec = {"layers": [{"units": 5, "activation": "relu"}, {"units": 3, "activation": "tanh"},
                       {"units": 2, "activation": "softmax"}]}
    x = [[0.3, -0.7, 1.1, 0.2]] * 2                   # (a list of one row would be a column)
    with model(tmp_path, spec, x, [[1, 0]] * 2, effort="0", save_weights="yes",
               weights_filename="w.dat") as net:
        net.step()
        out, loss = net.output("M.OUTPUT").copy(), float(net.output("M.LOSS")[0])
    weights = torch.load(tmp_path / "w.dat", weights_only=True)
    w = {k: v.numpy().astype(np.float64) for k, v in weights.items()}
    h = np.maximum(0, w["0.weight"] @ x[0] + w["0.bias"])
    h = np.tanh(w["2.weight"] @ h + w["2.bias"])
    z = w["4.weight"] @ h + w["4.bias"]
    expected = np.exp(z) / np.exp(z).sum()
    assert np.allclose(out, expected, atol=1e-6)
    assert loss == pytest.approx(np.mean((expected - [1, 0]) ** 2), abs=1e-6)


def test_saved_weights_are_loaded_by_the_next_run(tmp_path):
    patterns, targets = [[0, 0], [0, 1], [1, 0], [1, 1]], [[0], [1], [1], [0]]
    with model(tmp_path, XOR, patterns, targets, learning_rate="0.05",
               save_weights="yes") as net:
        net.run(ticks=400)
        net.set_parameter("Effort.data", 0)
        trained = []
        for _ in range(4):
            net.step()
            trained.append(float(net.output("M.OUTPUT")[0]))
    assert (tmp_path / "network_weights.dat").exists()
    with model(tmp_path, XOR, patterns, targets, effort="0", seed="2") as net:
        loaded = []
        for _ in range(4):
            net.step()
            loaded.append(float(net.output("M.OUTPUT")[0]))
    assert np.allclose(loaded, trained, atol=1e-6)


def test_no_step_while_effort_is_zero(tmp_path):
    with model(tmp_path, XOR, [[0, 1]], [[1]], effort="0") as net:
        net.run(ticks=3)
        first = net.output("M.LOSS").copy()
        net.run(ticks=20)
        assert np.array_equal(net.output("M.LOSS"), first)


@pytest.mark.parametrize("spec, message", [
    ("{", "spec.json:1: not JSON"),
    ({"layers": []}, 'needs "layers"'),
    ({"layers": [{"units": 0}]}, 'layer 0 needs "units"'),
    ({"layers": [{"units": 1, "activation": "swish"}]}, "unknown activation 'swish'"),
    ({"layers": [{"units": 1}], "loss": "hinge"}, "unknown loss 'hinge'"),
    ({"layers": [{"units": 3}]}, "the last layer has 3 units and T_TARGET 1"),
])
def test_a_wrong_description_is_refused_naming_the_file(tmp_path, spec, message):
    with pytest.raises(ModelError, match=message.replace("(", r"\(")):
        model(tmp_path, spec, [[0, 1]], [[1]])


def test_a_missing_description_names_the_file(tmp_path):
    with pytest.raises(ModelError, match="cannot read the network description .*other.json"):
        model(tmp_path, XOR, [[0, 1]], [[1]], spec_filename="other.json")
