"""The network's C rand() stream (ikaros/crandom.py) draws GNU libc's numbers. Expected
values: printed by glibc 2.36's rand() itself (srand(seed), then rand() repeatedly)."""
import ctypes
import ctypes.util

import numpy as np
import pytest

from ikaros.crandom import RAND_MAX, CRandom
from ikaros.testing import load_body as load

GLIBC = {1: [1804289383, 846930886, 1681692777, 1714636915, 1957747793, 424238335,
             719885386, 1649760492],
         4: [1968078301, 287724083, 410622274, 558519326],
         123456789: [1965102536, 1639725855, 706684578]}


@pytest.mark.parametrize("seed", sorted(GLIBC))
def test_the_first_numbers_are_glibcs(seed):
    stream = CRandom(seed)
    assert [stream.rand() for _ in GLIBC[seed]] == GLIBC[seed]


def test_unseeded_and_seed_0_are_seed_1_and_numbers_997_to_999():
    assert CRandom(0).rand() == CRandom().rand() == 1804289383
    stream = CRandom()
    numbers = [stream.rand() for _ in range(1000)]
    assert numbers[997:] == [695466127, 745598382, 1143565421]
    assert all(0 <= n <= RAND_MAX for n in numbers)


def test_seed_starts_again_and_uniform_is_rand_over_rand_max():
    stream = CRandom(7)
    stream.rand()
    stream.seed(1)
    assert stream.uniform() == 1804289383 / RAND_MAX


@pytest.mark.skipif(not ctypes.util.find_library("c"), reason="no C library to compare with")
def test_agrees_with_this_machines_glibc_when_it_has_one():
    libc = ctypes.CDLL(ctypes.util.find_library("c"))
    if not hasattr(libc, "gnu_get_libc_version"):
        pytest.skip("the C library is not GNU libc")
    libc.srand(2024)
    expected = [libc.rand() for _ in range(500)]
    stream = CRandom(2024)
    assert [stream.rand() for _ in range(500)] == expected


def test_modules_of_one_network_share_one_stream_and_networks_start_afresh(tmp_path):
    body = ('<module class="PlanarArm" name="A"/>'
            '<module class="PlanarArm" name="B"/>')
    for _ in range(2):
        net = load(tmp_path, body)
        try:
            net.step()
            targets = sorted([tuple(net.output("A.TARGET")), tuple(net.output("B.TARGET"))])
        finally:
            net.close()
        draws = [0.1 + 0.8 * v / RAND_MAX for v in GLIBC[1][:4]]
        expected = sorted([(draws[0], draws[1]), (draws[2], draws[3])])
        assert np.allclose(targets, expected, atol=1e-6)
