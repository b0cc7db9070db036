"""DeepNetwork: a feed-forward network, described in a JSON file, trained by PyTorch."""
import json
import os

import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.io._files import resolve

from ._torch import (ACTIVATIONS, activation, generator, load_weights, optimizer, pytorch,
                     save_weights, set_rate)

LOSSES = ("mse", "bce")


def read_spec(path: str) -> dict:
    """The network description in ``path``: ``{"layers": [...], "loss": ..., "optimizer":
    ...}``; ``ValueError`` naming the file and what is wrong."""
    try:
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
    except OSError as e:
        raise ValueError(f"cannot read the network description {path}: {e.strerror}") \
            from None
    except json.JSONDecodeError as e:
        raise ValueError(f"{path}:{e.lineno}: not JSON: {e.msg}") from None
    layers = spec.get("layers") if isinstance(spec, dict) else None
    if not layers or not isinstance(layers, list):
        raise ValueError(f"{path}: needs \"layers\", a list of layers such as "
                         f"{{\"units\": 8, \"activation\": \"tanh\"}}")
    for i, layer in enumerate(layers):
        units = layer.get("units") if isinstance(layer, dict) else None
        if not isinstance(units, int) or units < 1:
            raise ValueError(f"{path}: layer {i} needs \"units\", a positive whole number")
        if layer.get("activation", "linear") not in ACTIVATIONS:
            raise ValueError(f"{path}: layer {i}: unknown activation "
                             f"{layer.get('activation')!r}: use one of {', '.join(ACTIVATIONS)}")
    if spec.get("loss", "mse") not in LOSSES:
        raise ValueError(f"{path}: unknown loss {spec.get('loss')!r}: use mse or bce")
    if spec.get("optimizer", "adam") not in ("adam", "sgd"):
        raise ValueError(f"{path}: unknown optimizer {spec.get('optimizer')!r}: use adam or "
                         f"sgd")
    return spec


class DeepNetwork(Module):
    """A feed-forward network of fully connected layers, trained on line with PyTorch (the
    ``deep`` extra, ``pip install 'ikaros[deep]'``; CPU). Its layers are described in a JSON
    file, ``spec_filename`` (relative to the model file), for example::

        {"layers": [{"units": 8, "activation": "tanh"},
                    {"units": 1, "activation": "sigmoid"}],
         "loss": "mse", "optimizer": "adam"}

    Each layer has ``units`` and an ``activation`` (linear, relu, tanh, sigmoid or softmax;
    linear when left out); the input layer has the size of INPUT and the last layer must
    have the size of T_TARGET. ``loss`` is mse (mean squared error, the default) or bce
    (binary cross-entropy, for outputs in 0..1); ``optimizer`` adam (the default) or sgd.
    Each tick OUTPUT is the network's response to INPUT; then LOSS is the loss of its
    response to T_INPUT against T_TARGET, and the network takes one gradient step on that
    pair with step size ``learning_rate`` times EFFORT (no step while EFFORT is 0 or less).
    With ``load_weights`` the weights are read from ``weights_filename`` when that file
    exists (otherwise the run starts from random weights: PyTorch's initialisation, drawn
    from ``seed`` when it is set); with ``save_weights`` they are written there when the
    run ends. The original's class is known only by its interface: the file format and the
    training rule are this project's reading of it."""

    spec_filename = Parameter("network_spec.json", "the JSON file that describes the "
                              "layers", file=True, fixed=True)
    weights_filename = Parameter("network_weights.dat", "the file the weights are read "
                                 "from and written to (PyTorch's format)", file=True,
                                 fixed=True)
    load_weights = Parameter(True, "read the weights when the file exists", fixed=True)
    save_weights = Parameter(False, "write the weights when the run ends")
    learning_rate = Parameter(0.001, "the step size (times EFFORT)", range=(0, None))
    seed = Parameter(None, "seed of the initial weights; unset (or 0): a different run "
                     "every time", type="int", fixed=True)

    INPUT = Input("the input the network responds to", flatten=True)
    EFFORT = Input("how much to learn this tick: the step size is learning_rate times this")
    T_INPUT = Input("the training input", flatten=True)
    T_TARGET = Input("the training target", flatten=True)
    OUTPUT = Output("the response to INPUT", shape="T_TARGET.size")
    LOSS = Output("the loss on the training pair before this tick's step", shape="1")

    def configure(self):
        self.torch = pytorch()

    def init(self):
        torch = self.torch
        spec_path = resolve(self, self.spec_filename)
        spec = read_spec(spec_path)
        sizes = [self.INPUT.size] + [layer["units"] for layer in spec["layers"]]
        if sizes[-1] != self.T_TARGET.size:
            raise ValueError(f"{spec_path}: the last layer has {sizes[-1]} units and "
                             f"T_TARGET {self.T_TARGET.size} values: they must be the same")
        if self.T_INPUT.size != self.INPUT.size:
            raise ValueError(f"T_INPUT has {self.T_INPUT.size} values and INPUT "
                             f"{self.INPUT.size}: they must be the same")
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(int(generator(torch, self.seed).initial_seed()))
            layers = []
            for (n_in, n_out), layer in zip(zip(sizes, sizes[1:]), spec["layers"]):
                layers += [torch.nn.Linear(n_in, n_out),
                           activation(torch, layer.get("activation", "linear"))]
            self.network = torch.nn.Sequential(*layers)
        self.loss = (torch.nn.MSELoss() if spec.get("loss", "mse") == "mse"
                     else torch.nn.BCELoss())
        self.optimizer = optimizer(torch, spec.get("optimizer", "adam"),
                                   self.network.parameters(), self.learning_rate)
        self._weights = resolve(self, self.weights_filename)
        if self.load_weights and os.path.exists(self._weights):
            load_weights(torch, self.network, self._weights)

    def _tensor(self, array):
        return self.torch.from_numpy(np.asarray(array, np.float32).reshape(1, -1))

    def tick(self):
        torch = self.torch
        with torch.no_grad():
            self.OUTPUT[...] = self.network(self._tensor(self.INPUT)).numpy().reshape(
                self.OUTPUT.shape)
        loss = self.loss(self.network(self._tensor(self.T_INPUT)),
                         self._tensor(self.T_TARGET))
        self.LOSS[0] = float(loss.detach())
        effort = float(np.asarray(self.EFFORT).ravel()[0]) if self.EFFORT.size else 0.0
        if effort > 0:
            set_rate(self.optimizer, self.learning_rate * effort)
            self.optimizer.zero_grad()
            loss.backward()
            self.optimizer.step()

    def stop(self):
        if self.save_weights and hasattr(self, "network"):
            save_weights(self.torch, self.network, resolve(self, self.weights_filename,
                                                           write=True))
