"""Recordings that come back damaged: cut short at several sizes, or with 256 bytes
overwritten in the middle. Each is refused at once with one line naming the file and the
damage, or read up to its last whole chunk with a note that says so: never a hang, never
a value that was not recorded. Every open runs in a child process with a time limit, so
that a hang (HDF5 retrying a damaged file for minutes, deaf to signals) fails the test
instead of hanging the suite."""
import json
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

h5py = pytest.importorskip("h5py")
pytest.importorskip("xarray")

from ikaros.experiments import open_recording  # noqa: E402
from ikaros.experiments.reading import RecordingWarning  # noqa: E402
from ikaros.testing import load_body  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
ENV = dict(os.environ, PYTHONPATH=ROOT + os.pathsep + os.environ.get("PYTHONPATH", ""))
BODY = """
<module class="Sweep" name="Counter" min="0" max="100000000" step="1"/>
<module class="Sweep" name="Grid" outputsize_x="8" outputsize_y="4" min="0" max="100000000"
        step="0.5"/>
"""
TICKS = 40000           # three chunks of 16384 rows in each dataset
SECONDS = 10            # to open one damaged file (they take milliseconds; HDF5's retries
                        # of a damaged file opened for SWMR reading took minutes)

# In a child process: open each file, one JSON line per file (the error, or the values).
OPEN_EACH = """
import json, sys, time, warnings
from ikaros.experiments import open_recording
warnings.simplefilter("ignore")
for path in sys.argv[1:]:
    start = time.monotonic()
    try:
        ds = open_recording(path)
        answer = {"rows": ds.sizes["tick"], "damage": ds.attrs.get("damage"),
                  "tick": ds["tick"].values.tolist(), "time": ds["time"].values.tolist(),
                  "real_time": ds["real_time"].values.tolist(),
                  "grid": ds["Grid.OUTPUT"].values.reshape(ds.sizes["tick"], -1).tolist(),
                  "model": ds.attrs["model"], "parameters": ds.attrs["parameters"]}
    except Exception as e:
        answer = {"error": type(e).__name__, "message": str(e)}
    answer["seconds"] = time.monotonic() - start
    print(json.dumps(answer), flush=True)
"""


def open_in_child(paths: list) -> list[dict]:
    done = subprocess.run([sys.executable, "-c", OPEN_EACH, *map(str, paths)], env=ENV,
                          capture_output=True, text=True, timeout=60 + SECONDS * len(paths))
    assert done.returncode == 0, done.stderr
    answers = [json.loads(line) for line in done.stdout.splitlines()]
    assert len(answers) == len(paths)
    return answers


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    folder = tmp_path_factory.mktemp("whole")
    net = load_body(folder, BODY)
    with net.record(str(folder / "run.h5")):
        net.run(ticks=TICKS)
    net.close()
    path = folder / "run.h5"
    return path, open_recording(str(path))


def damaged(folder, source, name: str, size: int | None = None,
            overwrite: tuple | None = None):
    data = bytearray(source.read_bytes())
    if overwrite is not None:
        at, patch = overwrite
        data[at:at + len(patch)] = patch
    path = folder / name
    path.write_bytes(bytes(data[:size]))
    return path


def assert_refused_or_true(path, answer: dict, whole) -> None:
    """Refused with one line naming the file, or the recorded values up to a row."""
    assert answer["seconds"] < SECONDS
    if "error" in answer:
        assert answer["error"] in ("RecordingError", "OSError"), answer
        assert str(path) in answer["message"] and "\n" not in answer["message"]
        return
    n = answer["rows"]
    assert n == TICKS or answer["damage"], answer["damage"]
    for name in ("tick", "time", "real_time"):
        np.testing.assert_array_equal(answer[name], whole[name].values[:n])
    np.testing.assert_array_equal(answer["grid"],
                                  whole["Grid.OUTPUT"].values.reshape(TICKS, -1)[:n])
    assert answer["model"] == whole.attrs["model"]
    assert answer["parameters"] == whole.attrs["parameters"]


