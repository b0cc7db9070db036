"""The ikaros command: options, exit statuses, messages."""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = os.path.join(ROOT, "tests", "cli_models")


def ikaros(*args, timeout=60):
    return subprocess.run([sys.executable, "-m", "ikaros", *args], capture_output=True,
                          text=True, timeout=timeout, cwd=ROOT)


def test_hello_runs_100_ticks_in_batch_mode():
    r = ikaros("-b", "-s", "100", "examples/hello.ikg")
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == [f"Show: {v:g}" for v in
                                     (0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75, 2, 0, 0.25)]
    r = ikaros("-b", "-s", "21", "examples/hello.ikg", "gain=3")
    assert r.stdout.splitlines() == ["Show: 0.375", "Show: 0.75", "Show: 1.125"]


def test_info_prints_the_schedule_of_nested_groups():
    r = ikaros("-b", "-s", "1", "-i", os.path.join(MODELS, "nested.ikg"))
    assert r.returncode == 0, r.stderr
    schedule = r.stdout.split("Schedule:\n")[1].split("\n\n")[0].splitlines()
    assert schedule == ["  1. Arm.Inner.A", "  2. Arm.B", "  3. Last"]
    assert "    output OUTPUT: 2" in r.stdout
    assert "input INPUT: 2 (shares its source's memory)" in r.stdout


def test_model_errors_exit_1_with_one_message_naming_file_and_line():
    path = os.path.join(MODELS, "broken.ikg")
    r = ikaros("-b", "-s", "1", path)
    assert r.returncode == 1
    assert r.stderr.strip().splitlines() == [
        f'ikaros: error: {path}:4: <connection>: connection target "S.NOPE" not found: '
        f'module S has no input named "NOPE" (inputs: INPUT, SCALE)']
    assert "Traceback" not in r.stderr
    assert "Traceback" in ikaros("-v", "-b", "-s", "1", path).stderr


def test_bad_usage_exits_2():
    assert ikaros("-s", "1.5", "examples/hello.ikg").returncode == 2
    assert ikaros("-d", "nan", "examples/hello.ikg").returncode == 2
    assert ikaros("-t", "0", "examples/hello.ikg").returncode == 2
    assert ikaros("-b").returncode == 2
    assert ikaros("--no-such-option").returncode == 2


def test_fatal_error_stops_after_the_tick_calls_stop_and_exits_1():
    r = ikaros("-b", "-s", "10", os.path.join(MODELS, "fail.ikg"))
    assert r.returncode == 1
    assert r.stdout.splitlines() == ["F: stopped at tick 2"]
    assert r.stderr == "fatal error: F: broken at tick 2\n"          # once
    r = ikaros("-b", "-q", "-s", "10", os.path.join(MODELS, "fail.ikg"))
    assert (r.returncode, r.stderr) == (1, "fatal error: F: broken at tick 2\n")


def test_exception_in_tick_is_a_fatal_error_naming_the_module():
    r = ikaros("-b", "-s", "10", os.path.join(MODELS, "fail.ikg"), "how=raise")
    assert r.returncode == 1
    assert r.stderr == "fatal error: F: RuntimeError: boom\n"


def test_end_of_file_stops_cleanly_with_exit_0():
    r = ikaros("-b", "-s", "10", os.path.join(MODELS, "fail.ikg"), "how=eof", "at=4")
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["F: stopped at tick 4"]


def test_classes_and_class():
    r = ikaros("--classes")
    assert r.returncode == 0
    names = [line.split()[0] for line in r.stdout.splitlines()]
    for name in ("Constant", "Scale", "Add", "Sweep", "Print", "InputFile", "OutputFile"):
        assert name in names
    r = ikaros("--class", "Scale")
    assert r.returncode == 0
    assert "  factor (number, default 1.0): the factor the input is multiplied by" in r.stdout
    assert ikaros("--class", "NoSuchClass").returncode == 1


def test_classes_and_class_show_descriptions_without_their_markup():
    """Issue 27, item 6: ``code`` in a description is printed as the bare word."""
    listed = ikaros("--classes").stdout
    assert "`" not in listed
    scale = next(line for line in listed.splitlines() if line.split()[0] == "Scale")
    assert scale.split(None, 1)[1] == ("Multiplies the input by factor, and by the first "
                                       "element of SCALE when that input is connected.")
    text = ikaros("--class", "Scale").stdout
    assert "`" not in text
    assert "Multiplies the input by factor, and by the first element of SCALE" in text


def test_options_may_stand_between_overrides_and_the_model():
    r = ikaros("gain=3", "-b", "-s", "21", "examples/hello.ikg", "-q")
    assert r.returncode == 0, r.stderr
    assert r.stdout == ""          # -q hides prints


