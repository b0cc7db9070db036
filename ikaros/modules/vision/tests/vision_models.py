"""Helpers for the vision module tests: a model with one module under test, fed by Constant
modules that hold test images, loaded from a temporary folder and run through the kernel."""
import numpy as np

from ikaros.testing import load_body


def literal(a) -> str:
    """An array of any rank as a model-file literal (nested brackets)."""
    return str(np.asarray(a, np.float32).astype(float).tolist()).replace(" ", "")


def run(tmp_path, cls: str, inputs: dict, ticks: int = 1, name: str = "M", **params):
    """Load a model with the module ``name`` of class ``cls``, each input fed with delay 0
    from a Constant that holds the given array, run ``ticks`` ticks and return the network
    (the caller closes it), an Ikaros 2 file. Parameters are written as given (``str``)."""
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = [f'<module class="{cls}" name="{name}" {attrs}/>']
    for port, value in inputs.items():
        source = "In_" + port.replace("-", "_")
        body.append(f'<module class="Constant" name="{source}" data="{literal(value)}"/>')
        body.append(f'<connection source="{source}.OUTPUT" target="{name}.{port}" '
                    f'delay="0"/>')
    # Ikaros 2 files, as before the signs of Ikaros 3 (a class's Ikaros 3 ports) counted
    net = load_body(tmp_path, "\n".join(body), dialect=2)
    if ticks:
        net.run(ticks=ticks)
    return net


def outputs(tmp_path, cls: str, inputs: dict, *names: str, **params) -> list:
    """Run one tick and return copies of the named outputs of the module under test."""
    with run(tmp_path, cls, inputs, **params) as net:
        return [net.output(f"M.{n}") for n in names]
