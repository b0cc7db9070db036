"""Benchmark models for ikaros for Python: generators that write .ikg files.

    from benchmarks.models import robot_320, chain, matrix_chain, write_all
    path = robot_320("/tmp/bench")            # -> "/tmp/bench/robot_320.ikg"
    path = chain("/tmp/bench", 1000, delay=1)  # -> "/tmp/bench/chain_1000_d1.ikg"
    path = matrix_chain("/tmp/bench", 0)       # -> "/tmp/bench/matrix_chain_d0.ikg"

Everything is deterministic: the same call writes the same file, byte for byte.
Run ``python benchmarks/models.py FOLDER`` to write every model into FOLDER.
"""
from __future__ import annotations

import collections
import os
import sys
from xml.sax.saxutils import quoteattr


# --- a tiny model writer -------------------------------------------------------------------

class _Group:
    def __init__(self, name: str, attrs: dict | None = None, comment: str | None = None):
        self.name = name
        self.attrs = attrs or {}
        self.comment = comment
        self.children: list = []          # _Group or _Module, in writing order
        self.connections: list = []       # (source, target, delay) relative to this group


class _Module:
    def __init__(self, cls: str, name: str, attrs: dict):
        self.cls, self.name, self.attrs = cls, name, attrs


class ModelWriter:
    """Builds a tree of groups and modules, places every connection in the innermost group
    that holds both ends (with paths relative to that group), counts modules by class and
    connections by delay, and writes the .ikg text."""

    def __init__(self, top: str, attrs: dict | None = None, comment: str | None = None):
        self.top = _Group(top, attrs, comment)
        self.groups: dict[str, _Group] = {"": self.top}
        self.modules: dict[str, _Module] = {}
        self.class_count: collections.Counter = collections.Counter()
        self.delay_count: collections.Counter = collections.Counter()
        self.connected: collections.Counter = collections.Counter()   # "Mod.INPUT" -> n

    def group(self, path: str, comment: str | None = None, **attrs) -> str:
        """Create the group at dotted ``path`` (its parent must exist); returns the path."""
        parent, _, name = path.rpartition(".")
        g = _Group(name, {k: str(v) for k, v in attrs.items()}, comment)
        self.groups[parent].children.append(g)
        self.groups[path] = g
        return path

    def module(self, cls: str, path: str, **attrs) -> str:
        """Create a module at dotted ``path``; returns the path."""
        parent, _, name = path.rpartition(".")
        assert path not in self.modules, path
        m = _Module(cls, name, {k: str(v) for k, v in attrs.items()})
        self.groups[parent].children.append(m)
        self.modules[path] = m
        self.class_count[cls] += 1
        return path

    def connect(self, source: str, target: str, delay: int = 1, select: str = "") -> None:
        """Connect ``source`` (module path, its OUTPUT unless a port is given) to ``target``
        (module path + "." + input name). ``select`` is an optional selector such as
        "[0:3]" appended to the source."""
        if source in self.modules:
            source += ".OUTPUT"
        src_mod, tgt_mod = source.rpartition(".")[0], target.rpartition(".")[0]
        assert src_mod in self.modules, source
        assert tgt_mod in self.modules, target
        a, b = src_mod.split("."), tgt_mod.split(".")
        common = []
        for x, y in zip(a[:-1], b[:-1]):
            if x != y:
                break
            common.append(x)
        where = ".".join(common)
        n = len(common)
        rel_src = ".".join(source.split(".")[n:]) + select
        rel_tgt = ".".join(target.split(".")[n:])
        self.groups[where].connections.append((rel_src, rel_tgt, delay))
        self.delay_count[delay] += 1
        self.connected[target] += 1

    @property
    def n_connections(self) -> int:
        return sum(self.delay_count.values())

    def text(self) -> str:
        out = ['<?xml version="1.0"?>']

        def attrs_text(d):
            return "".join(f" {k}={quoteattr(v)}" for k, v in d.items())

        def write(g: _Group, indent: str):
            if g.comment:
                out.append(f"{indent}<!-- {g.comment} -->")
            out.append(f'{indent}<group name="{g.name}"{attrs_text(g.attrs)}>')
            inner = indent + "    "
            for c in g.children:
                if isinstance(c, _Group):
                    write(c, inner)
                else:
                    out.append(f'{inner}<module class="{c.cls}" name="{c.name}"'
                               f'{attrs_text(c.attrs)} />')
            for s, t, d in g.connections:
                out.append(f'{inner}<connection source="{s}" target="{t}" delay="{d}" />')
            out.append(f"{indent}</group>")

        write(self.top, "")
        return "\n".join(out) + "\n"

    def save(self, folder: str, filename: str) -> str:
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, filename)
        with open(path, "w") as f:
            f.write(self.text())
        return path


