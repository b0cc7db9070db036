"""Tests of the QLearning module."""
from collections import deque

import numpy as np

from ikaros.testing import load_body

# A test-only grid world, written next to the model so the kernel finds it. It behaves like
# Ikaros's GridWorld in "max" mode: MOVE's largest element picks up/right/down/left, walls (1)
# block, and on entering the goal (2) REWARD is 1 and the agent is put back at the start in
# the same tick.
TINY_GRID = '''
import numpy as np
from ikaros.module import Input, Module, Output, Parameter


class TinyGrid(Module):
    """A grid world for tests: 0 free, 1 wall, 2 goal."""
    world = Parameter("0", "the map", type="matrix")
    start_row = Parameter(1, "start row", type="int")
    start_col = Parameter(1, "start column", type="int")
    MOVE = Input("up, right, down, left")
    LOCATION = Output("one-hot location", shape="world.shape")
    REWARD = Output("1 on reaching the goal", size="1")

    def init(self):
        self._pos = (self.start_row, self.start_col)
        self._draw()

    def _draw(self):
        self.LOCATION[...] = 0
        self.LOCATION[self._pos] = 1

    def tick(self):
        self.REWARD[0] = 0
        if np.any(self.MOVE != 0):
            dr, dc = [(-1, 0), (0, 1), (1, 0), (0, -1)][int(np.argmax(self.MOVE))]
            r, c = self._pos[0] + dr, self._pos[1] + dc
            if self.world[r, c] != 1:
                self._pos = (r, c)
            if self.world[self._pos] == 2:
                self.REWARD[0] = 1
                self._pos = (self.start_row, self.start_col)
        self._draw()
'''

WORLD = np.array([[1, 1, 1, 1, 1, 1, 1],
                  [1, 0, 0, 0, 0, 0, 1],
                  [1, 0, 1, 1, 1, 0, 1],
                  [1, 0, 1, 0, 0, 0, 1],
                  [1, 0, 0, 0, 1, 2, 1],
                  [1, 1, 1, 1, 1, 1, 1]])


def shortest_path(world, start):
    """Breadth-first search: the number of moves from start to the goal."""
    goal = tuple(np.argwhere(world == 2)[0])
    seen, queue = {start: 0}, deque([start])
    while queue:
        r, c = queue.popleft()
        if (r, c) == goal:
            return seen[(r, c)]
        for dr, dc in [(-1, 0), (0, 1), (1, 0), (0, -1)]:
            nxt = (r + dr, c + dc)
            if world[nxt] != 1 and nxt not in seen:
                seen[nxt] = seen[(r, c)] + 1
                queue.append(nxt)
    raise AssertionError("no path")


def grid_model(tmp_path, q_attributes):
    (tmp_path / "TinyGrid.py").write_text(TINY_GRID)
    world = "; ".join(" ".join(str(v) for v in row) for row in WORLD)
    return load_body(tmp_path,
                     f'<module class="TinyGrid" name="W" world="{world}"/>'
                     f'<module class="QLearning" name="Q" {q_attributes}/>'
                     '<connection source="Q.ACTION" target="W.MOVE"/>'
                     '<connection source="W.LOCATION" target="Q.STATE" delay="0"/>'
                     '<connection source="W.REWARD" target="Q.REINFORCEMENT" delay="0"/>')


def test_finds_the_shortest_path_in_a_grid_world(tmp_path):
    best = shortest_path(WORLD, (1, 1))
    assert best == 7                        # the long way round (down and left) is 9
    net = grid_model(tmp_path, 'alpha="0.5" gamma="0.9" epsilon="0.2" seed="1"')
    try:
        assert net.output("Q.VALUE").shape == WORLD.shape
        assert net.output("Q.ACTION").shape == (4,)
        net.run(ticks=4000)                 # explore
        net.set_parameter("Q.epsilon", 0.0)    # then act greedily
        rewards = []
        for _ in range(200):
            net.step()
            rewards.append(net.output("W.REWARD")[0])
        goal_ticks = np.flatnonzero(rewards)
        episodes = np.diff(goal_ticks)
        assert len(episodes) >= 20
        assert np.all(episodes == best), episodes
        # the value map decreases by gamma per step away from the goal along the path
        value = net.output("Q.VALUE")
        assert value[4, 5] == 0.1           # the goal itself is never left by a move
        np.testing.assert_allclose(value[3, 5], 0.9, rtol=1e-3)
        np.testing.assert_allclose(value[1, 1], 0.9 ** 7, rtol=1e-2)
        assert np.all(value[WORLD == 1] == 0.1)   # walls are never visited: initial value
    finally:
        net.close()


MAZE = np.array([[1, 1, 1, 1, 1, 1, 1, 1, 1, 1],
                 [1, 0, 0, 0, 0, 1, 0, 0, 2, 1],
                 [1, 0, 1, 1, 0, 1, 0, 1, 0, 1],
                 [1, 0, 1, 0, 0, 0, 0, 1, 0, 1],
                 [1, 0, 1, 0, 1, 1, 1, 1, 0, 1],
                 [1, 0, 0, 0, 1, 0, 0, 0, 0, 1],
                 [1, 1, 1, 0, 1, 0, 1, 1, 1, 1],
                 [1, 0, 0, 0, 0, 0, 0, 0, 0, 1],
                 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]])


