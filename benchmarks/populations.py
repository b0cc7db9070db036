"""SpikingPopulation at scale, side by side with Brian2 on the same network (issue 30).

    python benchmarks/populations.py                       # ikaros only
    python benchmarks/populations.py --brian2-python /tmp/brian2-venv/bin/python
    python benchmarks/populations.py --cases 1000:dense,10000:0.01 --brian2-targets \\
        numpy,cython,cpp_standalone --brian2-python /tmp/brian2-venv/bin/python
    python benchmarks/populations.py --ikaros-kernels auto,numpy   # with and without numba

The network: N regular-spiking Izhikevich neurons, each with a constant DIRECT_IN current
drawn uniformly in 3..9, and the population's OUTPUT fed back (delay 1) into its own
EXCITATION_IN and INHIBITION_IN, each pair of neurons connected with the case's probability
(1 for dense), excitatory weights uniform in 0..12/(N p) and inhibitory ones in 0..16/(N p),
spikes counted as flags (``spike_input="flag"``). The weights are drawn once with a seed and
written to files (a dense .npy matrix, or compressed sparse columns in a .npz) that both
simulators read, so both run the same network. Each case runs 1 s of model time (1,000
ticks of 1 ms) in a process of its own, for ikaros and for every Brian2 target given; it
prints the build time, the run time, the CPU time of the run (less sensitive than the wall
time to other processes on a shared machine), the spike count, the peak memory (the
process's VmHWM) and how many spikes (tick, neuron) a run has in common with the first
ikaros run, with the first tick where they differ. Brian2 runs with the Python of its own
environment (``--brian2-python``; Brian2 2.9 does not import with NumPy 2.4): it is never a
dependency of ikaros. Brian2's compilation is not timed (its runtime targets run one
warm-up step first and are then restored; the C++ standalone target's compile is left out).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

import ikaros  # noqa: E402
from ikaros.modules.brain.SpikingPopulation import NEURON_TYPES  # noqa: E402
from ikaros.modules.neural import _connectivity as connectivity  # noqa: E402

from _peak_memory import peak_mb  # noqa: E402  (beside this file)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_CASES = "1000:dense,1000:0.01,10000:dense,10000:0.01,100000:0.01"
SEED = 1
DIRECT_RANGE = (3.0, 9.0)
EXCITATION_GAIN, INHIBITION_GAIN = 12.0, 16.0


def make_case(folder: str, n: int, p: float) -> None:
    """Write the network of one case: network.json, direct.npy and the weights."""
    rng = np.random.default_rng(SEED)
    np.save(os.path.join(folder, "direct.npy"),
            rng.uniform(*DIRECT_RANGE, n).astype(np.float32))
    for name, gain in (("excitation", EXCITATION_GAIN), ("inhibition", INHIBITION_GAIN)):
        projection = connectivity.random(rng, (n, n), 0.0, gain / (n * p), p)
        if projection.is_dense:
            np.save(os.path.join(folder, f"{name}.npy"), projection.dense)
        else:
            np.savez(os.path.join(folder, f"{name}.npz"), format="csc", shape=(n, n),
                     indptr=projection.indptr, indices=projection.indices,
                     data=projection.data)
        del projection
    with open(os.path.join(folder, "network.json"), "w") as f:
        json.dump({"n": n, "p": p, "threshold": 30.0, "substeps": 2,
                   "abcd": NEURON_TYPES["regular_spiking"]}, f)


def model_text(folder: str, n: int, kernel: str = "auto") -> str:
    direct = " ".join(repr(float(x)) for x in np.load(os.path.join(folder, "direct.npy")))
    ext = "npy" if os.path.exists(os.path.join(folder, "excitation.npy")) else "npz"
    return (f'<group name="Populations" stop="-1">\n'
            f'<module class="Constant" name="Direct" data="{direct}"/>\n'
            f'<module class="SpikingPopulation" name="P" population_size="{n}" '
            f'spike_input="flag" spike_kernel="{kernel}" '
            f'excitation_weights_file="excitation.{ext}" '
            f'inhibition_weights_file="inhibition.{ext}"/>\n'
            '<connection source="Direct.OUTPUT" target="P.DIRECT_IN" delay="0"/>\n'
            '<connection source="P.OUTPUT" target="P.EXCITATION_IN" delay="1"/>\n'
            '<connection source="P.OUTPUT" target="P.INHIBITION_IN" delay="1"/>\n'
            '</group>\n')


def run_ikaros(folder: str, ticks: int, kernel: str) -> None:
    """The child process of the ikaros side: prints one JSON line."""
    with open(os.path.join(folder, "network.json")) as f:
        n = json.load(f)["n"]
    path = os.path.join(folder, "model.ikg")
    with open(path, "w") as f:
        f.write(model_text(folder, n, kernel))
    start = time.perf_counter()
    net = ikaros.load(path)
    build = time.perf_counter() - start
    out = net.buffer_array("P.OUTPUT")
    ticks_of, neurons = [], []
    start, cpu = time.perf_counter(), time.process_time()
    for t in range(ticks):
        net.step()
        spiking = np.flatnonzero(out >= 30.0)
        if spiking.size:
            neurons.append(spiking)
            ticks_of.append(np.full(spiking.size, t))
    run, cpu = time.perf_counter() - start, time.process_time() - cpu
    net.close()
    spikes = (np.stack([np.concatenate(ticks_of), np.concatenate(neurons)], axis=1)
              if neurons else np.zeros((0, 2), np.int64))
    np.save(os.path.join(folder, f"ikaros-{kernel}.npy"), spikes)
    print(json.dumps({"build_s": build, "run_s": run, "cpu_s": cpu, "spikes": int(len(spikes)),
                      "peak_mb": peak_mb()}))


def child(command: list[str], timeout: float) -> dict:
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                              env={**os.environ, "PYTHONPATH": ROOT})
    except subprocess.TimeoutExpired:
        return {"error": f"over {timeout:.0f} s"}
    if done.returncode != 0:
        return {"error": (done.stderr.strip().splitlines() or ["failed"])[-1][:200]}
    return json.loads(done.stdout.strip().splitlines()[-1])


def agreement(folder: str, mine: str, other: str) -> str:
    """How many spikes the two runs share, and the first tick where they differ."""
    a = {tuple(r) for r in np.load(os.path.join(folder, mine)).tolist()}
    b = {tuple(r) for r in np.load(os.path.join(folder, other)).tolist()}
    differ = a ^ b
    first = f", first difference at tick {min(t for t, _ in differ)}" if differ else ""
    return f"{len(a & b)} of {len(a)} / {len(b)} spikes in common{first}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default=DEFAULT_CASES,
                        help="N:density pairs, density 'dense' or a probability")
    parser.add_argument("--ticks", type=int, default=1000)
    parser.add_argument("--brian2-python", help="the Python of an environment with Brian2")
    parser.add_argument("--brian2-targets", default="cython",
                        help="comma-separated: numpy, cython, cpp_standalone")
    parser.add_argument("--timeout", type=float, default=900.0,
                        help="seconds allowed to each run")
    parser.add_argument("--ikaros-kernels", default="auto",
                        help="comma-separated spike_kernel values: auto (numba when "
                        "installed), numpy")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        run_ikaros(args.child, args.ticks, args.ikaros_kernels)
        return
    print(f"# load average at start: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print("| network | simulator | build s | run s (1 s of model time) | run CPU s | spikes | "
          "peak MB | same spikes |")
    print("|---|---|---|---|---|---|---|---|")
    for case in args.cases.split(","):
        size, density = case.split(":")
        n, p = int(size), (1.0 if density == "dense" else float(density))
        label = f"{n:,} neurons, {'dense' if p == 1 else f'{p:.0%}'}"
        with tempfile.TemporaryDirectory() as folder:
            print(f"{label}: writing the network", file=sys.stderr)
            make_case(folder, n, p)
            rows = []
            kernels = args.ikaros_kernels.split(",")
            mine = f"ikaros-{kernels[0]}.npy"
            for kernel in kernels:
                print(f"{label}: ikaros, spike_kernel {kernel}", file=sys.stderr)
                result = child([sys.executable, __file__, "--child", folder, "--ticks",
                                str(args.ticks), "--ikaros-kernels", kernel], args.timeout)
                same = ("" if kernel == kernels[0] or "error" in result or "error" in rows[0][1]
                        else agreement(folder, mine, f"ikaros-{kernel}.npy"))
                rows.append((f"ikaros ({kernel})", result, same))
            for target in (args.brian2_targets.split(",") if args.brian2_python else []):
                print(f"{label}: Brian2 {target}", file=sys.stderr)
                result = child([args.brian2_python, os.path.join(HERE, "_populations_brian2.py"),
                                folder, target, str(args.ticks)], args.timeout)
                same = ("" if "error" in result or "error" in rows[0][1]
                        else agreement(folder, mine, f"brian2-{target}.npy"))
                rows.append((f"Brian2 {result.get('version', '')} {target}", result, same))
            for name, r, same in rows:
                if "error" in r:
                    print(f"| {label} | {name} | – | {r['error']} | – | – | – | |")
                else:
                    print(f"| {label} | {name} | {r['build_s']:.2f} | {r['run_s']:.2f} | "
                          f"{r['cpu_s']:.2f} | {r['spikes']} | {r['peak_mb']:.0f} | {same} |")
            sys.stdout.flush()
    print(f"# load average at end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
