"""Web UI benchmark: does a client that polls as fast as it can slow the kernel down?

    python benchmarks/webui.py                 # about 60 s
    python benchmarks/webui.py --seconds 3 --rounds 2
    python benchmarks/webui.py --real-time     # lag at 1 kHz instead of ticks per second
    python benchmarks/webui.py --format history   # the client keeps every tick (plots)

Runs robot_320 (benchmarks/models.py) in play mode (as fast as possible) in the
controller's background thread, with the web UI server (uvicorn, on 127.0.0.1, a free port)
in this process, and measures ticks per second:

* kernel only: no server at all;
* no client: the server is up, nobody is connected;
* client: a real WebSocket client in another process subscribes to 20 buffers and polls
  as fast as it can (sends "ready" again as soon as a data frame arrives).

The "no client" and "client" phases alternate for ``--rounds`` rounds of ``--seconds``
each (the client process connects at the start of each client phase and disconnects at its
end); the medians are printed with the drop in percent (the goal: at most 5 %), and the
frames per second the client received. On a busy machine the rounds vary a lot: compare
the median of the rounds' drops, and run it on a quiet machine.

With ``--real-time`` the model runs in real time at 1 kHz instead, and each phase reports
the kernel's own lag figures (mean, 99th percentile, max) instead of ticks per second.
"""
from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import statistics
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)


def client_process(url: str, paths: list[str], go, stop, quit_, frames, connected,
                   fmt: str = "raw") -> None:
    """Each time ``go`` is set: connect, subscribe to ``paths`` (in format ``fmt``: raw,
    png or jpeg) and poll as fast as possible (a new "ready" as soon as a data frame
    arrives) until ``stop`` is set, then disconnect. Ends when ``quit_`` is set."""
    from websockets.sync.client import connect
    while not quit_.is_set():
        if not go.wait(0.2):
            continue
        go.clear()
        with connect(url, max_size=None, compression=None) as ws:
            ws.send(json.dumps({"type": "subscribe",
                                "buffers": [{"path": p, "format": fmt} for p in paths]}))
            ws.send(json.dumps({"type": "ready"}))
            connected.set()
            while not stop.is_set():
                try:
                    msg = ws.recv(timeout=0.2)
                except TimeoutError:
                    continue
                if isinstance(msg, bytes):
                    with frames.get_lock():
                        frames.value += 1
                    ws.send(json.dumps({"type": "ready"}))
        stop.clear()
        connected.clear()


def serve_in_thread(net, **options):
    """Serve ``net``'s web UI on 127.0.0.1 (a free port) from a thread, below the tick as
    ``ikaros`` serves it; returns (server, thread, port). Stop it with
    ``server.should_exit = True; thread.join()``."""
    import uvicorn

    from ikaros import priority
    from ikaros.webui.server import create_app, listen
    sock = listen("127.0.0.1", 0)
    app = create_app(net, **options)
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", access_log=False,
                                           lifespan="off", ws_per_message_deflate=False))

    def serve():
        priority.below_tick_thread()
        try:
            server.run(sockets=[sock])
        finally:
            app.state.ui.hub.close()
    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    while not server.started:
        time.sleep(0.05)
    return server, thread, sock.getsockname()[1]


def start_client(port: int, paths: list[str], fmt: str = "raw"):
    """Start ``client_process`` in a spawned process on the server at ``port``; returns
    (process, go, stop, quit_, frames, connected)."""
    spawn = mp.get_context("spawn")
    go, stop, quit_, connected = (spawn.Event() for _ in range(4))
    frames = spawn.Value("l", 0)
    proc = spawn.Process(target=client_process, daemon=True,
                         args=(f"ws://127.0.0.1:{port}/api/ws", paths, go, stop, quit_,
                               frames, connected, fmt))
    proc.start()
    return proc, go, stop, quit_, frames, connected


def rate(net, seconds: float) -> float:
    t0, n0 = time.perf_counter(), net.tick
    time.sleep(seconds)
    return (net.tick - n0) / (time.perf_counter() - t0)


