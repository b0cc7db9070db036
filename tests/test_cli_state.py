"""ikaros -W / -L: the state saved at the end of a run and loaded after init."""
import json
import os
import resource
import subprocess
import sys

from ikaros import cli

# A counter printed: P prints 0, 1, 2, ... on ticks 0, 1, 2, ... (every connection has the
# default delay 1; an Ikaros 2 file)
MODEL = ('<group name="G" stop="3" dialect="2"><module class="Constant" name="C" data="1"/>'
         '<module class="Add" name="S"/><module class="Print" name="P"/>'
         '<connection source="C.OUTPUT" target="S.INPUT1"/>'
         '<connection source="S.OUTPUT" target="S.INPUT2" delay="1"/>'
         '<connection source="S.OUTPUT" target="P.INPUT"/></group>')


def _model(tmp_path):
    path = tmp_path / "ramp.ikg"
    path.write_text(MODEL)
    return str(path)


def test_w_then_l_continues_the_run_where_it_ended(tmp_path, capsys):
    model = _model(tmp_path)
    assert cli.main(["-b", "-W", model]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[:3] == ["P: 0", "P: 1", "P: 2"]
    assert f"Saved state to {tmp_path / 'ramp.state'} (2 items, tick 3)" in out
    assert json.loads((tmp_path / "ramp.state").read_text())["tick"] == 3
    assert cli.main(["-b", "-L", "-s", "2", model]) == 0       # ticks 3 and 4
    out = capsys.readouterr().out
    assert out.splitlines() == [f"Loaded state from {tmp_path / 'ramp.state'} (tick 3)",
                                "P: 3", "P: 4"]


def test_a_name_value_pair_after_a_bare_w_is_not_its_file(tmp_path, capsys):
    model = _model(tmp_path)
    assert cli.main(["-b", "-W", "stop=1", model]) == 0
    assert "(2 items, tick 1)" in capsys.readouterr().out
    assert (tmp_path / "ramp.state").exists() and not (tmp_path / "stop=1").exists()


def test_state_files_that_cannot_be_read_or_written_exit_1(tmp_path, capsys):
    model = _model(tmp_path)
    assert cli.main(["-b", f"-W{tmp_path}/no/such/folder.state", model]) == 1
    err = capsys.readouterr().err
    assert f"ikaros: error: cannot save the state to {tmp_path}/no/such/folder.state: No " \
           f"such file or directory" in err
    assert cli.main(["-b", "--load-state", str(tmp_path / "none.state"), model]) == 1
    err = capsys.readouterr().err
    assert "ikaros: error: cannot load the state: cannot read none.state: No such file" in err


def test_a_state_that_does_not_fit_on_the_disk_is_named_and_leaves_no_file(tmp_path):
    """A file-size limit stands in for a full disk (the write fails the same way)."""
    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (100, 100))     # the state is ~400 bytes
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = dict(os.environ, PYTHONPATH=root + os.pathsep + os.environ.get("PYTHONPATH", ""))
    state = tmp_path / "out.state"
    done = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-q", "-W", str(state),
                           _model(tmp_path)], env=env, preexec_fn=limit,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 1
    assert done.stderr == f"ikaros: error: cannot save the state to {state}: File too " \
                          f"large\n"
    assert sorted(os.listdir(tmp_path)) == ["ramp.ikg"]       # no out.state, no .tmp
