"""Tests of EyeModel's pupil dynamics."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def run(tmp_path, rows, params="", gaze=None):
    (tmp_path / "x.txt").write_text("S/1 D/1\n" + "\n".join(f"{s} {d}" for s, d in rows) + "\n")
    body = ('<module class="InputFile" name="X" filename="x.txt"/>'
            f'<module class="EyeModel" name="E" {params}/>'
            '<connection source="X.S" target="E.PUPIL_SPHINCTER" delay="0"/>'
            '<connection source="X.D" target="E.PUPIL_DILATOR" delay="0"/>')
    if gaze:
        body += (f'<module class="Constant" name="G" data="{gaze}"/>'
                 '<connection source="G.OUTPUT" target="E.GAZE" delay="0"/>')
    net = load(tmp_path, body)
    try:
        assert net.output("E.PUPIL_DIAMETER")[0] == pytest.approx(2.0 if not params else
                                                                   net.output("E.PUPIL_DIAMETER")[0])
        out = []
        for _ in rows:
            net.step()
            out.append((float(net.output("E.PUPIL_DIAMETER")[0]), net.output("E.OUTPUT").copy()))
        return out
    finally:
        net.close()


def reference(rows, lo=2.0, hi=8.0, eps=0.5, m3=1.0, a1=1.0, amp=1.0):
    d, out = lo, []
    for s, dil in rows:
        target = lo + (hi - lo) * min(max(amp * (a1 * dil - m3 * s), 0), 1)
        d += eps * (target - d)
        out.append(d)
    return out


ROWS = [(0, 1), (0, 1), (0, 1), (0, 0.5), (1, 0.5), (0.2, 0.7), (0, 3), (0.5, 0), (0, 0.25)]


def test_dilates_and_constricts(tmp_path):
    got = run(tmp_path, ROWS, gaze="0.3 -0.4")
    expected = reference(ROWS)
    assert [g for g, _ in got] == pytest.approx(expected, abs=1e-5)
    # hand-worked: full dilation from 2 moves half way to 8 each tick: 5, 6.5, 7.25
    assert [g for g, _ in got[:3]] == pytest.approx([5, 6.5, 7.25])
    assert all(2 <= g <= 8 for g, _ in got)
    assert np.allclose(got[-1][1], [0.3, -0.4, 0.1 * got[-1][0]])


def test_receptor_gains(tmp_path):
    params = 'm3="2" alpha1a="0.5" amplifier="4" epsilon="1" pupil_min="3" pupil_max="7"'
    got = run(tmp_path, ROWS, params)
    expected = reference(ROWS, 3, 7, 1.0, 2.0, 0.5, 4.0)
    assert [g for g, _ in got] == pytest.approx(expected, abs=1e-5)


def test_gaze_unconnected_is_zero(tmp_path):
    got = run(tmp_path, ROWS[:2])
    assert np.allclose(got[-1][1][:2], 0)