def _numbers(values) -> str:
    return " ".join(f"{v:g}" for v in values)


# --- robot_320 -----------------------------------------------------------------------------

LIMBS = [  # (name, joints, elements per joint)
    ("LeftArm", ["ShoulderPitch", "ShoulderRoll", "Elbow", "Wrist"], 3),
    ("RightArm", ["ShoulderPitch", "ShoulderRoll", "Elbow", "Wrist"], 3),
    ("LeftLeg", ["HipPitch", "HipRoll", "Knee", "Ankle"], 4),
    ("RightLeg", ["HipPitch", "HipRoll", "Knee", "Ankle"], 4),
]

# Slots of Body.Gains: scalar gains read through Scale.SCALE, and a vector of motor
# constants (torque per unit command) at Gains[KT:KT+k].
GAIN_SLOT = {"In": 0, "Diff": 1}
KT = 8

ROBOT_CLASSES = {"Add": 188, "Scale": 64, "Multiply": 53, "Constant": 10, "Sum": 5}
ROBOT_DELAYS = {0: 289, 1: 326}

# A note on feedback: this kernel sizes an Add/Multiply output from all its inputs and a
# Scale output from INPUT, so a loop made only of INPUT/INPUT1/INPUT2 edges could never be
# sized. Every feedback loop here therefore closes through an input that does not set a
# size: Scale.SCALE (adaptive gains) fed from a Sum (limb effort, body balance), delay 1.
# Short-term memory inside a joint uses delay taps (FIR filters: x[t] + x[t-1]).


