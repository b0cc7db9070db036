"""The module of a class whose code is a Python script run in a worker process."""
from __future__ import annotations

import json
import os
import sys

import numpy as np

from ..module import DEBUG, EXCEPTION, PRINT, WARNING, DynamicArray, Module, \
    attribute_name, parameter_attribute
from .process import WorkerCrashed, WorkerProcess
from .shared import SharedArrays, unlink

# what the script's log levels (proxy.py) are in the kernel's log
LEVELS = {"print": PRINT, "warning": WARNING, "error": EXCEPTION, "debug": DEBUG}
ON_ERROR = ("fail", "zero", "log")


class ScriptError(RuntimeError):
    """A script failed (the message ends with the script's traceback), or its worker
    process did."""


class ScriptedModule(Module):
    """Runs its class's script (``script``) in a worker process of its own: the kernel
    sends the inputs, changed parameters and tick number, the worker runs the script's
    hook and sends back the outputs. See docs/python-scripts.md."""

    script: str = ""                     # the script's path (set for each class)
    script_parameters: tuple = ()       # the .ikc's parameters, which the script sees
    on_error: str = "fail"
    restart_on_crash: bool = False
    use_global_names: bool = False
    python_executable: str = ""

    _ik_spawned: WorkerProcess | None = None     # started before init, not yet used
    _ik_worker: WorkerProcess | None = None

    def _ik_before_init(self) -> None:
        """Start the worker process now, so that the interpreters of all scripted modules
        start at once; init hands it the script (a process that cannot be started is
        init's error)."""
        try:
            self._ik_spawned = self._spawn()
        except ScriptError:
            self._ik_spawned = None

    def _ik_not_initialised(self) -> None:
        """The start-up failed before (or during) init: no worker is left behind."""
        for name in ("_ik_spawned", "_ik_worker"):
            worker = getattr(self, name)
            setattr(self, name, None)
            if worker is not None:
                worker.kill()

    def init(self) -> None:
        self._ik_sent: dict = {}
        self._ik_parameter_attributes = [(name, parameter_attribute(name))
                                         for name in self.script_parameters]
        self._start()

    # --- the worker ------------------------------------------------------------------------
    def _spawn(self) -> WorkerProcess:
        python = self.python_executable or sys.executable
        try:
            return WorkerProcess(python, self._log, self.warning)
        except OSError as e:
            raise ScriptError(f"the Python interpreter {python} (python_executable) for "
                              f"{self.path} cannot be started: {e.strerror or e}") from None

    def _start(self) -> None:
        """Start the script in a worker (the one started before init, else a new one)."""
        python = self.python_executable or sys.executable
        worker, self._ik_spawned = self._ik_spawned or self._spawn(), None
        self._ik_worker = worker
        inputs = {"in:" + n: self._input(n) for n in self._ik_inputs}
        outputs = {"out:" + n: self._output(n) for n in self._outputs()}
        ports = {k: a for k, a in list(inputs.items()) + list(outputs.items())
                 if a is not None}
        self._ik_shared = SharedArrays.create({k: a.shape for k, a in ports.items()})
        shared = self._ik_shared.arrays
        for key, array in ports.items():
            np.copyto(shared[key], array)
        # the kernel binds a module's ports once, so each pairs with its shared copy once
        self._ik_input_pairs = [(a, shared[k]) for k, a in inputs.items() if a is not None]
        self._ik_output_pairs = [(a, shared[k]) for k, a in outputs.items()]
        fields, arrays = self._parameter_message(self._parameter_values())
        fields.update(name=self.name, path=self.path, script=self.script,
                      on_error=self.on_error, use_global_names=self.use_global_names,
                      inputs=list(self._ik_inputs), outputs=self._outputs(),
                      shared=self._ik_shared.description)
        try:
            answer, _ = worker.request("start", fields, arrays)
        except WorkerCrashed as e:
            self._ik_worker = None
            details = "".join("\n" + line for line in e.stderr)
            raise ScriptError(f"the worker process of {self.path} ({python}) {e} before "
                              f"its script started{details}") from None
        finally:
            unlink(self._ik_shared.path)
        if answer["kind"] == "failed":
            worker.close()
            self._ik_worker = None
            raise ScriptError(_failure_text(answer))
        self._ik_hooks = frozenset(answer.get("hooks", ()))
        self._take_outputs()
        worker.forward_stderr()

    def _input(self, name: str) -> np.ndarray | None:
        array = getattr(self, attribute_name(name), None)
        if isinstance(array, DynamicArray):
            raise ScriptError(f"the input {name} of {self.path} is fed by a dynamic output, "
                              f"which a class written as a Python script cannot take")
        return None if array is None else np.asarray(array)

    def _output(self, name: str) -> np.ndarray:
        return np.asarray(getattr(self, attribute_name(name)))

    def _log(self, level: str, text: str) -> None:
        self.notify(LEVELS.get(level, PRINT), text)

    # --- parameters ------------------------------------------------------------------------
    def _parameter_values(self) -> dict:
        return {name: getattr(self, attribute)
                for name, attribute in self._ik_parameter_attributes}

    def _changed_parameters(self) -> dict:
        """The parameters whose values changed since they were last sent."""
        changed = {}
        for name, value in self._parameter_values().items():
            old = self._ik_sent.get(name, self)
            same = np.array_equal(old, value) if isinstance(value, np.ndarray) and \
                isinstance(old, np.ndarray) else (type(old) is type(value) and old == value)
            if not same:
                changed[name] = value
        return changed

    def _parameter_message(self, values: dict) -> tuple[dict, dict]:
        fields, arrays = {}, {}
        for name, value in values.items():
            self._ik_sent[name] = value.copy() if isinstance(value, np.ndarray) else value
            if isinstance(value, np.ndarray):
                arrays["par:" + name] = value
            else:
                fields[name] = value.item() if isinstance(value, np.generic) else value
        return {"parameters": fields}, arrays

    # --- the run ---------------------------------------------------------------------------
    def _outputs(self) -> list[str]:
        """The outputs the script sees: not the matrix states the kernel keeps, nor the
        aliases (views of another output, which the script writes)."""
        return [name for name, spec in self._ik_outputs.items()
                if not spec.private and "alias" not in spec.rule]

    def _take_outputs(self) -> None:
        for output, shared in self._ik_output_pairs:
            np.copyto(output, shared)

    def _request(self, kind: str, fields: dict, arrays: dict) -> dict | None:
        """Send a tick or command with the outputs as the kernel has them (a script that
        accumulates in them sees a loaded state or a reset); the answer, or None when the
        worker crashed (and was restarted, if it may be)."""
        for output, shared in self._ik_output_pairs:
            np.copyto(shared, output)
        try:
            answer, _ = self._ik_worker.request(kind, fields, arrays)
        except WorkerCrashed as e:
            self._crashed(e)
            return None
        return answer

    def tick(self) -> None:
        fields, arrays = self._parameter_message(self._changed_parameters())
        fields.update(tick=self.clock.tick, on_error=self.on_error)
        for array, shared in self._ik_input_pairs:
            np.copyto(shared, array)
        answer = self._request("tick", fields, arrays)
        if answer is None:
            return
        if answer["kind"] == "failed":
            self._failed(answer)
        else:
            self._take_outputs()

    def command(self, name: str, x: float = 0, y: float = 0, value=None) -> None:
        """A command from the user interface: the script's ``command`` hook, with the
        parameters as they are now. A script without the hook, a value that cannot be
        sent, or a hook that raises is a ScriptError (the command fails; the run goes
        on)."""
        script = os.path.basename(self.script)
        if self._ik_worker is None or "command" not in self._ik_hooks:
            raise ScriptError(f"{self.path} takes no commands ({script} defines no "
                              f"command() function)")
        given = {"value": value.item() if isinstance(value, np.generic) else value}
        if isinstance(value, np.ndarray):
            given = {}
        try:
            json.dumps(given)
        except (TypeError, ValueError) as e:
            raise ScriptError(f"the value of command {name} for {self.path} cannot be sent "
                              f"to {script}: {e}") from None
        fields, arrays = self._parameter_message(self._changed_parameters())
        fields.update(given, name=str(name), x=float(x), y=float(y))
        if isinstance(value, np.ndarray):
            arrays["value"] = value
        answer = self._request("command", fields, arrays)
        if answer is None:
            return
        if answer["kind"] == "failed":
            raise ScriptError(_failure_text(answer))
        self._take_outputs()

    def _failed(self, answer: dict) -> None:
        """A hook failed: on_error says what happens (the worker has set its outputs to
        0 or back to their last values already)."""
        text = _failure_text(answer)
        if self.on_error == "fail":
            raise ScriptError(text)
        self.error(text)
        self._take_outputs()

    def _crashed(self, error: WorkerCrashed) -> None:
        self._ik_worker = None
        what = f"the worker process of {self.path} ({os.path.basename(self.script)}) {error}"
        if not self.restart_on_crash:
            raise ScriptError(what)
        self.warning(f"{what}; restarting it (restart_on_crash)")
        self._ik_sent = {}
        self._start()

    def stop(self) -> None:
        worker, self._ik_worker = getattr(self, "_ik_worker", None), None
        if worker is None:
            return
        failure = worker.close()
        if failure is not None:
            text = _failure_text(failure)
            if self.on_error == "fail":
                raise ScriptError(text)
            self.error(text)


def _failure_text(answer: dict) -> str:
    trace = answer.get("traceback") or ""
    return answer["message"] + ("\n" + trace if trace else "")
