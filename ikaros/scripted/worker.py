"""The worker process of a script-backed module: ``python worker.py``.

Started by the kernel with this file's path (the interpreter need not have ikaros, only
NumPy). Its stdin and stdout are the message pipe (protocol.py); what the script prints
and logs goes to the kernel as log messages, and anything written to the process's own
stdout or stderr reaches the kernel's log through stderr. The worker ends when the kernel
closes the pipe (after the script's shutdown hook) or goes away.
"""
import io
import logging
import os
import signal
import sys
import threading
import time

_HERE = os.path.dirname(os.path.abspath(__file__))
_PARENT_CHECK = 0.5       # seconds between checks that the kernel still runs
_shutting_down = False    # the shutdown hook runs: the parent check waits for it

from protocol import WorkerGone, receive, send  # noqa: E402  (this folder is sys.path[0])
from proxy import DEBUG, ERROR, LOG, WARNING, ModuleProxy  # noqa: E402
from script import Script, ScriptError  # noqa: E402
from shared import SharedArrays  # noqa: E402

# the script's own imports must not find this folder's files
sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != _HERE]
for _name in ("protocol", "proxy", "script", "shared"):
    sys.modules.pop(_name, None)


class Channel:
    """The pipe to the kernel; messages from several threads do not mix."""

    def __init__(self, reader, writer):
        self.reader, self.writer = reader, writer
        self.lock = threading.Lock()

    def send(self, kind, fields=None, arrays=None):
        with self.lock:
            send(self.writer, kind, fields, arrays)

    def log(self, level, text):
        self.send("log", {"level": level, "text": text})


class LineWriter(io.TextIOBase):
    """``sys.stdout``/``sys.stderr`` of the script: each line becomes a log message."""

    def __init__(self, channel, level):
        self.channel, self.level, self.pending = channel, level, ""

    def writable(self):
        return True

    def write(self, text):
        *lines, self.pending = (self.pending + text).split("\n")
        for line in lines:
            self.channel.log(self.level, line)
        return len(text)

    def flush(self):
        if self.pending:
            self.channel.log(self.level, self.pending)
            self.pending = ""


class Forward(logging.Handler):
    """Records of the standard ``logging`` module become the module's log messages."""

    def __init__(self, channel):
        super().__init__()
        self.channel = channel

    def emit(self, record):
        level = (ERROR if record.levelno >= logging.ERROR else WARNING
                 if record.levelno >= logging.WARNING else LOG
                 if record.levelno >= logging.INFO else DEBUG)
        text = self.format(record)
        if record.name != "root":
            text = f"{record.name}: {text}"
        self.channel.log(level, text)


def _watch_parent():
    parent = os.getppid()

    def watch():
        while True:
            time.sleep(_PARENT_CHECK)
            if os.getppid() != parent and not _shutting_down:
                os._exit(0)
    threading.Thread(target=watch, daemon=True).start()


class Worker:
    """Runs one module's script: start (the script and its init), then ticks until
    shutdown."""

    def __init__(self, channel):
        self.channel = channel
        self.script = None
        self.inputs, self.outputs = {}, {}
        self.on_error = "fail"

    def serve(self):
        while True:
            try:
                header, arrays = receive(self.channel.reader)
            except WorkerGone:          # the kernel closed the pipe: the run has ended
                self.shutdown()
                return
            if header["kind"] == "start":
                self.start(header, arrays)
            elif header["kind"] == "command":
                self.command(header, arrays)
            else:
                self.tick(header, arrays)

    def _flush(self):
        sys.stdout.flush()
        sys.stderr.flush()

    def _failed(self, error):
        self._flush()
        self.channel.send("failed", {"message": str(error),
                                     "traceback": getattr(error, "traceback_text", "")})

    def start(self, header, arrays):
        shared = SharedArrays.open(header["shared"]).arrays
        self.inputs = {name: shared.get("in:" + name) for name in header["inputs"]}
        self.outputs = {name: shared["out:" + name] for name in header["outputs"]}
        self.on_error = header["on_error"]
        proxy = ModuleProxy(header["name"], header["path"], self.inputs, self.outputs,
                            _parameters(header, arrays), self.channel.log)
        try:
            sys.path.insert(0, os.path.dirname(header["script"]))
            self.script = Script(header["script"], proxy, header["use_global_names"])
            self.script.call("init")
        except ScriptError as e:
            self.script = None
            return self._failed(e)
        self._flush()
        self.channel.send("ready", {"hooks": [name for name in self.script.hooks
                                              if self.script.has(name)]})

    def tick(self, header, arrays):
        module = self.script.module
        module.set_parameters(_parameters(header, arrays))
        module.tick = header["tick"]
        self.on_error = header["on_error"]      # a parameter: it may have changed
        kept = {k: v.copy() for k, v in self.outputs.items()} \
            if self.on_error == "log" else None
        try:
            self.script.call("tick")
        except ScriptError as e:
            for name, array in self.outputs.items():
                array[...] = kept[name] if kept is not None else 0
            return self._failed(e)
        self._flush()
        self.channel.send("done")

    def command(self, header, arrays):
        """A command from the user interface, between ticks: the script's command hook
        (the kernel calls it only when the script has one). A failure is the command's:
        the kernel does not take what the hook wrote."""
        self.script.module.set_parameters(_parameters(header, arrays))
        value = arrays["value"] if "value" in arrays else header.get("value")
        try:
            self.script.call("command", header["name"], header["x"], header["y"], value)
        except ScriptError as e:
            return self._failed(e)
        self._flush()
        self.channel.send("done")

    def shutdown(self):
        """Run the script's shutdown hook and say how it went (the kernel reads until the
        pipe closes; if it has gone, nobody hears)."""
        global _shutting_down
        _shutting_down = True
        try:
            if self.script is not None:
                self.script.call("shutdown")
            self._flush()
            self.channel.send("bye")
        except ScriptError as e:
            self._failed(e)


def _parameters(header, arrays):
    values = dict(header.get("parameters", {}))
    values.update({key[4:]: array for key, array in arrays.items() if key.startswith("par:")})
    return values


def main():
    reader = os.fdopen(os.dup(0), "rb")
    writer = os.fdopen(os.dup(1), "wb")
    os.dup2(os.open(os.devnull, os.O_RDONLY), 0)
    os.dup2(2, 1)           # stray writes to fd 1 go to stderr, which the kernel reads
    signal.signal(signal.SIGINT, signal.SIG_IGN)    # the kernel ends the run (and us)
    _watch_parent()
    channel = Channel(reader, writer)
    sys.stdout = LineWriter(channel, LOG)
    sys.stderr = LineWriter(channel, WARNING)
    root = logging.getLogger()
    root.handlers[:] = [Forward(channel)]
    root.setLevel(logging.INFO)
    try:
        Worker(channel).serve()
    except OSError:             # the kernel went away while we answered
        pass


if __name__ == "__main__":
    main()