def robot_320_writer() -> ModelWriter:
    """The robot controller model as a ModelWriter (counts checked)."""
    w = ModelWriter("Robot", {"tick_duration": "0.01"},
                    comment="robot_320: a 16-joint, 4-limb robot controller benchmark. "
                            "Per joint: encoder filter -> adaptive PD controller -> motor "
                            "command; limb effort and body balance feed the gains back "
                            "with delay 1. Generated by benchmarks/models.py.")

    # Body: whole-robot sensors, the gain table, and a balance monitor.
    w.group("Body", comment="whole-body sensors, shared gains, balance monitor")
    imu = w.module("Constant", "Body.IMU",
                   data=_numbers(round(0.01 * (i % 8) - 0.03, 3) for i in range(16)))
    gains = w.module("Constant", "Body.Gains",
                     data=_numbers([1, 1, 0, 0, 0, 0, 0, 0, 0.9, 0.8, 0.7, 0.6,
                                    0, 0, 0, 0]))
    w.group("Body.Balance")
    stability = w.module("Multiply", "Body.Balance.Stability")   # left x right leg effort
    tilt = w.module("Sum", "Body.Balance.Tilt")                  # sum of the IMU

    def gain(slot: str, target: str):
        i = GAIN_SLOT[slot]
        w.connect(gains, target + ".SCALE", 1, f"[{i}:{i + 1}]")

    efforts = {}
    for li, (limb, joints, k) in enumerate(LIMBS):
        n = len(joints) * k
        leg = "Leg" in limb
        w.group(limb, comment=f"{limb}: {len(joints)} joints x {k} channels")
        enc = w.module("Constant", f"{limb}.Encoders",
                       data=_numbers(round(0.05 + 0.4 * ((i * 7 + li) % n) / n, 4)
                                     for i in range(n)))
        tgt = w.module("Constant", f"{limb}.Targets",
                       data=_numbers(round(0.1 + 0.3 * ((i * 5 + li) % n) / n, 4)
                                     for i in range(n)))
        dyn = w.group(f"{limb}.Dynamics", comment="limb posture, gravity load, effort")
        posture = w.module("Add", f"{dyn}.Posture")
        gravity = w.module("Add", f"{dyn}.Gravity")
        load = w.module("Multiply", f"{dyn}.Load")
        contact = w.module("Add", f"{dyn}.Contact")
        effort = w.module("Sum", f"{dyn}.Effort")
        efforts[limb] = effort

        prev = None
        for j, joint in enumerate(joints):
            J = w.group(f"{limb}.{joint}")
            sl = f"[{j * k}:{(j + 1) * k}]"
            # Encoder filter: 2-tap FIR low-pass and a velocity estimate.
            F = w.group(f"{J}.Filter")
            fin = w.module("Scale", f"{F}.In", factor=0.5)
            lp = w.module("Add", f"{F}.LP")
            diff = w.module("Scale", f"{F}.Diff", factor=-1)
            vel = w.module("Add", f"{F}.Vel")
            # Controller: PD with an effort-adapted P gain, smoothing and feedforward.
            C = w.group(f"{J}.Controller")
            err = w.module("Add", f"{C}.Err")
            kp = w.module("Scale", f"{C}.Kp", factor=0.8)
            kd = w.module("Scale", f"{C}.Kd", factor=-0.5)
            pd = w.module("Add", f"{C}.PD")
            smooth = w.module("Add", f"{C}.Smooth")
            errsq = w.module("Multiply", f"{C}.ErrSq")
            ff = w.module("Add", f"{C}.Feedforward")
            pid = w.module("Add", f"{C}.Control")
            # Motor: command with coupling along the limb, torque, power and cost.
            M = w.group(f"{J}.Motor")
            cmd = w.module("Add", f"{M}.Cmd")
            torque = w.module("Multiply", f"{M}.Torque")
            out = w.module("Add", f"{M}.Out")
            power = w.module("Multiply", f"{M}.Power")
            energy = w.module("Add", f"{M}.Energy")
            cost = w.module("Add", f"{M}.CostAcc")

            # sensors -> filter (sampling delay 1)
            w.connect(enc, f"{fin}.INPUT", 1, sl)
            gain("In", fin)
            w.connect(fin, f"{lp}.INPUT1", 0)
            w.connect(fin, f"{lp}.INPUT2", 1)                 # FIR tap x[t-1]
            w.connect(lp, f"{diff}.INPUT", 1)
            gain("Diff", diff)
            w.connect(lp, f"{vel}.INPUT1", 0)
            w.connect(diff, f"{vel}.INPUT2", 0)                # lp[t] - lp[t-1]
            # filter -> controller
            w.connect(tgt, f"{err}.INPUT1", 1, sl)
            w.connect(diff, f"{err}.INPUT2", 0)                # target - position
            w.connect(err, f"{kp}.INPUT", 0)
            w.connect(effort, f"{kp}.SCALE", 1)                # adaptive gain: feedback loop
            w.connect(vel, f"{kd}.INPUT", 1)
            w.connect(stability if leg else tilt, f"{kd}.SCALE", 1)   # balance-scheduled damping
            w.connect(kp, f"{pd}.INPUT1", 0)
            w.connect(kd, f"{pd}.INPUT2", 0)
            w.connect(pd, f"{smooth}.INPUT1", 0)
            w.connect(pd, f"{smooth}.INPUT2", 1)               # FIR tap
            w.connect(err, f"{errsq}.INPUT1", 0)
            w.connect(err, f"{errsq}.INPUT2", 1)
            w.connect(tgt, f"{ff}.INPUT1", 1, sl)
            w.connect(gravity, f"{ff}.INPUT2", 1)
            w.connect(smooth, f"{pid}.INPUT1", 0)
            w.connect(ff, f"{pid}.INPUT2", 0)
            # controller -> motor (pipelined: delay 1), coupling along the limb (delay 1)
            w.connect(pid, f"{cmd}.INPUT1", 1)
            w.connect(posture if prev is None else prev["cmd"], f"{cmd}.INPUT2", 1)
            w.connect(cmd, f"{torque}.INPUT1", 0)
            w.connect(gains, f"{torque}.INPUT2", 1, f"[{KT}:{KT + k}]")   # motor constants
            w.connect(torque, f"{out}.INPUT1", 0)
            w.connect(imu, f"{out}.INPUT2", 1, sl if (j + 1) * k <= 16 else f"[0:{k}]")
            w.connect(cmd, f"{power}.INPUT1", 0)
            w.connect(vel, f"{power}.INPUT2", 1)
            w.connect(power, f"{energy}.INPUT1", 0)
            w.connect(errsq, f"{energy}.INPUT2", 0)
            w.connect(energy, f"{cost}.INPUT1", 0)
            w.connect(contact if prev is None else prev["cost"], f"{cost}.INPUT2", 1)
            prev = {"cmd": cmd, "cost": cost}

        # limb level: posture and gravity load; effort = total cost along the limb
        w.connect(tgt, f"{posture}.INPUT1", 1, f"[0:{k}]")
        w.connect(gravity, f"{posture}.INPUT2", 0)
        w.connect(imu, f"{gravity}.INPUT1", 1, f"[{li * 4}:{li * 4 + k}]")
        w.connect(load, f"{gravity}.INPUT2", 0)
        w.connect(enc, f"{load}.INPUT1", 1, f"[{n - k}:{n}]")
        w.connect(imu, f"{load}.INPUT2", 1, f"[{12 - li * 4}:{12 - li * 4 + k}]")
        w.connect(imu, f"{contact}.INPUT1", 1, f"[{16 - k}:16]")
        w.connect(posture, f"{contact}.INPUT2", 0)
        w.connect(prev["cost"], f"{effort}.INPUT", 0)

    w.connect(efforts["LeftLeg"], f"{stability}.INPUT1", 1)
    w.connect(efforts["RightLeg"], f"{stability}.INPUT2", 1)
    w.connect(imu, f"{tilt}.INPUT", 0)

    # --- the counts the benchmark promises ---
    assert len(w.modules) == 320, len(w.modules)
    assert dict(w.class_count) == ROBOT_CLASSES, dict(w.class_count)
    assert w.n_connections == 615, w.n_connections
    assert dict(w.delay_count) == ROBOT_DELAYS, dict(w.delay_count)
    required = {"Add": ("INPUT1", "INPUT2"), "Multiply": ("INPUT1", "INPUT2"),
                "Scale": ("INPUT", "SCALE"), "Sum": ("INPUT",), "Constant": ()}
    for path, m in w.modules.items():
        for port in required[m.cls]:
            assert w.connected[f"{path}.{port}"] == 1, f"{path}.{port} is not connected once"
    assert sum(w.connected.values()) == 615
    _check_no_zero_delay_cycle(w)
    return w


