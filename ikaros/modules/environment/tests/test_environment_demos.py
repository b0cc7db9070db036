"""The two demonstration models in examples/ run headless and do what they claim:
qlearning_maze.ikg learns the shortest path through its maze, and planar_arm_reaching.ikg
learns the arm's inverse kinematics well enough to track a moving target."""
import collections
import os
import subprocess
import sys

import numpy as np

import ikaros

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))
MAZE_MODEL = os.path.join(ROOT, "examples", "qlearning_maze.ikg")
ARM_MODEL = os.path.join(ROOT, "examples", "planar_arm_reaching.ikg")


def shortest_path(maze, start, goal):
    """Breadth-first search over the floor cells (y, x) of the maze."""
    dist = {start: 0}
    queue = collections.deque([start])
    while queue:
        y, x = queue.popleft()
        for dy, dx in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            n = (y + dy, x + dx)
            if maze[n] < 1 and n not in dist:
                dist[n] = dist[(y, x)] + 1
                queue.append(n)
    return dist[goal]


def test_qlearning_finds_the_shortest_path_through_the_maze():
    net = ikaros.load(MAZE_MODEL)
    try:
        maze = net.output("Maze.OUTPUT")
        goal = tuple(int(v) for v in np.argwhere(net.output("Goal.OUTPUT") > 0)[0])
        best = shortest_path(maze, (1, 1), goal)
        assert best == 20
        reward_ticks = []
        for tick in range(5000):
            net.step()
            if net.output("World.REWARD")[0] > 0:
                reward_ticks.append(tick)
        lengths = np.diff(reward_ticks)            # moves per episode after the first
        late = lengths[np.array(reward_ticks[1:]) >= 4000]
        # the first searches are long; after 4000 ticks every episode is a shortest path
        assert reward_ticks[0] > 3 * best and lengths[:3].min() > 3 * best
        assert len(late) >= 40 and np.all(late <= 1.1 * best)
        assert np.all(late >= best)
        # the model's own measure: rewards per tick over the last 500 ticks = 1 / 20
        assert net.output("RewardRate.OUTPUT")[0] >= 0.9 / best
    finally:
        net.close()


def test_planar_arm_learns_to_reach():
    net = ikaros.load(ARM_MODEL)
    try:
        distance = []
        for _ in range(3000):
            net.step()
            distance.append(float(net.output("Arm.DISTANCE")[0]))
        distance = np.array(distance)
        # babbling ignores the target; after 200 ticks of reaching the hand tracks it
        assert distance[:2000].mean() > 0.3
        assert distance[2200:].mean() < 0.005
        assert distance[2200:].max() < 0.01
    finally:
        net.close()


def test_both_demos_run_in_batch_mode():
    for model, ticks in ((MAZE_MODEL, 500), (ARM_MODEL, 500)):
        result = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-q", "-s", str(ticks),
                                 model], capture_output=True, text=True, timeout=60,
                                cwd=ROOT)
        assert result.returncode == 0, result.stderr
