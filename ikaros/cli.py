"""The ``ikaros`` command: ``ikaros [options] [name=value ...] MODEL.ikg``."""
from __future__ import annotations

import argparse
import math
import os
import sys
import traceback

from . import classes, load
from .closedpipe import run_command
from .description import plain_text
from .experiments import commandline as experiment_options
from .errors import ModelError, RunError
from .language.reader import read_file
from .module import DEBUG, FATAL_ERROR, PRINT

EXIT_OK, EXIT_ERROR, EXIT_USAGE = 0, 1, 2


def replay_network(p: argparse.ArgumentParser, opts, model: str | None):
    """The network of --replay (its recorded model, every recorded module a Replay), or
    None after printing why there is none."""
    if model is not None or opts.batch:
        p.error("--replay shows a recording in the web UI: give no model file and no -b")
    if opts.record:
        p.error("--replay and --record can not be used together")
    from . import webui
    from .experiments.replay import replay_network as build
    try:
        webui._check()
        return build(opts.replay, quiet=opts.quiet)
    except (webui.MissingWebDependencies, ImportError, OSError, ValueError) as e:
        print(f"ikaros: error: --replay: {e}", file=sys.stderr)
        return None


def _ticks(text: str) -> int:
    if not text.lstrip("+").isdigit():
        raise argparse.ArgumentTypeError(f'"{text}" is not a whole number of ticks >= 0')
    return int(text)


def _positive_int(text: str) -> int:
    if not text.lstrip("+").isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f'"{text}" is not a whole number >= 1')
    return int(text)


def _seed(text: str) -> int:
    if not text.lstrip("+").isdigit() or int(text) > 0xFFFFFFFF:
        raise argparse.ArgumentTypeError(f'"{text}" is not a seed (a whole number from 0 '
                                         f'to 4294967295)')
    return int(text)


def _port(text: str) -> int:
    if not text.lstrip("+").isdigit() or int(text) > 65535:
        raise argparse.ArgumentTypeError(f'"{text}" is not a port number (0-65535)')
    return int(text)


def _token(text: str) -> str:
    if not text.strip():
        raise argparse.ArgumentTypeError("the access token must not be empty")
    return text


def _folder(text: str) -> str:
    if not text.strip():
        raise argparse.ArgumentTypeError("the folder must not be empty")
    return os.path.abspath(text)


def _literal_values(argv: list[str]) -> list[str]:
    """``-a VALUE`` and ``--token VALUE`` take VALUE as it stands, even ``-banana``
    (argparse would take it for an option). ``-p`` is Ikaros 2's profile flag, but
    followed by an executable file it is Ikaros 3's ``-p PATH``, the scripts' interpreter."""
    out, i = [], 0
    while i < len(argv):
        if argv[i] in ("-a", "--token") and i + 1 < len(argv):
            out.append("--token=" + argv[i + 1])
            i += 2
        elif argv[i] == "-p" and i + 1 < len(argv) and _is_interpreter(argv[i + 1]):
            out.append("--python=" + argv[i + 1])
            i += 2
        else:
            out.append(argv[i])
            i += 1
    return out


def _is_interpreter(path: str) -> bool:
    return (not path.endswith((".ikg", ".ikc")) and os.path.isfile(path)
            and os.access(path, os.X_OK))


def _memory(text: str) -> int:
    from .limits import LimitError, parse_bytes
    try:
        return parse_bytes(text)
    except LimitError as e:
        raise argparse.ArgumentTypeError(str(e)) from None


