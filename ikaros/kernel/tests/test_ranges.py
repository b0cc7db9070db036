"""Parameter values: finite unless the class says otherwise, within a declared range; at
build and when set while running; and the limits given to ikaros.load."""
from __future__ import annotations

import math

import numpy as np
import pytest

import ikaros
from ikaros.limits import Limits, LimitError, parse_bytes

GAINS = '''"""A module with a range, an open-ended range, an array range and a non-finite value."""
from ikaros.module import Module, Output, Parameter


class Gains(Module):
    """Parameters with declared ranges."""
    p = Parameter(0.5, "a probability", range=(0, 1))
    n = Parameter(1, "a count", type="int", range=(1, None))
    w = Parameter("0 0", "weights", type="array", range=(-1, 1))
    x = Parameter(0.0, "anything, nan and inf too", finite=False)
    OUTPUT = Output("nothing", size_x="1")
'''


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "Gains.py").write_text(GAINS)
    return tmp_path


def _load(folder, attrs="", **kw):
    (folder / "m.ikg").write_text(f'<group name="M"><module class="Gains" name="G" {attrs}/>'
                                  f'</group>')
    return ikaros.load(str(folder / "m.ikg"), **kw)


@pytest.mark.parametrize("attrs, reason", [
    ('p="1.5"', 'parameter "p" of G: 1.5 is above maximum 1'),
    ('p="-0.25"', 'parameter "p" of G: -0.25 is below minimum 0'),
    ('n="0"', 'parameter "n" of G: 0 is below minimum 1'),
    ('w="0.5 2"', 'parameter "w" of G: 2 is above maximum 1'),
    ('w="0.5 nan"', 'parameter "w" of G: nan is not a finite number'),
    ('p="nan"', 'parameter "p" of G: nan is not a finite number'),
    ('p="1e400"', 'parameter "p" of G: inf is not a finite number'),
])
def test_values_outside_their_range_are_build_errors(folder, attrs, reason):
    with pytest.raises(ikaros.ModelError) as e:
        _load(folder, attrs)
    assert str(e.value) == f'{folder}/m.ikg:1: <module name="G">: {reason}'


def test_the_ends_of_a_range_and_declared_non_finite_values_are_taken(folder):
    net = _load(folder, 'p="1" n="1000000" w="-1 1" x="nan"')
    try:
        assert net.parameter("G.p") == 1
        assert math.isnan(net.parameter("G.x"))
        net.set_parameter("G.x", "-inf")
        assert net.parameter("G.x") == -math.inf
    finally:
        net.close()


def test_values_set_while_running_are_checked_and_change_nothing(folder):
    net = _load(folder)
    try:
        for path, value, reason in [("G.p", 2, "2 is above maximum 1"),
                                    ("G.p", "nan", "nan is not a finite number"),
                                    ("G.n", 0, "0 is below minimum 1"),
                                    ("G.w", [0, -3], "-3 is below minimum -1")]:
            with pytest.raises(ValueError) as e:
                net.set_parameter(path, value)
            assert str(e.value) == f'bad value for parameter "{path}": {reason}'
        assert net.parameter("G.p") == 0.5 and net.parameter("G.n") == 1
        assert np.array_equal(net.parameter("G.w"), [0, 0])
    finally:
        net.close()


def test_a_standard_class_declares_its_range():
    desc = ikaros.classes()["FunctionGenerator"]
    assert desc.parameter("duty").range == (0, 1)
    assert "  duty (number, default 0.5, range 0..1): " in desc.to_text()
    # a filter constant of Ikaros 3's PIDController is a rate (1/s): no upper bound
    assert ikaros.classes()["PIDController"].parameter("Fs").range == (0, None)
    assert ikaros.classes()["Histogram"].parameter("size").range == (1, None)


def test_max_memory_of_load(folder):
    (folder / "big.ikg").write_text('<group name="B"><module class="Constant" name="C" '
                                    'outputsize="1000000"/></group>')
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(folder / "big.ikg"), max_memory="1M")
    assert str(e.value).endswith("size of output \"OUTPUT\": a buffer of size 1000000: "
                                 "3.8 MB is more than the memory limit of 1.0 MB (set with "
                                 "--max-memory or max_memory=)")
    net = ikaros.load(str(folder / "big.ikg"), max_memory=8 << 20)
    net.close()
    with pytest.raises(ikaros.ModelError, match='max_memory: "lots" is not an amount'):
        ikaros.load(str(folder / "big.ikg"), max_memory="lots")


def test_a_file_larger_than_the_limit_is_not_read(tmp_path):
    from ikaros.language.reader import read_file
    from ikaros.limits import applied
    path = tmp_path / "big.ikg"
    path.write_text("<group>" + " " * 2000 + "</group>")
    with applied(Limits(max_file_size=1000)):
        with pytest.raises(ikaros.ModelError) as e:
            read_file(str(path))
    assert str(e.value) == f"{path}: the file is larger than the limit of 1000 bytes"
    assert read_file(str(path)).tag == "group"


def test_parse_bytes():
    assert [parse_bytes(t) for t in ("512", "2K", "1.5M", "2G", "1t", "3GiB")] == \
        [512, 2048, 1572864, 2 << 30, 1 << 40, 3 << 30]
    for bad in ("", "x", "-1", "0", "1Q"):
        with pytest.raises(LimitError):
            parse_bytes(bad)
    assert Limits().with_memory("1G").max_memory == 1 << 30


def test_a_model_of_more_modules_than_the_memory_limit_can_build_is_refused_first(folder):
    """Building a module takes about 6 KB besides its buffers (10^6 modules took 5.4 GB):
    a model of more than the memory limit can build is refused before any is built."""
    (folder / "Unbuilt.py").write_text(
        "from ikaros.module import Module\n\n\nclass Unbuilt(Module):\n"
        "    def configure(self):\n        raise RuntimeError('built')\n")
    modules = "".join(f'<module class="Unbuilt" name="U{k}"/>' for k in range(3000))
    (folder / "many.ikg").write_text(f'<group name="M">{modules}</group>')
    with pytest.raises(ikaros.ModelError) as e:
        ikaros.load(str(folder / "many.ikg"), max_memory="16M")
    assert str(e.value) == (f'{folder / "many.ikg"}:1: <group name="M">: the model has 3000 '
                            f'modules; the memory limit of 16.0 MB can build at most 2730 '
                            f'(about 6.0 KB each; set with --max-memory or max_memory=)')
    # group files used as classes add theirs while the model is built
    block = "".join(f'<module class="Unbuilt" name="U{k}"/>' for k in range(1000))
    (folder / "Block.ikg").write_text(f'<group name="Block">{block}</group>')
    (folder / "blocks.ikg").write_text('<group name="M">' + "".join(
        f'<module class="Block" name="B{k}"/>' for k in range(3)) + "</group>")
    with pytest.raises(ikaros.ModelError, match="the model has more than 2730 modules; "
                                               "the memory limit of 16.0 MB can build at "
                                               "most 2730"):
        ikaros.load(str(folder / "blocks.ikg"), max_memory="16M")
