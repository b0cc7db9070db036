"""Tests of the Constant module's default data in each dialect."""
import numpy as np
import pytest

from ikaros.testing import load_body as load


@pytest.mark.parametrize("dialect, expected", [("2", [0]), ("3", [1, 2, 3, 4, 5, 6])])
def test_default_data_follows_the_files_version(tmp_path, dialect, expected):
    net = load(tmp_path, '<module class="Constant" name="C"/>', dialect=dialect)
    try:
        net.step()
        assert np.array_equal(net.output("C.OUTPUT"), expected)
    finally:
        net.close()


def test_given_data_is_used_in_either_dialect(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="7 8"/>', dialect="3")
    try:
        net.step()
        assert np.array_equal(net.output("C.OUTPUT"), [7, 8])
    finally:
        net.close()