def _check_no_zero_delay_cycle(w: ModelWriter) -> None:
    """Assert that the delay-0 connections form a DAG."""
    edges = collections.defaultdict(set)

    def walk(g: _Group, prefix: str):
        for s, t, d in g.connections:
            if d == 0:
                s_mod = prefix + s.split("[")[0].rpartition(".")[0]
                t_mod = prefix + t.rpartition(".")[0]
                edges[s_mod].add(t_mod)
        for c in g.children:
            if isinstance(c, _Group):
                walk(c, prefix + c.name + ".")

    walk(w.top, "")
    state: dict[str, int] = {}

    def visit(node):
        stack = [(node, iter(edges[node]))]
        state[node] = 1
        while stack:
            n, it = stack[-1]
            for m in it:
                if state.get(m) == 1:
                    raise AssertionError(f"zero-delay cycle through {m}")
                if m not in state:
                    state[m] = 1
                    stack.append((m, iter(edges[m])))
                    break
            else:
                state[n] = 2
                stack.pop()

    for node in list(edges):
        if node not in state:
            visit(node)


def robot_320(folder: str) -> str:
    """Write robot_320.ikg into ``folder``; returns its path."""
    return robot_320_writer().save(folder, "robot_320.ikg")


# --- chains --------------------------------------------------------------------------------

def chain(folder: str, n: int, delay: int = 1) -> str:
    """A 4-element Constant followed by ``n`` Scale modules in a chain, every connection with
    ``delay``. Writes chain_{n}_d{delay}.ikg; returns its path."""
    w = ModelWriter(f"Chain{n}", comment=f"chain of {n} Scale modules, delay {delay}")
    prev = w.module("Constant", "Source", data="1 2 3 4")
    for i in range(n):
        cur = w.module("Scale", f"S{i}", factor=1)
        w.connect(prev, f"{cur}.INPUT", delay)
        prev = cur
    assert w.class_count == {"Constant": 1, "Scale": n}
    assert w.delay_count == {delay: n}
    return w.save(folder, f"chain_{n}_d{delay}.ikg")


def matrix_chain(folder: str, delay: int = 1, n: int = 10, size: int = 1000) -> str:
    """A Constant of ``size`` x ``size`` followed by ``n`` Scale modules in a chain passing the
    matrix on, every connection with ``delay``. Writes matrix_chain_d{delay}.ikg."""
    w = ModelWriter("MatrixChain", comment=f"{n} Scale modules on a {size}x{size} matrix, "
                                           f"delay {delay}")
    prev = w.module("Constant", "Source", data="1", outputsize_x=size, outputsize_y=size)
    for i in range(n):
        cur = w.module("Scale", f"S{i}", factor=1)
        w.connect(prev, f"{cur}.INPUT", delay)
        prev = cur
    assert w.class_count == {"Constant": 1, "Scale": n}
    assert w.delay_count == {delay: n}
    return w.save(folder, f"matrix_chain_d{delay}.ikg")