def test_compatibility_warnings_quiet_strict_and_lenient():
    path = os.path.join(MODELS, "lenient.ikg")
    r = ikaros("-b", "-s", "1", path)
    assert r.returncode == 1
    assert r.stderr.splitlines()[-1] == (
        f'ikaros: error: {path}:5: <connection>: connection target "Gone.INPUT" not found: '
        f'there is no "Gone" seen from group "L"')
    r = ikaros("-b", "-s", "1", "--lenient", path)
    assert r.returncode == 0, r.stderr
    assert r.stdout == "P: 2\n"
    assert r.stderr.splitlines() == [
        f'{path}:2: warning: <module name="C">: no space before attribute "description"',
        f'{path}:3: warning: <module name="P">: parameter "interval" of P has an empty value; '
        f'the default applies',
        f'{path}:5: warning: <connection>: connection target "Gone.INPUT" not found: there is '
        f'no "Gone" seen from group "L"; the connection is dropped (lenient)']
    r = ikaros("-b", "-s", "1", "--lenient", "-q", path)
    assert (r.returncode, r.stdout, r.stderr) == (0, "", "")
    r = ikaros("-b", "-s", "1", "--strict", path)
    assert r.returncode == 1
    assert r.stderr.splitlines() == [
        f'ikaros: error: {path}:2: <module name="C">: no space before attribute "description" '
        f'(an error with --strict)']
    assert ikaros("-b", "--strict", "--lenient", path).returncode == 2


def test_a_password_is_the_access_token_taken_literally():
    from ikaros import cli
    for argv, token in ((["-a", "-banana"], "-banana"), (["-atrue"], "true"),
                        (["--token", "-x"], "-x"), (["-a", "pw"], "pw")):
        opts = cli.parser().parse_intermixed_args(cli._literal_values(argv + ["m.ikg"]))
        assert (opts.token, opts.args) == (token, ["m.ikg"])


def test_user_data_folder_takes_written_files_and_the_model_cannot_choose_it(tmp_path):
    import ikaros
    model = tmp_path / "m.ikg"
    model.write_text('<group user_data="elsewhere"><module class="Constant" name="C" data="5"/>'
                     '<module class="OutputFile" name="O" filename="o.csv" timestamp="tick" decimals="1"/>'
                     '<connection source="C.OUTPUT" target="O.INPUT" delay="0" label="v"/>'
                     '</group>')
    net = ikaros.load(str(model), user_data=str(tmp_path / "data"), quiet=True)
    net.run(ticks=1)
    net.close()
    # an Ikaros 3 file by its signs (INPUT, a label): the first tick is 1
    assert (tmp_path / "data" / "o.csv").read_text() == "tick,v\n1,5.0\n"
    assert not (tmp_path / "o.csv").exists() and not (tmp_path / "elsewhere").exists()
    assert [w.message for w in net.warnings][:1] == [
        "user_data in a model file is ignored (a model may not choose where files are "
        "written); use ikaros -u DIR"]


def test_the_web_ui_listens_on_the_models_webui_port_unless_w_is_given(tmp_path):
    import signal
    import socket
    ports = []
    for _ in range(2):
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            ports.append(s.getsockname()[1])
    model = tmp_path / "m.ikg"
    model.write_text(f'<group webui_port="{ports[0]}"><module class="Constant" name="C" '
                     f'data="1"/></group>')
    for extra, port in (([], ports[0]), (["-w", str(ports[1])], ports[1]),
                        ([f"webui_port={ports[1]}"], ports[1])):
        proc = subprocess.Popen([sys.executable, "-m", "ikaros", *extra, str(model)],
                                cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True)
        try:
            line = proc.stdout.readline()
        finally:
            proc.send_signal(signal.SIGINT)
            proc.communicate(timeout=20)
        assert f" at http://127.0.0.1:{port}/" in line, line


def test_dialect_option_gives_a_file_the_ikaros_3_ticks(tmp_path):
    # golden/README.md: in Ikaros 3 a Constant reaches a delay-1 receiver on the second
    # tick (zeros on the first), and the first tick is numbered 1; in Ikaros 2 the value
    # Constant writes in init reaches it on the first tick.
    path = tmp_path / "m.ikg"
    path.write_text('<group name="G"><module class="Constant" name="C" data="4 4"/>'
                    '<module class="Print" name="P"/>'
                    '<connection source="C.OUTPUT" target="P.INPUT"/></group>')
    # an Ikaros 2 file (its matrix written with spaces), although Print is Ikaros 3's
    r = ikaros("-b", "-s", "2", str(path))
    assert r.stdout.splitlines() == ["P: 4 4", "P: 4 4"]
    assert f"{path}:1: note: read as an Ikaros 2 file" in r.stderr
    r = ikaros("-b", "-s", "2", "--dialect", "3", str(path))
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["P: 0 0", "P: 4 4"]
    assert "note" not in r.stderr
    assert ikaros("-b", "-s", "2", str(path), "dialect=3").stdout.splitlines() == \
        ["P: 0 0", "P: 4 4"]
    r = ikaros("-b", "-s", "2", "--dialect", "4", str(path))
    assert r.returncode == 2 and "--dialect" in r.stderr


def test_a_closed_pipe_ends_every_printing_command_quietly():
    """Issue 27, item 8: ``ikaros --classes | head`` (a reader that goes away) ends with no
    BrokenPipeError traceback and status 141, as a Unix tool ended by SIGPIPE."""
    for args in (["--classes"], ["--class", "Scale"], ["--modules-doc", "-"],
                 ["-b", "-s", "50", "examples/hello.ikg"]):
        read_end, write_end = os.pipe()
        os.close(read_end)                  # the reader has gone before the first write
        proc = subprocess.run([sys.executable, "-m", "ikaros", *args], stdout=write_end,
                              stderr=subprocess.PIPE, text=True, timeout=60, cwd=ROOT)
        os.close(write_end)
        assert proc.stderr == "", (args, proc.stderr)
        assert proc.returncode == 141, (args, proc.returncode)