def test_a_recording_cut_short_is_refused_at_once_naming_the_file_and_the_damage(
        recording, tmp_path):
    source, whole = recording
    size = source.stat().st_size
    sizes = [100, 1024, 4096, 16384] + [size * p // 100 for p in (10, 30, 50, 80)]
    paths = [damaged(tmp_path, source, f"cut{n}.h5", n) for n in sizes]
    answers = open_in_child(paths)
    for path, n, answer in zip(paths, sizes, answers):
        said = answer.get("message") or answer["damage"]       # refused, or read in part
        assert said.startswith(f"the recording {path} is cut off: the file has {n} of the "
                               f"{size} bytes it says it holds;"), said
        assert_refused_or_true(path, answer, whole)
    assert all("error" in answer for answer in answers[:6])


def test_a_recording_whose_end_is_cut_off_reads_up_to_its_last_whole_chunk_and_says_so(
        recording, tmp_path):
    source, whole = recording
    with h5py.File(source, "r") as f:        # the end of each dataset's second chunk
        ends = [info.byte_offset + info.size
                for name in ("data", "tick", "time", "real_time")
                for info in [f[name].id.get_chunk_info(1)]]
        rows = f["tick"].chunks[0] * 2
    path = damaged(tmp_path, source, "end.h5", max(ends))
    answer, = open_in_child([path])
    assert answer["rows"] == rows
    assert answer["damage"] == (
        f"the recording {path} is cut off: the file has {max(ends)} of the "
        f"{source.stat().st_size} bytes it says it holds; only its first {rows} of "
        f"{TICKS} rows are read")
    assert_refused_or_true(path, answer, whole)
    with pytest.warns(RecordingWarning, match="only its first 32768 of 40000 rows"):
        assert open_recording(str(path)).sizes["tick"] == rows


def test_256_bytes_overwritten_anywhere_are_found_or_change_nothing(recording, tmp_path):
    source, whole = recording
    with h5py.File(source, "r") as f:
        places = {name: f[name].id.get_chunk_info(0).byte_offset
                  for name in ("data", "tick", "time", "real_time", "header", "model")}
        places["stored"] = f["stored"].id.get_offset()
    size = source.stat().st_size
    places.update({"superblock": 0, "root": 48, "middle": size // 2,
                   "tick-middle": places["tick"] + 60000, "last": size - 300})
    rng = np.random.default_rng(7)
    paths = []
    for name, at in places.items():
        for kind, patch in (("zeros", bytes(256)),
                            ("noise", rng.integers(0, 256, 256, np.uint8).tobytes())):
            paths.append(damaged(tmp_path, source, f"{name}-{kind}.h5",
                                 overwrite=(at, patch)))
    answers = open_in_child(paths)
    for path, answer in zip(paths, answers):
        assert_refused_or_true(path, answer, whole)
    refused = {p.name for p, a in zip(paths, answers) if "error" in a}
    # the values and texts have checksums: damage to them is always found
    for name in ("data", "tick", "time", "real_time", "header", "model", "stored",
                 "tick-middle", "middle"):
        assert {f"{name}-zeros.h5", f"{name}-noise.h5"} <= refused, name


def test_replay_and_the_replay_command_refuse_a_damaged_recording_in_one_line(
        recording, tmp_path):
    source, _ = recording
    for n in (48, 100, 16384):
        path = damaged(tmp_path, source, f"cut{n}.h5", n)
        model = tmp_path / "replay.ikg"
        model.write_text(f'<group name="R"><module class="Replay" name="R" '
                         f'filename="{path}" signal="Counter.OUTPUT"/></group>\n')
        for args in (["-b", "-s", "10", str(model)], ["--replay", str(path), "-w", "0"]):
            done = subprocess.run([sys.executable, "-m", "ikaros", *args], env=ENV,
                                  capture_output=True, text=True, timeout=120)
            assert done.returncode == 1, done.stderr
            lines = done.stderr.splitlines()
            assert len(lines) == 1 and "Traceback" not in done.stderr, done.stderr
            assert f"the recording {path} is cut off: the file has {n} of the" in lines[0]


def test_a_replay_of_a_recording_cut_at_its_end_plays_its_whole_chunks_and_warns_once(
        recording, tmp_path):
    source, whole = recording
    with h5py.File(source, "r") as f:
        end = max(f[name].id.get_chunk_info(1).byte_offset + f[name].id.get_chunk_info(1).size
                  for name in ("data", "tick", "time", "real_time"))
    path = damaged(tmp_path, source, "end.h5", end)
    net = load_body(tmp_path, f'<module class="Replay" name="A" filename="{path}" '
                              f'signal="Counter.OUTPUT"/>'
                              f'<module class="Replay" name="B" filename="{path}" '
                              f'module="Grid"/>')
    net.log_level = -1
    played = net.run(ticks=TICKS, record="A.OUTPUT")["A.OUTPUT"].values
    np.testing.assert_array_equal(played[:, 0], whole["Counter.OUTPUT"].values[:32768, 0])
    # a load-time warning: once, at the line of the module that opened the file first
    warned = [m for _, _, _, m in net.log if "cut off" in m]
    assert warned == [f'{tmp_path / "model.ikg"}:2: <module name="A">: the recording {path} '
                      f"is cut off: the file has {end} of the {source.stat().st_size} bytes "
                      f"it says it holds; only its first 32768 of {TICKS} rows are read"]
    net.close()


# --- recordings of format 2 (before checksums) -------------------------------------------

def write_format_2(path, ticks: int) -> None:
    """A recording as format 2 wrote it: text in variable-length string attributes."""
    with h5py.File(path, "w", libver="latest") as f:
        f.attrs.update({
            "format": "ikaros-recording", "format_version": 2, "ikaros_version": "0",
            "model_file": "m.ikg", "top_group": "Test", "command_line": '["ikaros"]',
            "created": "2026-11-01T00:00:00+00:00", "every": 1, "tick_duration": 0.01,
            "first_tick": 0, "signals": '[["Counter.OUTPUT", [1], 0, 1]]',
            "parameters": '{"Counter.step": "1"}', "seeds": "{}", "finished": True,
            "ticks_recorded": ticks})
        f.create_dataset("model", data='<group name="Test"/>')
        k = np.arange(ticks)
        f.create_dataset("data", data=(k + 1.0).astype("<f4").reshape(-1, 1),
                         maxshape=(None, 1), chunks=(1024, 1), compression="gzip")
        for name, values in (("tick", k), ("time", k * 0.01), ("real_time", k * 0.001)):
            f.create_dataset(name, data=values, maxshape=(None,), chunks=(1024,))
        f.create_dataset("parameter_changes", (0,), maxshape=(None,), chunks=(16,),
                         dtype=[("tick", "<i8"), ("path", "S256"), ("value", "S4096")])
        f.create_dataset("stored", data=np.array([ticks], np.int64))


def test_a_recording_of_format_2_still_reads_and_its_damage_is_found(tmp_path):
    path = tmp_path / "old.h5"
    write_format_2(path, 3000)
    ds = open_recording(str(path))
    np.testing.assert_array_equal(ds["tick"].values, np.arange(3000))
    np.testing.assert_array_equal(ds["Counter.OUTPUT"].values[:, 0], np.arange(1, 3001))
    assert ds.attrs["model"] == '<group name="Test"/>' and ds.attrs["finished"] is True
    with h5py.File(path, "r") as f:
        heap = path.read_bytes().index(b"GCOL")
        ticks = f["tick"].id.get_chunk_info(1).byte_offset
    paths = [damaged(tmp_path, path, "heap.h5", overwrite=(heap + 128, bytes(256))),
             damaged(tmp_path, path, "ticks.h5", overwrite=(ticks + 800, bytes(256)))]
    heap_answer, ticks_answer = open_in_child(paths)
    assert heap_answer["error"] == "RecordingError"
    assert heap_answer["message"].startswith(f"the recording {paths[0]} is damaged: its "
                                             f"global heap at byte {heap} has an object of "
                                             f"a wrong size at byte "), heap_answer
    assert ticks_answer["error"] == "RecordingError"
    assert ticks_answer["message"] == (
        f"the recording {paths[1]} is damaged: the time of its row 1124 is not its tick "
        f"times tick_duration")


def test_a_file_that_is_not_a_recording_is_named(tmp_path):
    path = tmp_path / "other.h5"
    with h5py.File(path, "w") as f:
        f["x"] = [1, 2, 3]
    with pytest.raises(ValueError, match=f"{path} is not an ikaros recording"):
        open_recording(str(path))
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # a whole file: no warning
        (tmp_path / "empty.h5").write_bytes(b"")
        with pytest.raises(OSError, match=f"cannot read the recording {tmp_path}/empty.h5"):
            open_recording(str(tmp_path / "empty.h5"))
