"""Tests of MemorySequencer."""
import numpy as np

from ikaros.testing import load_body as load


def run(tmp_path, rows):
    n = len(rows[0])
    (tmp_path / "x.txt").write_text(f"X/{n}\n" + "\n".join(" ".join(map(str, r)) for r in rows)
                                    + "\n")
    net = load(tmp_path, '<module class="InputFile" name="X" filename="x.txt"/>'
               '<module class="MemorySequencer" name="M"/>'
               '<connection source="X.X" target="M.INPUT" delay="0"/>')
    try:
        out = []
        for _ in rows:
            net.step()
            o = net.output("M.OUTPUT")
            assert o.shape == (80,) and o.sum() <= 1
            out.append(int(np.argmax(o)) if o.any() else None)
        return out
    finally:
        net.close()


def test_replays_and_restarts(tmp_path):
    rows = [[0, 0, 0]] * 2 + [[0, 1, 0]] * 23 + [[0, 0, 1]] * 3 + [[0.5, 0, 0]] * 2
    got = run(tmp_path, rows)
    assert got[:2] == [None, None]                     # no change yet: nothing
    assert got[2:12] == list(range(10, 20))            # pattern 1: positions 10..19
    assert got[12:22] == list(range(10, 20))           # and again
    assert got[22:25] == [10, 11, 12]
    assert got[25:28] == [20, 21, 22]                  # a change restarts at once
    assert got[28:30] == [0, 1]


def test_patterns_past_the_output_are_not_shown(tmp_path):
    rows = [[0] * 8 + [1]] * 3 + [[0] * 7 + [1, 0]] * 2
    got = run(tmp_path, rows)
    assert got == [None, None, None, 70, 71]
