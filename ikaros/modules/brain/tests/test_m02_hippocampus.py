"""Tests of M02_Hippocampus: bindings, novelty resets and contexts, worked by hand."""
import numpy as np
import pytest

import ikaros

from ikaros.testing import load_body as load


def run(tmp_path, rows, extra=""):
    (tmp_path / "x.txt").write_text("S/2 L/2\n" + "\n".join(
        " ".join(map(str, r)) for r in rows) + "\n")
    net = load(tmp_path, '<module class="InputFile" name="X" filename="x.txt"/>'
               f'<module class="M02_Hippocampus" name="H" {extra}/>'
               '<connection source="X.S" target="H.STIMULUS" delay="0"/>'
               '<connection source="X.L" target="H.LOCATION" delay="0"/>')
    out = []
    try:
        for _ in rows:
            net.step()
            out.append({k: net.output(f"H.{k}").copy()
                        for k in ("BIND", "BIND_DELTA", "CONTEXT", "RESET")})
        return out
    finally:
        net.close()


ROWS = [[1, 0, 1, 0],    # CS at place 0: binding 0 (new), context 0
        [1, 0, 1, 0],    # same: no change
        [0, 0, 1, 0],    # CS missing where it was expected: reset, binding 1, context 1
        [1, 0, 1, 0],    # binding 0, no novelty in context 1: context 1 takes binding 0
        [0, 0, 0, 0],    # no input: BIND 0, no reset
        [0, 1, 0, 1],    # another stimulus at place 1: binding 2, nothing expected there
        [1, 0, 1, 0]]    # binding 0 again


def test_bindings_contexts_and_resets(tmp_path):
    out = run(tmp_path, ROWS, 'bind="current"')
    binds = [int(np.argmax(o["BIND"])) if o["BIND"].any() else None for o in out]
    assert binds == [0, 0, 1, 0, None, 2, 0]
    assert all(o["BIND"].sum() == (1 if b is not None else 0) for o, b in zip(out, binds))
    assert [o["RESET"][0] for o in out] == [0, 0, 1, 0, 0, 0, 0]
    # a context keeps a binding it takes (golden-v2 M02_Hippocampus "varying")
    assert [int(np.argmax(o["CONTEXT"])) for o in out] == [0, 0, 1, 1, 1, 1, 1]
    assert all(o["CONTEXT"].sum() == 1 for o in out)
    assert [o["BIND_DELTA"].tolist() for o in out][:4] == [
        [1, 0, 0, 0], [0, 0, 0, 0], [0, 1, 0, 0], [1, 0, 0, 0]]
    assert out[4]["BIND_DELTA"].sum() == 0 and out[5]["BIND_DELTA"].tolist() == [0, 0, 1, 0]


def test_bind_shows_every_binding_of_the_context_by_default(tmp_path):
    out = run(tmp_path, ROWS)
    assert [o["BIND"].tolist() for o in out] == [
        [1, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0], [0, 0, 0, 0],
        [1, 1, 1, 0], [1, 1, 1, 0]]
    assert [o["BIND_DELTA"].tolist() for o in out] == [
        [1, 0, 0, 0], [0, 0, 0, 0], [0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0],
        [1, 1, 1, 0], [0, 0, 0, 0]]


def test_too_few_contexts_is_a_fatal_error(tmp_path):
    # each tick an expected stimulus is missing and the pattern is a new binding, so each
    # needs a new context: the second new one does not fit in contextsize 2
    rows = [[1, 1, 1, 0], [1, 0, 1, 0], [0, 0, 1, 0], [0, 0, 1, 0]]
    (tmp_path / "x.txt").write_text("S/2 L/2\n" + "\n".join(
        " ".join(map(str, r)) for r in rows) + "\n")
    net = load(tmp_path, '<module class="InputFile" name="X" filename="x.txt"/>'
               '<module class="M02_Hippocampus" name="H" contextsize="2"/>'
               '<connection source="X.S" target="H.STIMULUS" delay="0"/>'
               '<connection source="X.L" target="H.LOCATION" delay="0"/>')
    try:
        net.step()
        net.step()
        assert net.output("H.RESET")[0] == 1 and net.output("H.CONTEXT").tolist() == [0, 1]
        with pytest.raises(ikaros.RunError, match="context"):
            net.run(ticks=3)
    finally:
        net.close()
