"""Tests of EyeModel's pupil dynamics, against the formula worked by hand and the golden
files of Ikaros 2 (golden-v2 EyeModel)."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


def run(tmp_path, rows, params="", gaze=None):
    (tmp_path / "x.txt").write_text("S/2 D/2\n" + "\n".join(f"{s} 9 {d} 9" for s, d in rows)
                                    + "\n")
    body = ('<module class="InputFile" name="X" filename="x.txt"/>'
            f'<module class="EyeModel" name="E" {params}/>'
            '<connection source="X.S" target="E.PUPIL_SPHINCTER" delay="0"/>'
            '<connection source="X.D" target="E.PUPIL_DILATOR" delay="0"/>')
    if gaze:
        body += (f'<module class="Constant" name="G" data="{gaze}"/>'
                 '<connection source="G.OUTPUT" target="E.GAZE" delay="0"/>')
    net = load(tmp_path, body)
    try:
        out = [(float(net.output("E.PUPIL_DIAMETER")[0]), net.output("E.OUTPUT").copy())]
        for _ in rows:
            net.step()
            out.append((float(net.output("E.PUPIL_DIAMETER")[0]), net.output("E.OUTPUT").copy()))
        return out
    finally:
        net.close()


def reference(rows, lo=2.0, hi=8.0, eps=0.5, m3=1.0, a1=1.0, amp=1.0, start=0.0):
    d, out = start, [start]
    for s, dil in rows:
        target = lo + (hi - lo) * min(max(amp * (a1 * dil - m3 * s), 0), 1)
        d += eps * (target - d)
        out.append(d)
    return out


ROWS = [(0, 1), (0, 1), (0, 1), (0, 0.5), (1, 0.5), (0.2, 0.7), (0, 3), (0.5, 0), (0, 0.25)]


def test_dilates_and_constricts_from_0(tmp_path):
    """The second element of each input (9) is not used: the first ones drive the pupil."""
    got = run(tmp_path, ROWS, gaze="0.3 -0.4")
    assert [g for g, _ in got] == pytest.approx(reference(ROWS), abs=1e-5)
    # hand-worked: from 0, full dilation moves half way to 8 each tick: 4, 6, 7
    assert [g for g, _ in got[:4]] == pytest.approx([0, 4, 6, 7])
    assert np.allclose(got[-1][1], [0.3, -0.4, got[-1][0]])


def test_receptor_gains_and_start(tmp_path):
    params = ('m3="2" alpha1a="0.5" amplifier="4" epsilon="1" pupil_min="3" pupil_max="7" '
              'start_diameter="3"')
    got = run(tmp_path, ROWS, params)
    assert [g for g, _ in got] == pytest.approx(reference(ROWS, 3, 7, 1.0, 2.0, 0.5, 4.0, 3.0),
                                                abs=1e-5)


def test_golden_defaults_case(tmp_path):
    """golden-v2 EyeModel "defaults": S = 0.2, D = 0.5 give 1.9, 2.85, 3.325 ... 3.796."""
    got = run(tmp_path, [(0.2, 0.5)] * 10)
    assert [g for g, _ in got[1:4]] == pytest.approx([1.9, 2.85, 3.325], abs=1e-6)
    assert got[10][0] == pytest.approx(3.7962892056, abs=1e-6)


def test_gaze_unconnected_is_zero(tmp_path):
    got = run(tmp_path, ROWS[:2])
    assert np.allclose(got[-1][1][:2], 0)
