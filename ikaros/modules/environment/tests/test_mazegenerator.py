"""Tests of the MazeGenerator module: perfect mazes are spanning trees of the rooms, the seed
fixes the maze, regeneration happens on schedule, and the L- and T-mazes are as drawn."""
import collections
import ctypes
import subprocess
import sys

import numpy as np
import pytest

from ikaros import ModelError
from ikaros.testing import load_body as load


def rooms_reached(maze):
    """Breadth-first search over floor cells from (1, 1)."""
    seen = {(1, 1)}
    queue = collections.deque(seen)
    while queue:
        y, x = queue.popleft()
        for dy, dx in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            n = (y + dy, x + dx)
            if maze[n] == 0 and n not in seen:
                seen.add(n)
                queue.append(n)
    return seen


def test_perfect_maze_is_a_spanning_tree(tmp_path):
    for size, seed in ((1, 1), (4, 7), (8, 3)):
        net = load(tmp_path, f'<module class="MazeGenerator" name="M" size="{size}" '
                             f'seed="{seed}"/>')
        try:
            maze = net.output("M.OUTPUT")
            n = 2 * size + 1
            assert maze.shape == (n, n) and set(np.unique(maze)) <= {0, 1}
            assert np.all(maze[0] == 1) and np.all(maze[-1] == 1)
            assert np.all(maze[:, 0] == 1) and np.all(maze[:, -1] == 1)
            assert np.all(maze[1::2, 1::2] == 0)            # every room is floor
            assert np.all(maze[0::2, 0::2] == 1)            # every pillar is wall
            # a tree over size^2 rooms has size^2 - 1 open doors, and reaches every room
            doors = (maze[1::2, 2:-1:2] == 0).sum() + (maze[2:-1:2, 1::2] == 0).sum()
            assert doors == size * size - 1
            assert len(rooms_reached(maze)) == (maze == 0).sum() == size * size + doors
        finally:
            net.close()


def test_the_seed_fixes_the_maze(tmp_path):
    mazes = []
    for seed in (5, 5, 6):
        net = load(tmp_path, f'<module class="MazeGenerator" name="M" size="6" seed="{seed}"/>')
        mazes.append(net.output("M.OUTPUT"))
        net.close()
    assert np.array_equal(mazes[0], mazes[1])
    assert not np.array_equal(mazes[0], mazes[2])


def test_regenerate_every_n_ticks(tmp_path):
    net = load(tmp_path, '<module class="MazeGenerator" name="M" size="6" seed="2" '
                         'regenerate="3"/>')
    try:
        outputs = [net.output("M.OUTPUT")]
        for _ in range(7):
            net.step()
            outputs.append(net.output("M.OUTPUT"))
        # init, ticks 0-2 share a maze; new ones on ticks 3 and 6
        same = [np.array_equal(outputs[i], outputs[i + 1]) for i in range(7)]
        assert same == [True, True, True, False, True, True, False]
        net.command("M", "regenerate")
        assert not np.array_equal(net.output("M.OUTPUT"), outputs[-1])
    finally:
        net.close()


def test_no_regeneration_by_default(tmp_path):
    net = load(tmp_path, '<module class="MazeGenerator" name="M" size="3" seed="4"/>')
    try:
        first = net.output("M.OUTPUT")
        net.run(ticks=5)
        assert np.array_equal(net.output("M.OUTPUT"), first)
    finally:
        net.close()


def test_l_and_t_mazes(tmp_path):
    net = load(tmp_path, '<module class="MazeGenerator" name="L" size="2" type="l-maze"/>'
                         '<module class="MazeGenerator" name="T" size="2" type="t-maze"/>')
    try:
        assert np.array_equal(net.output("L.OUTPUT"), [[1, 1, 1, 1, 1],
                                                        [1, 0, 1, 1, 1],
                                                        [1, 0, 1, 1, 1],
                                                        [1, 0, 0, 0, 1],
                                                        [1, 1, 1, 1, 1]])
        assert np.array_equal(net.output("T.OUTPUT"), [[1, 1, 1, 1, 1],
                                                        [1, 0, 0, 0, 1],
                                                        [1, 1, 1, 0, 1],
                                                        [1, 1, 1, 0, 1],
                                                        [1, 1, 1, 1, 1]])
    finally:
        net.close()
    net = load(tmp_path, '<module class="MazeGenerator" name="T" size="3" type="t-maze"/>')
    try:
        t = net.output("T.OUTPUT")
        expected = np.ones((7, 7))
        expected[1, 1:6] = 0                 # the cross bar along the top room row
        expected[1:6, 3] = 0                 # the stem up the middle room column
        assert np.array_equal(t, expected)
    finally:
        net.close()