def _timeout(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value <= 0:
        raise argparse.ArgumentTypeError(f'"{text}" is not a finite number of seconds > 0')
    return value


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value <= 0:
        raise argparse.ArgumentTypeError(f'Invalid tick duration "{text}": give a finite '
                                         f'number of seconds > 0')
    return value


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="ikaros", description="Run an Ikaros model (.ikg).",
                epilog="name=value pairs set attributes of the top group and win over the "
                       "file. Exit status: 0 success, 1 model or run error, 2 bad usage.")
    p.add_argument("args", nargs="*", metavar="[name=value ...] MODEL.ikg")
    p.add_argument("-b", "--batch", action="store_true",
                   help="run as fast as possible and exit when the run ends; without -b "
                        "the model is served in the web UI (paused unless -S)")
    p.add_argument("-s", "--stop", type=_ticks, metavar="N",
                   help="run N ticks (ticks 0 to N-1), then stop")
    p.add_argument("-r", "--real-time", action="store_true",
                   help="run in real time on the tick_duration time base")
    p.add_argument("-d", "--tick-duration", type=_seconds, metavar="SECONDS",
                   help="the real-time tick duration in seconds")
    p.add_argument("-z", "--seed", type=_seed, metavar="N",
                   help="seed the C rand() stream the Ikaros 2 random classes share, as "
                        "the original's -z does (top-group random_seed)")
    p.add_argument("-t", "--threads", type=_positive_int, metavar="N",
                   help="size of the worker thread pool")
    p.add_argument("--priority", nargs="?", const="fifo", metavar="POLICY",
                   help="run the tick and device threads at a real-time priority: fifo "
                        "(the default), rr, or nice, optionally with a level (fifo:80, "
                        "nice:-5); memory is locked too (lock_memory=no keeps it unlocked); "
                        "what is refused is a warning")
    p.add_argument("--cpus", metavar="CORES",
                   help="pin the tick and device threads to these cores (1, 0,2 or 2-3)")
    p.add_argument("--blas-threads", metavar="N",
                   help="threads of the numerical libraries (BLAS, OpenMP) in real time "
                        "(default: the cores less one; off: not limited)")
    p.add_argument("-S", "--start", action="store_true",
                   help="web UI: start running at once (-r starts in real time)")
    p.add_argument("-i", "--info", action="store_true",
                   help="print modules, connections, buffers with shapes, and the schedule")
    p.add_argument("-w", "--port", type=_port, metavar="PORT",
                   help="web UI port (default 8000)")
    p.add_argument("--bind", metavar="ADDRESS", default="127.0.0.1",
                   help="address the web UI listens on (default 127.0.0.1, this machine "
                        "only); any other address requires an access token")
    p.add_argument("--token", "-a", metavar="TOKEN", type=_token,
                   help="the web UI's access token, or password (one is made up when "
                        "--bind serves other machines); -a PASSWORD as in Ikaros 3, "
                        "taken literally even when it starts with -")
    p.add_argument("-u", "--user-data", type=_folder, metavar="DIR",
                   help="the folder where modules write files with relative names "
                        "(made if missing; default: the model's folder); files are read "
                        "relative to the model's folder. Also user_data=DIR; a "
                        "user_data attribute in the model file is ignored")
    p.add_argument("--models", metavar="DIR",
                   help="web UI editor: the folder to save, list, open and create models "
                        "in (default: the model's folder)")
    p.add_argument("--max-memory", type=_memory, metavar="SIZE",
                   help="the most memory the model's buffers may take, in bytes or with "
                        "K, M, G (default: half the physical memory)")
    p.add_argument("--max-body", type=_memory, metavar="SIZE", default=4 << 20,
                   help="web UI: the largest request body or WebSocket message, in bytes "
                        "or with K, M, G (default 4M); larger ones are refused with 413")
    p.add_argument("--build-timeout", type=_timeout, metavar="SECONDS", default=30.0,
                   help="web UI: how long a build from the editor may take before it is "
                        "abandoned with an error (default 30)")
    p.add_argument("-L", "--load-state", nargs="?", const=True, metavar="FILE",
                   help="load the state (outputs, delay lines, declared state, tick) from "
                        "FILE after init; without FILE, MODEL.state beside the model")
    p.add_argument("-W", "--save-state", nargs="?", const=True, metavar="FILE",
                   help="save the state to FILE at the end of the run; without FILE, "
                        "MODEL.state beside the model")
    p.add_argument("-p", "--profile", action="store_true",
                   help="measure per-module time and print the timing figures at exit")
    p.add_argument("--python", metavar="PATH",
                   help="the Python interpreter that runs the scripts of Python-scripted "
                        "classes (python_executable; also -p PATH, as in Ikaros 3, when PATH is an "
                        "executable file; default: this one)")
    p.add_argument("--dialect", choices=("2", "3"),
                   help="read the model as written for Ikaros 2 or Ikaros 3 (first tick 0 "
                        "or 1, ...); default: the file's dialect attribute, else what the "
                        "file contains (docs/language.md)")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="print only errors: no warnings, no print messages")
    p.add_argument("--strict", action="store_true",
                   help="make every compatibility warning an error (for clean files)")
    p.add_argument("--lenient", action="store_true",
                   help="drop connections to modules or ports that do not exist, with a "
                        "warning, as Ikaros 3 does (by default they are errors)")
    p.add_argument("-v", "--verbose", action="store_true",
                   help="print debug messages and full tracebacks")
    p.add_argument("--classes", action="store_true", help="list every class found")
    p.add_argument("--class", dest="class_name", metavar="NAME",
                   help="print one class's description")
    p.add_argument("--modules-doc", nargs="?", const="docs/modules.md", metavar="FILE",
                   help="write the standard module reference (Markdown) to FILE "
                        "(default docs/modules.md); - prints it")
    experiment_options.add_arguments(p)
    return p