def image_pipelines(folder: str, threads: int, pipelines: int = 4, stages: int = 6,
                    size: int = 1000) -> str:
    """``pipelines`` independent image pipelines (a ``size`` x ``size`` Constant, then
    ``stages`` Scale and Add modules joined by zero-delay connections), run with
    ``threads`` threads. Writes pipelines_t{threads}.ikg."""
    w = ModelWriter("Pipelines", {"threads": str(threads)},
                    comment=f"{pipelines} image pipelines of {size}x{size}, {threads} threads")
    for p in range(pipelines):
        prev = w.module("Constant", f"Camera{p}", data="0.5", outputsize_x=size,
                        outputsize_y=size)
        for k in range(stages):
            cls = "Scale" if k % 2 == 0 else "Add"
            cur = w.module(cls, f"P{p}Stage{k}", **({"factor": 0.5} if cls == "Scale" else {}))
            if cls == "Scale":
                w.connect(prev, f"{cur}.INPUT", 0)
            else:
                w.connect(prev, f"{cur}.INPUT1", 0)
                w.connect(f"Camera{p}.OUTPUT", f"{cur}.INPUT2", 0)
            prev = cur
    return w.save(folder, f"pipelines_t{threads}.ikg")


def brain(folder: str, stages: int = 20, width: int = 50, size: int = 10) -> str:
    """A brain-style model: ``stages`` groups of ``width`` modules (1000 with the defaults),
    each module an array of ``size`` elements. Stage 0 holds 10 Constant inputs; every other
    module is, by its place j in the stage, an Add, Multiply, Scale, Tanh, Integrator or
    Threshold reading module (7j + 3) mod width of the stage before (delay 0, but delay 1
    into every fifth stage); Add and Multiply also read module j - 1 of their own stage
    (delay 0; the first reads the last of the stage before). Writes brain_1000.ikg (for the defaults); returns its path."""
    w = ModelWriter("Brain", comment=f"{stages} stages of {width} modules, {size} elements")
    kinds = [("Add", {}), ("Multiply", {}), ("Scale", {"factor": 0.5}), ("Tanh", {}),
             ("Integrator", {"alpha": 0.9, "beta": 0.1}), ("Threshold", {"threshold": 0.1})]
    previous: list[str] = []
    for s in range(stages):
        group = w.group(f"Stage{s}")
        current = []
        for j in range(width):
            if s == 0 and j < 10:
                data = " ".join(f"{0.01 * ((j * size + k) % 17):g}" for k in range(size))
                current.append(w.module("Constant", f"{group}.Input{j}", data=data))
                continue
            cls, attrs = kinds[j % len(kinds)]
            m = w.module(cls, f"{group}.{cls}{j}", **attrs)
            source = current[j % 10] if s == 0 else previous[(7 * j + 3) % width]
            delay = 1 if s % 5 == 0 and s > 0 else 0
            if cls in ("Add", "Multiply"):
                w.connect(source, f"{m}.INPUT1", delay)
                if j > 0:
                    w.connect(current[j - 1], f"{m}.INPUT2", 0)
                else:
                    w.connect(previous[-1], f"{m}.INPUT2", delay)
            else:
                w.connect(source, f"{m}.INPUT", delay)
            current.append(m)
        previous = current
    assert sum(w.class_count.values()) == stages * width
    _check_no_zero_delay_cycle(w)
    return w.save(folder, f"brain_{stages * width}.ikg")


CHAIN_SIZES = (10, 100, 1000, 10000)


def write_all(folder: str) -> dict[str, str]:
    """Write every benchmark model into ``folder``: {benchmark name: path}."""
    paths = {"robot_320": robot_320(folder), "brain_1000": brain(folder)}
    for n in CHAIN_SIZES:
        for d in (0, 1):
            paths[f"chain_{n}_d{d}"] = chain(folder, n, d)
    for d in (0, 1):
        paths[f"matrix_chain_d{d}"] = matrix_chain(folder, d)
    for t in (1, 2):
        paths[f"pipelines_t{t}"] = image_pipelines(folder, t)
    return paths


if __name__ == "__main__":
    folder = sys.argv[1] if len(sys.argv) > 1 else "."
    for name, path in write_all(folder).items():
        print(f"{name}: {path}")