def glibc_rand_stream(seed):
    """The C library's rand() after srand(seed), from the library itself (Linux: glibc, the
    generator Ikaros 2 ran with for the golden files)."""
    libc = ctypes.CDLL(None)
    libc.srand(seed)
    return libc.rand


def depth_first_maze(size, rand):
    """Ikaros 2's perfect maze as its golden file shows it, written out on its own: start in
    room rand() % size² (x = s % size, y = s / size); each room entered draws k = rand() % 4
    and tries left, right, up, down from the k-th in turn, entering each unvisited one."""
    maze = np.ones((2 * size + 1, 2 * size + 1))
    seen = set()

    def visit(x, y):
        seen.add((x, y))
        maze[2 * y + 1, 2 * x + 1] = 0
        k = rand() % 4
        for i in range(4):
            dx, dy = ((-1, 0), (1, 0), (0, -1), (0, 1))[(k + i) % 4]
            if 0 <= x + dx < size and 0 <= y + dy < size and (x + dx, y + dy) not in seen:
                maze[2 * y + 1 + dy, 2 * x + 1 + dx] = 0
                visit(x + dx, y + dy)

    start = rand() % (size * size)
    visit(start % size, start // size)
    return maze


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="needs glibc's rand()")
def test_the_seed_draws_as_srand_does(tmp_path):
    for size, seed in ((8, 1), (5, 2), (11, 12345)):
        net = load(tmp_path, f'<module class="MazeGenerator" name="M" size="{size}" '
                             f'seed="{seed}"/>')
        try:
            assert np.array_equal(net.output("M.OUTPUT"),
                                  depth_first_maze(size, glibc_rand_stream(seed)))
        finally:
            net.close()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="needs glibc's rand()")
def test_unseeded_mazes_share_the_networks_rand_stream(tmp_path):
    # Ikaros 2 never seeds rand(): the first maze is srand(1)'s, the second goes on drawing
    rand = glibc_rand_stream(1)
    first, second = depth_first_maze(4, rand), depth_first_maze(4, rand)
    net = load(tmp_path, '<module class="MazeGenerator" name="A" size="4"/>'
                         '<module class="MazeGenerator" name="B" size="4"/>')
    try:
        assert np.array_equal(net.output("A.OUTPUT"), first)
        assert np.array_equal(net.output("B.OUTPUT"), second)
        assert not np.array_equal(first, second)
    finally:
        net.close()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="needs glibc's rand()")
def test_the_top_groups_random_seed_is_srand_of_the_shared_stream(tmp_path):
    # Ikaros 2's -z (KERNEL.md, the v2 options): the seed of the one rand() stream
    expected = depth_first_maze(5, glibc_rand_stream(9))
    assert not np.array_equal(expected, depth_first_maze(5, glibc_rand_stream(1)))
    net = load(tmp_path, '<module class="MazeGenerator" name="M" size="5"/>', random_seed=9)
    try:
        assert np.array_equal(net.output("M.OUTPUT"), expected)
    finally:
        net.close()
    model = tmp_path / "seeded.ikg"
    model.write_text('<group name="T"><module class="MazeGenerator" name="M" size="5"/>'
                     '<module class="Print" name="P"/>'
                     '<connection source="M.OUTPUT" target="P.INPUT"/></group>')
    done = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-s", "1", "-z", "9",
                           str(model)], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    printed = done.stdout.strip().splitlines()[-1].removeprefix("P: ")
    rows = [[float(v) for v in row.split()] for row in printed.split(";")]
    assert np.array_equal(np.array(rows), expected)


@pytest.mark.parametrize("text", ["-3", "1.5", "seven", "4294967296"])
def test_a_random_seed_that_is_not_a_whole_number_fails_the_build(tmp_path, text):
    with pytest.raises(ModelError, match=f'random_seed="{text}" must be a whole number'):
        load(tmp_path, '<module class="Constant" name="C" data="1"/>', random_seed=text)