def _state_options(opts) -> None:
    """``-W model.ikg``: a bare -W (or -L) followed by the model, which argparse took for
    the option's file."""
    for key in ("load_state", "save_state"):
        value = getattr(opts, key)
        if not isinstance(value, str):
            continue
        name, eq, _ = value.partition("=")
        model_given = any("=" not in a for a in opts.args)
        if (eq and name.isidentifier()) or (value.endswith(".ikg") and not model_given):
            opts.args.insert(0, value)
            setattr(opts, key, True)


def _state_file(value) -> str | None:
    """The file of -L/-W: None (the model's .state) for a bare option."""
    return None if value is True else value


def _save_state(net, opts) -> bool:
    """-W at the end of the run; False (reported) when the state could not be written."""
    from .kernel.state import StateError
    try:
        net.save_state(_state_file(opts.save_state))
    except StateError as e:
        print(f"ikaros: error: cannot save the state: {e}", file=sys.stderr)
        return False
    except OSError as e:
        where = f" to {e.filename}" if e.filename else ""
        print(f"ikaros: error: cannot save the state{where}: {e.strerror or e}",
              file=sys.stderr)
        return False
    return True


def _split_args(p, args: list[str]) -> tuple[str | None, dict]:
    model, overrides = None, {}
    for arg in args:
        name, eq, value = arg.partition("=")
        if eq and name.isidentifier():
            overrides[name] = value
        elif model is None:
            model = arg
        else:
            p.error(f'more than one model file given: "{model}" and "{arg}"')
    return model, overrides


def _web_port(opts, model_port: int | None) -> int:
    """The web UI's port: -w, else the model's ``webui_port``, else 8000."""
    return opts.port if opts.port is not None else model_port or 8000


def _model_port(model: str | None, overrides: dict) -> int | None:
    """``webui_port`` given on the command line or in the model's top group, read before
    the model is built; None when there is none or it is not a port (the load reports a
    bad one)."""
    text = overrides.get("webui_port")
    if text is None and model is not None:
        try:
            text = read_file(model, root_tag="group").attrs.get("webui_port")
        except (ModelError, OSError, ValueError):
            return None                 # the load reports it
    try:
        port = int(str(text).strip())
    except ValueError:
        return None
    return port if 1 <= port <= 65535 else None


def _listen(opts, model_port: int | None):
    """The web UI's listening socket, opened before the model is built so that a port in
    use ends the command before any module's ``init`` runs; None (reported) if it fails."""
    from .webui.server import ServeError, listen
    try:
        return listen(opts.bind, _web_port(opts, model_port))
    except ServeError as e:
        print(f"ikaros: error: {e}", file=sys.stderr)
        return None