def lag_figures(net, seconds: float) -> tuple[float, float, float]:
    """Lag mean, 99th percentile and max in ms of the ticks run in the next ``seconds``."""
    timing = net.timing
    c0 = timing.lag_count
    time.sleep(seconds)
    c1 = timing.lag_count
    lags = [timing.lags[i % len(timing.lags)] for i in range(max(c0, c1 - len(timing.lags)), c1)]
    lags.sort()
    return (statistics.fmean(lags) * 1e3, lags[int(0.99 * (len(lags) - 1))] * 1e3,
            lags[-1] * 1e3)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=2.0, help="length of one phase")
    ap.add_argument("--rounds", type=int, default=12, help="alternations of the two phases")
    ap.add_argument("--buffers", type=int, default=20, help="buffers the client subscribes to")
    ap.add_argument("--format", default="raw", choices=["raw", "history", "events"],
                    help="how the client subscribes: history and events keep every tick "
                         "(the per-tick ring of ikaros/webui/history.py)")
    ap.add_argument("--max-rate", type=float, default=None,
                    help="the server's cap on data frames per second (default: the server's)")
    ap.add_argument("--real-time", action="store_true",
                    help="run in real time at 1 kHz and report lag instead of ticks per second")
    args = ap.parse_args(argv)

    import ikaros
    from benchmarks.models import robot_320
    from ikaros.module import WARNING

    folder = tempfile.mkdtemp(prefix="ikaros-webui-bench-")
    net = ikaros.load(robot_320(folder), **({"tick_duration": 0.001} if args.real_time else {}))
    net.log_level = WARNING
    outputs = [p + ".OUTPUT" for p in net.modules]
    step = max(1, len(outputs) // args.buffers)
    paths = outputs[::step][:args.buffers]

    ctrl = net.controller
    ctrl.start("realtime" if args.real_time else "play")
    measure = lag_figures if args.real_time else rate
    time.sleep(1.0)                                   # warm up
    alone = measure(net, args.seconds)

    options = {} if args.max_rate is None else {"max_rate": args.max_rate}
    server, thread, port = serve_in_thread(net, **options)
    proc, go, stop, quit_, frames, connected = start_client(port, paths, args.format)
    idle, busy, fps = [], [], []
    for _ in range(args.rounds):
        idle.append(measure(net, args.seconds))
        go.set()
        if not connected.wait(30):
            print("the client did not connect", file=sys.stderr)
            return 1
        time.sleep(0.2)
        f0, t0 = frames.value, time.perf_counter()
        busy.append(measure(net, args.seconds))
        fps.append((frames.value - f0) / (time.perf_counter() - t0))
        stop.set()
        while connected.is_set():
            time.sleep(0.01)
        time.sleep(0.2)
    quit_.set()
    proc.join(10)

    server.should_exit = True
    thread.join(10)
    ctrl.stop()
    ctrl.join(10)
    net.close()

    fps_text = f"client received {statistics.median(fps):.1f} frames/s"
    if args.real_time:
        def row(label, figures):
            med = [statistics.median(f[i] for f in figures) for i in range(3)]
            print(f"  {label:34}{med[0]:8.3f}{med[1]:8.3f}{med[2]:8.3f}   (p99 of the rounds: "
                  f"{', '.join(f'{f[1]:.2f}' for f in figures)})")
        print(f"robot_320, real time at 1 kHz, {args.rounds} x {args.seconds:g} s per phase "
              f"(medians of the rounds; {os.cpu_count()} cores); lag in ms: mean, p99, max")
        row("kernel only (no server):", [alone])
        row("server, no client:", idle)
        row(f"server, client on {len(paths)} buffers:", busy)
        print(f"  ({fps_text})")
        return 0
    no_client, client = statistics.median(idle), statistics.median(busy)
    drop = (no_client - client) / no_client * 100
    paired = statistics.median((a - b) / a * 100 for a, b in zip(idle, busy))
    print(f"robot_320, play mode, {args.rounds} x {args.seconds:g} s per phase "
          f"(medians; {os.cpu_count()} cores)")
    print(f"  kernel only (no server):          {alone:10.1f} ticks/s")
    print(f"  server, no client:                {no_client:10.1f} ticks/s   "
          f"(rounds: {', '.join(f'{x:.0f}' for x in idle)})")
    print(f"  server, client on {len(paths)} buffers:     {client:10.1f} ticks/s   "
          f"(rounds: {', '.join(f'{x:.0f}' for x in busy)})")
    print(f"  drop: {drop:.1f} % of the medians; {paired:.1f} % the median of the rounds' "
          f"drops ({fps_text})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
