"""Brian2's side of benchmarks/populations.py: the same Izhikevich network as
SpikingPopulation computes it, run with one Brian2 target. It needs only NumPy and Brian2
and runs in Brian2's own environment (never a dependency of ikaros)::

    /tmp/brian2-venv/bin/python benchmarks/_populations_brian2.py CASE_DIR TARGET TICKS

CASE_DIR holds network.json, direct.npy and the weights (receivers x senders), excitation
and inhibition, each a dense .npy or compressed sparse columns in a .npz. It prints one JSON
line: build and run seconds, the CPU time of the run, the spike count, the peak memory; the
spikes go to CASE_DIR/brian2-TARGET.npy as (tick, neuron) rows.

The model, as SpikingPopulation with spike_input="flag" and a recurrent connection of delay
1: per 1 ms step, v is integrated in ``substeps`` Euler steps and held at the threshold,
then u += a (b v - u); a neuron at the threshold spikes and is reset (v = c, u += d) at the
end of the step, which SpikingPopulation does at the start of the next tick (the same
values); its spike adds its weights to the receivers' synaptic current of the next step.
"""
import json
import os
import resource
import sys
import time

import brian2 as b2
import numpy as np

from _peak_memory import peak_mb  # beside this file


def load_synapses(case_dir, name):
    """(senders, receivers, weights), sender by sender, from name.npy (a dense receivers x
    senders matrix) or name.npz (compressed sparse columns)."""
    path = os.path.join(case_dir, name)
    if os.path.exists(path + ".npy"):
        w = np.load(path + ".npy")
        n_post, n_pre = w.shape
        return (np.repeat(np.arange(n_pre, dtype=np.int32), n_post),
                np.tile(np.arange(n_post, dtype=np.int32), n_pre), w.T.ravel())
    z = np.load(path + ".npz")
    indptr, indices = z["indptr"], z["indices"]
    senders = np.repeat(np.arange(len(indptr) - 1, dtype=np.int32), np.diff(indptr))
    return senders, indices.astype(np.int32), z["data"]


def _children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main(case_dir, target, ticks):
    b2.prefs.codegen.loop_invariant_optimisations = False
    b2.prefs.codegen.cpp.extra_compile_args_gcc = ["-w", "-O3"]   # no -ffast-math
    if target == "cpp_standalone":
        b2.set_device("cpp_standalone", build_on_run=False)
    else:
        b2.prefs.codegen.target = target
    with open(os.path.join(case_dir, "network.json")) as f:
        net = json.load(f)
    n, th, steps = net["n"], net["threshold"], net["substeps"]
    a, b, c, d = net["abcd"]
    h = 1.0 / steps
    start = time.perf_counter()
    b2.defaultclock.dt = 1 * b2.ms
    group = b2.NeuronGroup(n, """v : 1
                                 u : 1
                                 Idir : 1 (constant)
                                 Ie : 1
                                 Ii : 1""",
                           threshold=f"v >= {th!r}", reset=f"v = {c!r}\nu = u + {d!r}")
    group.v = -65.0
    group.u = b * -65.0
    group.Idir = np.load(os.path.join(case_dir, "direct.npy")).astype(np.float64)
    euler = "\n".join([f"v = v + {h!r} * (0.04 * v * v + 5.0 * v + 140.0 - u + I)\n"
                       f"v = clip(v, -1e9, {th!r})"] * steps)
    group.run_regularly(f"I = Idir + Ie - Ii\n{euler}\nu = u + {a!r} * ({b!r} * v - u)\n"
                        "Ie = 0\nIi = 0", when="groups")
    synapses = []
    for name, var in (("excitation", "Ie"), ("inhibition", "Ii")):
        pre, post, w = load_synapses(case_dir, name)
        s = b2.Synapses(group, group, "w : 1", on_pre=f"{var}_post += w")
        s.connect(i=pre, j=post)
        s.w = w.astype(np.float64)
        synapses.append(s)
        del pre, post, w
    monitor = b2.SpikeMonitor(group)
    network = b2.Network(group, *synapses, monitor)
    build = time.perf_counter() - start
    if target != "cpp_standalone":           # code generation and compilation, not timed
        network.store()
        network.run(1 * b2.ms)
        network.restore()
    if target == "cpp_standalone":
        network.run(ticks * b2.ms)            # only generates the code
        b2.device.build(directory=os.path.join(case_dir, "standalone"), run=False,
                        compile=True)
        start, cpu = time.perf_counter(), _children_cpu()
        b2.device.run()
        run, cpu = time.perf_counter() - start, _children_cpu() - cpu
    else:
        start, cpu = time.perf_counter(), time.process_time()
        network.run(ticks * b2.ms)
        run, cpu = time.perf_counter() - start, time.process_time() - cpu
    ticks_of_spikes = np.round(np.asarray(monitor.t / b2.ms)).astype(np.int64)
    spikes = np.stack([ticks_of_spikes, np.asarray(monitor.i, dtype=np.int64)], axis=1)
    np.save(os.path.join(case_dir, f"brian2-{target}.npy"), spikes)
    print(json.dumps({"build_s": build, "run_s": run, "cpu_s": cpu, "spikes": int(len(spikes)),
                      "peak_mb": peak_mb(),
                      "version": b2.__version__}))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]))
