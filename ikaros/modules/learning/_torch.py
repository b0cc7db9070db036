"""PyTorch for the deep-learning classes: the import (the ``deep`` extra), activations by
name, optimizers from the classes' parameters, and weight files."""
from __future__ import annotations

import os

from ikaros.module import require

ACTIVATIONS = ("linear", "relu", "tanh", "sigmoid", "softmax")


def pytorch():
    """The ``torch`` module, or a ``MissingDependency`` that says
    ``pip install 'ikaros[deep]'`` (the CPU build of PyTorch 2.13). Call it in ``configure``.

    PyTorch is set to compute in one thread (for the whole process): networks trained on
    one sample a tick are fastest so, and on a busy machine its thread pool waiting for
    cores made a step of a small convolutional network 60 times slower (2 against 135 ms)."""
    torch = require("torch", "torch==2.13.0", extra="deep")
    torch.set_num_threads(1)
    return torch


def activation(torch, name: str):
    """The layer for an activation named in ACTIVATIONS."""
    layers = {"linear": torch.nn.Identity, "relu": torch.nn.ReLU, "tanh": torch.nn.Tanh,
              "sigmoid": torch.nn.Sigmoid, "softmax": lambda: torch.nn.Softmax(dim=-1)}
    if name not in layers:
        raise ValueError(f"unknown activation {name!r}: use one of {', '.join(ACTIVATIONS)}")
    return layers[name]()


def optimizer(torch, kind: str, parameters, learning_rate: float, betas=(0.9, 0.999),
              epsilon: float = 1e-8):
    """An Adam or plain SGD optimizer over ``parameters``."""
    if kind == "adam":
        return torch.optim.Adam(parameters, lr=learning_rate, betas=betas, eps=epsilon)
    if kind == "sgd":
        return torch.optim.SGD(parameters, lr=learning_rate)
    raise ValueError(f"unknown optimizer {kind!r}: use adam or sgd")


def set_rate(optimizer_, rate: float) -> None:
    """Set the step size of every parameter group of an optimizer."""
    for group in optimizer_.param_groups:
        group["lr"] = rate


def generator(torch, seed):
    """A random generator of its own for a module: seeded when ``seed`` is set (not 0),
    otherwise from the operating system (a different run every time)."""
    g = torch.Generator()
    if seed:
        g.manual_seed(int(seed))
    else:
        g.seed()
    return g


def save_weights(torch, network, path: str) -> None:
    """Write a network's weights (its state dict) to ``path``, making its folder."""
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    torch.save(network.state_dict(), path)


def load_weights(torch, network, path: str) -> None:
    """Read weights written by ``save_weights`` into a network of the same layout;
    ``ValueError`` naming the file when the layout differs or the file is not one."""
    try:
        network.load_state_dict(torch.load(path, weights_only=True))
    except (RuntimeError, OSError, EOFError, KeyError) as e:
        raise ValueError(f"{path}: not weights of this network ({str(e).splitlines()[0]})") \
            from None