def test_finds_the_shortest_path_in_gridworld(tmp_path):
    walls = "; ".join(" ".join(str(int(v == 1)) for v in row) for row in MAZE)
    goals = "; ".join(" ".join(str(int(v == 2)) for v in row) for row in MAZE)
    net = load_body(tmp_path,
                    f'<module class="Constant" name="Walls" data="{walls}"/>'
                    f'<module class="Constant" name="Goals" data="{goals}"/>'
                    '<module class="GridWorld" name="W" start_x="1" start_y="7" move="max"/>'
                    '<module class="QLearning" name="Q" alpha="0.5" epsilon="0.1" seed="2"/>'
                    '<connection source="Walls.OUTPUT" target="W.OBSTACLES" delay="0"/>'
                    '<connection source="Goals.OUTPUT" target="W.VALUES" delay="0"/>'
                    '<connection source="Q.ACTION" target="W.MOVE"/>'
                    '<connection source="W.LOCATION" target="Q.STATE" delay="0"/>'
                    '<connection source="W.REWARD" target="Q.REINFORCEMENT" delay="0"/>')
    try:
        net.run(ticks=4000)
        net.set_parameter("Q.epsilon", 0.0)
        rewards = []
        for _ in range(300):
            net.step()
            rewards.append(net.output("W.REWARD")[0])
        episodes = np.diff(np.flatnonzero(rewards))
        assert len(episodes) >= 15
        assert np.all(episodes == shortest_path(MAZE, (7, 1))), episodes
    finally:
        net.close()


def reference(states, rewards, alpha, gamma, initial, horizon, n):
    """The same Q-learning in plain Python, for epsilon = 0 (no ties)."""
    q = np.full((4, n), initial)
    last, actions, values = None, [], []
    for s, r in zip(states, rewards):
        if last is not None:
            a, ls = last
            v = q[:, s].max()
            if horizon == "infinite":
                v += r
            if r > 0:
                v = r
            q[a, ls] += alpha * (gamma * v - q[a, ls])
        a = int(np.argmax(q[:, s]))
        actions.append(a)
        values.append(np.maximum(q.max(axis=0), 0))
        last = (a, s)
    return actions, values


def data_file(tmp_path, rows):
    lines = ["STATE/3 R/1"] + [" ".join(str(v) for v in row) for row in rows]
    (tmp_path / "data.txt").write_text("\n".join(lines) + "\n")


def test_updates_match_the_formula_for_both_horizons(tmp_path):
    states = [0, 1, 1, 2, 0, 2, 1, 0, 0, 1, 2, 2]
    rewards = [0, 0, -1, 0, 2, 0, -0.5, 0, 1, 0, 0, -1]
    rows = [list(np.eye(3, dtype=int)[s]) + [r] for s, r in zip(states, rewards)]
    data_file(tmp_path, rows)
    net = load_body(tmp_path, '<module class="InputFile" name="F" filename="data.txt"/>'
                    '<module class="QLearning" name="I" alpha="0.3" gamma="0.8" '
                    'initial="0.2" horizon="infinite"/>'
                    '<module class="QLearning" name="H" alpha="0.3" gamma="0.8" '
                    'initial="0.2" horizon="finite"/>'
                    '<connection source="F.STATE" target="I.STATE" delay="0"/>'
                    '<connection source="F.R" target="I.REINFORCEMENT" delay="0"/>'
                    '<connection source="F.STATE" target="H.STATE" delay="0"/>'
                    '<connection source="F.R" target="H.REINFORCEMENT" delay="0"/>')
    try:
        np.testing.assert_allclose(net.output("I.VALUE"), [0.2, 0.2, 0.2])   # init
        got = {"I": ([], []), "H": ([], [])}
        for _ in rows:
            net.step()
            for name in got:
                action = net.output(f"{name}.ACTION")
                assert action.sum() == 1
                got[name][0].append(int(np.argmax(action)))
                got[name][1].append(net.output(f"{name}.VALUE"))
        for name, horizon in [("I", "infinite"), ("H", "finite")]:
            actions, values = reference(states, rewards, 0.3, 0.8, 0.2, horizon, 3)
            assert got[name][0] == actions, name
            np.testing.assert_allclose(got[name][1], values, rtol=1e-5, atol=1e-7)
        # a negative reinforcement drives a value below 0 only with the infinite horizon
        assert not np.allclose(got["I"][1][-1], got["H"][1][-1])
    finally:
        net.close()


def test_same_seed_same_run_and_epsilon_one_is_random(tmp_path):
    def actions(seed):
        net = load_body(tmp_path, '<module class="Constant" name="S" data="0 1 0 0"/>'
                        '<module class="Constant" name="R" data="0"/>'
                        f'<module class="QLearning" name="Q" epsilon="1" seed="{seed}"/>'
                        '<connection source="S.OUTPUT" target="Q.STATE" delay="0"/>'
                        '<connection source="R.OUTPUT" target="Q.REINFORCEMENT" delay="0"/>')
        try:
            got = []
            for _ in range(200):
                net.step()
                got.append(int(np.argmax(net.output("Q.ACTION"))))
            return got
        finally:
            net.close()
    a, b, c = actions(5), actions(5), actions(6)
    assert a == b and a != c
    counts = np.bincount(a, minlength=4)
    assert np.all(counts > 30), counts      # all four actions, roughly uniformly
