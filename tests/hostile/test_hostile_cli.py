"""Hostile models through the ikaros command: each gives its exact error and exit status 1,
no traceback, within a bounded time, in a process whose memory is limited."""
from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
import time

import pytest

from hostile_cases import BUILD_ERRORS, MAX_MEMORY, RUN_ERRORS, generate

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ADDRESS_SPACE = 1536 << 20      # the process may map no more than 1.5 GB
SECONDS = 20        # of CPU time, the most the process may take (RLIMIT_CPU)
WALL_SECONDS = 90   # a hang is cut off after this (the CPU bound is what is asserted)


def _limited():
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))
    resource.setrlimit(resource.RLIMIT_CPU, (SECONDS, SECONDS))


def _env():
    return dict(os.environ, PYTHONPATH=ROOT, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")


def ikaros(*args, timeout=WALL_SECONDS):
    """The command's result and the CPU seconds it took (the machine's load does not
    change those, as it changes the wall time)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([sys.executable, "-m", "ikaros", *args], capture_output=True,
                       text=True, timeout=timeout, cwd=ROOT, preexec_fn=_limited, env=_env())
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r, (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    d = str(tmp_path_factory.mktemp("hostile"))
    generate(d)
    return d


@pytest.mark.parametrize("name", sorted(BUILD_ERRORS))
def test_a_hostile_model_gives_its_error(folder, name):
    r, seconds = ikaros("-b", "-s", "3", "--max-memory", MAX_MEMORY,
                        os.path.join(folder, f"{name}.ikg"))
    assert r.returncode == 1, r.stderr
    *notes, error = r.stderr.splitlines()
    assert error == f"ikaros: error: {BUILD_ERRORS[name].format(dir=folder)}"
    # the only other line is a note on the file's dialect (its Print is Ikaros 3's)
    assert all(": note: read as an Ikaros 3 file" in line for line in notes)
    assert r.stdout == ""
    assert seconds < 10


@pytest.mark.parametrize("name", sorted(RUN_ERRORS))
def test_a_module_fault_in_the_run_exits_1_naming_the_module(folder, name):
    r, seconds = ikaros("-b", "-s", "3", os.path.join(folder, f"{name}.ikg"))
    assert r.returncode == 1, r.stderr
    assert r.stderr.splitlines() == RUN_ERRORS[name]
    assert seconds < 10


def test_a_setting_given_on_the_command_line_is_blamed_on_it():
    r, _ = ikaros("-b", "stop=abc", "examples/hello.ikg")
    assert r.returncode == 1
    assert r.stderr == 'ikaros: error: stop="abc" must be a whole number >= -1 (given on the ' \
                       'command line)\n'


@pytest.mark.parametrize("args, message", [
    (["--token", ""], "argument --token/-a: the access token must not be empty"),
    (["--max-memory", "lots"], 'argument --max-memory: "lots" is not an amount of memory '
                               '(such as 512M or 2G)'),
    (["--max-memory", "0"], 'argument --max-memory: "0" is not an amount of memory > 0'),
])
def test_bad_limits_and_tokens_are_usage_errors(args, message):
    r, _ = ikaros(*args, "examples/hello.ikg")
    assert r.returncode == 2
    assert r.stderr.splitlines()[-1] == f"ikaros: error: {message}"


def _interrupt_while_init_loops(folder, tmp_path, *extra):
    marker = tmp_path / "looping"
    proc = subprocess.Popen([sys.executable, "-m", "ikaros", *extra,
                             f"marker={marker}", os.path.join(folder, "loops_in_init.ikg")],
                            cwd=ROOT, env=_env(), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=_limited)
    try:
        end = time.monotonic() + 15
        while not marker.exists() and time.monotonic() < end and proc.poll() is None:
            time.sleep(0.02)
        assert marker.exists(), proc.communicate(timeout=5)
        time.sleep(0.2)                     # well inside the loop
        start = time.monotonic()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=10)
        return proc.returncode, err, time.monotonic() - start
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()


@pytest.mark.parametrize("mode", [["-b"], ["-w", "0"]])
def test_ctrl_c_ends_a_build_that_loops_in_init(folder, tmp_path, mode):
    status, err, seconds = _interrupt_while_init_loops(folder, tmp_path, *mode)
    assert (status, err) == (0, "ikaros: interrupted\n")
    assert seconds < 2


def test_ctrl_c_ends_even_a_module_that_swallows_it(folder, tmp_path):
    status, err, seconds = _interrupt_while_init_loops(folder, tmp_path, "-b", "swallow=yes")
    assert status == 130
    assert err == "ikaros: interrupted; forced to exit (not done 2 s after Ctrl-C)\n"
    assert seconds < 3.5


def test_the_profile_table_keeps_its_columns_for_long_names(tmp_path):
    name = "A_module_with_a_name_far_longer_than_thirty_two"
    (tmp_path / "p.ikg").write_text(
        f'<group name="P"><module class="Constant" name="{name}" data="1"/>'
        f'<module class="M02_SensoryCortex" name="S"/>'
        f'<connection source="{name}.OUTPUT" target="S.INPUT"/></group>')
    r, _ = ikaros("-b", "-s", "2", "-p", str(tmp_path / "p.ikg"))
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    table = lines[lines.index(next(x for x in lines if x.startswith("module "))):]
    assert len(table) == 3
    header = table[0]
    for row in table[1:]:
        cells = row.split()
        assert len(cells) == 5
        # every column starts where its header does
        assert row.index(cells[1]) == header.index("class")
        assert row.rindex(cells[4]) + len(cells[4]) == len(header)
    assert {row.split()[0] for row in table[1:]} == {name, "S"}
