"""The vision classes that Ikaros 3 has today accept its interface: every input, output and
parameter its class file declares, with its defaults in an Ikaros 3 file. The names and
defaults below are those of the original's current class files (reference:
IKAROS3-INTERFACES.md); each class also computes with them (the tests of each class)."""
import importlib

import pytest

INTERFACES = {
    "CameraRectification": (["INPUT", "CAMERA_MATRIX", "DISTORTION"], ["OUTPUT"],
                            {"border_value": 0.0}),
    "CannyEdgeDetector": (["INPUT"], ["OUTPUT"],
                          {"sigma": 1.0, "low_threshold": 0.1, "high_threshold": 0.3}),
    "ColorMatch": (["INPUT", "TARGETINPUT", "FOCUS", "REINFORCEMENT"], ["OUTPUT"],
                   {"alpha": 0.01, "sigma": 25.0, "gain": 1.0, "threshold": 0.0,
                    "target0": 0.0, "target1": 0.0, "target2": 0.0}),
    "ColorTransform": (["INPUT"], ["OUTPUT"], {"transform": "RGB->Lab", "scale": 1.0}),
    "Downsample": (["INPUT"], ["OUTPUT"], {}),
    "SobelEdgeDetector": (["INPUT"], ["OUTPUT"], {"sigma": 1.0}),
    "StaufferGrimson": (["INPUT"], ["OUTPUT", "WEIGHTS", "MEANS", "VARIANCES"],
                        {"T": 0.8, "threshold": 2.5, "max_gaussians": 5,
                         "initial_variance": 100.0, "learning_rate": 0.01}),
    "Upsample": (["INPUT"], ["OUTPUT"], {}),
    "WhiteBalance": (["INPUT"], ["OUTPUT"],
                     {"red_target": 1.0, "green_target": 1.0, "blue_target": 1.0, "x0": 0,
                      "x1": 1, "y0": 0, "y1": 1, "log_x0": 0, "log_x1": 0, "log_y0": 0,
                      "log_y1": 0}),
}


@pytest.mark.parametrize("name", sorted(INTERFACES))
def test_ikaros3_interface(name):
    cls = getattr(importlib.import_module(f"ikaros.modules.vision.{name}"), name)
    description = cls.description
    inputs, outputs, parameters = INTERFACES[name]
    assert set(inputs) <= {i.name for i in description.inputs}
    assert set(outputs) <= {o.name for o in description.outputs}
    declared = {p.name: p for p in description.parameters}
    for parameter, default in parameters.items():
        spec = declared[parameter]
        in_ikaros3 = spec.default if spec.default_v3 is None else spec.default_v3
        assert in_ikaros3 == default, (name, parameter)
