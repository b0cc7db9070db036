"""Tests of the FanIn module."""
import numpy as np
import pytest

import ikaros
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def _fan_in(inputs, cx, cy):
    """Independent reference: element (j, i) of input k goes to row j*cy + k//cx,
    column i*cx + k%cx."""
    rows, cols = inputs[0].shape
    out = np.zeros((rows * cy, cols * cx))
    for k, m in enumerate(inputs[:cx * cy]):
        for j in range(rows):
            for i in range(cols):
                out[j * cy + k // cx, i * cx + k % cx] = m[j, i]
    return out


def _body(mats, cx, cy, n=None):
    n = len(mats) if n is None else n
    lines = [f'<module class="FanIn" name="F" inputs="{n}" cell_size_x="{cx}" '
             f'cell_size_y="{cy}"/>']
    for k, m in enumerate(mats, 1):
        data = "; ".join(" ".join(f"{v:g}" for v in row) for row in np.atleast_2d(m))
        lines.append(f'<module class="Constant" name="C{k}" data="{data}"/>')
        lines.append(f'<connection source="C{k}.OUTPUT" target="F.INPUT{k}" delay="0"/>')
    return "\n".join(lines)


@pytest.mark.parametrize("cx, cy", [(2, 2), (2, 1), (1, 2), (3, 2)])
def test_interleaves_like_the_reference(tmp_path, cx, cy):
    rng = np.random.default_rng(cx * 10 + cy)
    mats = [np.round(rng.uniform(-5, 5, (2, 3)), 2) for _ in range(cx * cy)]
    net = load(tmp_path, _body(mats, cx, cy))
    try:
        net.run(ticks=2)
        out = net.output("F.OUTPUT")
        assert out.shape == (2 * cy, 3 * cx)
        assert np.allclose(out, _fan_in(mats, cx, cy))
    finally:
        net.close()


def test_four_channels_in_2x2_cells(tmp_path):
    mats = [np.array([[1, 2]]) * (10 ** k) for k in range(4)]
    net = load(tmp_path, _body(mats, 2, 2))
    try:
        net.step()
        assert np.array_equal(net.output("F.OUTPUT"), [[1, 10, 2, 20], [100, 1000, 200, 2000]])
    finally:
        net.close()


def test_fewer_inputs_leave_zeros_and_extra_inputs_are_ignored(tmp_path):
    mats = [np.array([[1.0]]), np.array([[2.0]]), np.array([[3.0]])]
    net = load(tmp_path, _body(mats, 2, 2))
    try:
        net.step()
        assert np.array_equal(net.output("F.OUTPUT"), [[1, 2], [3, 0]])
    finally:
        net.close()
    (tmp_path / "b").mkdir()
    net = load(tmp_path / "b", _body(mats, 2, 1))
    try:
        net.step()
        assert np.array_equal(net.output("F.OUTPUT"), [[1, 2]])
        assert any(e[1] == WARNING and "ignored" in e[3] for e in net.log)
    finally:
        net.close()


def test_follows_changing_inputs(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="0" max="100" step="1" outputsize="2"/>\n'
               '<module class="Constant" name="C" data="-1 -2"/>\n'
               '<module class="FanIn" name="F" inputs="2" cell_size_x="1" cell_size_y="2"/>\n'
               '<connection source="S.OUTPUT" target="F.INPUT1" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="F.INPUT2" delay="0"/>')
    try:
        for tick in range(3):
            net.step()
            assert np.array_equal(net.output("F.OUTPUT"), [[tick + 1, tick + 1], [-1, -2]])
    finally:
        net.close()


def test_inputs_of_different_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="same size"):
        load(tmp_path, _body([np.ones((1, 2)), np.ones((1, 3))], 2, 1))
