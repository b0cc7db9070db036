"""Tests of the Print module."""

from ikaros.testing import load_body as load



def messages(net, name):
    """(tick, message) of what the module called ``name`` printed."""
    return [(tick, message) for tick, _level, where, message in net.log
            if where.split(".")[-1] == name]


def test_prints_every_tick(tmp_path, capfd):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="10" step="0.5" outputsize="2"/>\n'
               '<module class="Print" name="P"/>\n'
               '<connection source="W.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        capfd.readouterr()
        net.run(ticks=3)
        assert messages(net, "P") == [(0, "0.5 0.5"), (1, "1 1"), (2, "1.5 1.5")]
        out = capfd.readouterr().out
        assert "P: 0.5 0.5\n" in out and "P: 1.5 1.5\n" in out
    finally:
        net.close()


def test_interval_format_and_rows(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="10" step="1"/>\n'
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="Print" name="P" interval="2" format="%.2f"/>\n'
               '<module class="Print" name="M"/>\n'
               '<connection source="W.OUTPUT" target="P.INPUT" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="M.INPUT" delay="0"/>')
    try:
        net.run(ticks=5)
        # P prints on ticks 0, 2, 4, when W is 1, 3, 5
        assert messages(net, "P") == [(0, "1.00"), (2, "3.00"), (4, "5.00")]
        assert messages(net, "M") == [(t, "1 2; 3 4") for t in range(5)]
    finally:
        net.close()


def test_unconnected_input_is_allowed_and_prints_nothing(tmp_path):
    """Ikaros 3 interface: INPUT is optional."""
    net = load(tmp_path,
               '<module class="Print" name="P"/>\n'
               '<module class="Constant" name="C" data="7"/>\n'
               '<module class="Print" name="Q"/>\n'
               '<connection source="C.OUTPUT" target="Q.INPUT" delay="0"/>')
    try:
        net.run(ticks=2)
        assert messages(net, "P") == []
        assert messages(net, "Q") == [(0, "7"), (1, "7")]
    finally:
        net.close()