def _serve(net, opts, failure: dict | None = None, sock=None) -> int:
    """Serve the model in the web UI until Ctrl-C; the kernel runs in a background thread.
    ``failure``: the model failed to build and ``net`` stands in for it (webui/broken.py);
    ``sock``: the socket from ``_listen`` (else one is opened here)."""
    from .kernel.control import PAUSE, PLAY, REALTIME
    from .webui.server import ServeError, is_loopback, new_token, serve
    host = opts.bind
    token = opts.token
    if token is None and not is_loopback(host):
        token = new_token()
    state = REALTIME if opts.real_time else PLAY if opts.start else PAUSE
    if opts.stop is not None:
        net.stop_tick = opts.stop

    saved = [True]

    def end(current):
        """-W: the state of the network served at the end (the editor may have built
        another in the model's place; not the stand-in of a model that failed to build)."""
        if not opts.save_state or (failure is not None and current is net):
            return
        if current.stop_reason and current.stop_reason[0] == FATAL_ERROR:
            print("ikaros: the state is not saved: the run ended with a fatal error",
                  file=sys.stderr)
            return
        saved[0] = _save_state(current, opts)

    def ready(url):
        print(f"ikaros: serving {os.path.basename(net.filename)} at "
              f"{url}{'?token=' + token if token else ''}  (Ctrl-C to quit)\n", end="",
              flush=True)           # one write: the kernel's thread may be printing
        if token:
            print(f"ikaros: access token: {token}", flush=True)
    try:
        net.profiling = opts.profile
        serve(net, host, _web_port(opts, net.webui_port), token, state,
              on_ready=ready, models_dir=opts.models, max_memory=opts.max_memory,
              max_body=opts.max_body, build_timeout=opts.build_timeout, failure=failure,
              on_end=end, sock=sock)
    except ServeError as e:
        print(f"ikaros: error: {e}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:           # Ctrl-C or SIGTERM; net.close() stops the modules
        print("ikaros: interrupted", flush=True)       # on stdout, as "serving ..." is
    finally:
        if sock is not None:
            sock.close()
        net.close()
        if opts.profile:
            print(net.profile_text())
        _leave_stuck_builds()
    return EXIT_OK if saved[0] else EXIT_ERROR


def _leave_stuck_builds() -> None:
    """Exit now when builds started from the web UI never returned (their threads cannot
    be stopped, and would hold up the exit)."""
    from .webui.builds import stuck
    if stuck():
        from .interrupt import force_exit
        print("ikaros: leaving a build from the web UI that never returned",
              file=sys.stderr)
        force_exit(EXIT_OK)


def _worker(argv: list[str]) -> int:
    """``ikaros worker ...``: serve groups of models to other kernels (docs/links.md)."""
    from .links.worker import main as worker_main
    return worker_main(argv)


def main(argv: list[str] | None = None) -> int:
    """The ``ikaros`` command (``argv``: its arguments; None: the process's own)."""
    if argv is None:            # the command itself (not a call from Python code)
        from .interrupt import install
        install()
        return run_command(_main, sys.argv[1:])
    return _main(list(argv))


def _main(argv: list[str]) -> int:
    if argv[:1] == ["sweep"]:
        from .experiments.sweepcli import main as sweep_main
        return sweep_main(argv[1:])
    if argv[:1] == ["worker"]:
        return _worker(argv[1:])
    p = parser()
    opts = p.parse_intermixed_args(_literal_values(argv))
    _state_options(opts)
    experiment_options.check_arguments(p, opts)
    model, overrides = _split_args(p, opts.args)
    if "user_data" in overrides:        # user_data=DIR: the command line's -u DIR
        try:
            opts.user_data = _folder(overrides.pop("user_data"))
        except argparse.ArgumentTypeError as e:
            p.error(f"user_data: {e}")
    folders = [os.path.dirname(os.path.abspath(model))] if model else []
    net = None
    try:
        if opts.modules_doc is not None:
            from .docgen import module_reference
            text = module_reference()
            if opts.modules_doc == "-":
                sys.stdout.write(text)
                return EXIT_OK
            try:
                with open(opts.modules_doc, "w", encoding="utf-8", newline="\n") as f:
                    f.write(text)
            except OSError as e:
                print(f"ikaros: error: cannot write {opts.modules_doc}: {e.strerror or e}",
                      file=sys.stderr)
                return EXIT_ERROR
            if not opts.quiet:
                print(f"wrote {opts.modules_doc}")
            return EXIT_OK
        if opts.classes:
            for name, desc in classes(*folders).items():
                first = plain_text(desc.description).split(". ")[0]
                print(f"{name:24} {first}")
            return EXIT_OK
        if opts.class_name:
            found = classes(*folders).get(opts.class_name)
            if found is None:
                print(f'ikaros: error: no class named "{opts.class_name}"', file=sys.stderr)
                return EXIT_ERROR
            print(found.to_text())
            return EXIT_OK
        if opts.replay:
            net = replay_network(p, opts, model)
            return EXIT_ERROR if net is None else _serve(net, opts)
        if model is None:
            p.error("no model file given")
        if opts.tick_duration is not None:
            overrides["tick_duration"] = str(opts.tick_duration)
        if opts.threads is not None:
            overrides["threads"] = str(opts.threads)
        if opts.seed is not None:
            overrides["random_seed"] = str(opts.seed)
        if opts.python is not None:
            overrides["python_executable"] = opts.python
        for key in ("priority", "cpus", "blas_threads"):
            if getattr(opts, key) is not None:
                overrides[key] = getattr(opts, key)
        if opts.dialect is not None:
            overrides["dialect"] = opts.dialect
        if opts.models is not None and not os.path.isdir(opts.models):
            p.error(f'--models "{opts.models}" is not a folder')
        if not opts.batch:
            from . import webui
            try:
                webui._check()
            except webui.MissingWebDependencies as e:
                print(f"ikaros: error: {e} (or run in batch mode with -b)", file=sys.stderr)
                return EXIT_ERROR
        if opts.strict and opts.lenient:
            p.error("--strict and --lenient can not be used together")
        sock = None if opts.batch else _listen(opts, _model_port(model, overrides))
        if not opts.batch and sock is None:
            return EXIT_ERROR
        failure = None
        try:
            net = load(model, strict=opts.strict, lenient=opts.lenient, quiet=opts.quiet,
                       max_memory=opts.max_memory, user_data=opts.user_data, **overrides)
        except BaseException as e:
            if not isinstance(e, ModelError) or opts.batch:
                if sock is not None:
                    sock.close()
                raise
            from .webui.broken import open_broken     # fixed in the browser's editor
            net, failure = open_broken(model, overrides, e, max_memory=opts.max_memory)
            print(f"ikaros: error: {e}\nikaros: the model opens in the web UI's editor "
                  f"to be fixed", file=sys.stderr)
        net.log_level = FATAL_ERROR if opts.quiet else DEBUG if opts.verbose else PRINT
        if opts.load_state and failure is None:
            from .kernel.state import StateError
            try:
                net.load_state(_state_file(opts.load_state))
            except StateError as e:
                net.close()
                print(f"ikaros: error: cannot load the state: {e}", file=sys.stderr)
                return EXIT_ERROR
        if opts.info:
            print(net.info())
        ok = getattr(net, "checksum_ok", True)
        try:
            recording = experiment_options.start_recording(net, opts, argv)
        except (ValueError, ImportError, OSError) as e:
            net.close()
            if sock is not None:
                sock.close()
            print(f"ikaros: error: --record: {e}", file=sys.stderr)
            return EXIT_ERROR
        try:
            experiment_options.start_live_view(net, opts)
        except (ImportError, OSError, RuntimeError) as e:
            net.close()
            if sock is not None:
                sock.close()
            print(f"ikaros: error: --foxglove: {e}", file=sys.stderr)
            return EXIT_ERROR
        if not opts.batch:
            return _serve(net, opts, failure, sock)
        try:
            net.profiling = opts.profile
            with experiment_options.batch_session(net, opts, recording):
                net.run(ticks=opts.stop, real_time=opts.real_time)
            if opts.save_state and not _save_state(net, opts):
                return EXIT_ERROR
        finally:
            net.close()
            if opts.profile:
                print(net.profile_text())
        if net.stop_reason and net.stop_reason[0] == FATAL_ERROR:     # a stop() failed
            return EXIT_ERROR
        return EXIT_OK if ok or not opts.batch else EXIT_ERROR
    except ModelError as e:
        print(f"ikaros: error: {e}", file=sys.stderr)
        if opts.verbose:
            traceback.print_exc()
        return EXIT_ERROR
    except RunError as e:
        if not e.printed:           # (a module's fatal error is in the log's lines)
            print(f"ikaros: run stopped: {e}", file=sys.stderr)
        if opts.verbose:
            traceback.print_exc()
        return EXIT_ERROR
    except KeyboardInterrupt:
        if net is not None and net.stop_reason and net.stop_reason[0] == FATAL_ERROR:
            if not net.stop_printed:        # the run had failed before the Ctrl-C came
                print(f"ikaros: run stopped: {net.stop_reason[1]}\n", end="",
                      file=sys.stderr)
            return EXIT_ERROR
        print("ikaros: interrupted\n", end="", file=sys.stderr)    # (one write)
        return EXIT_OK
