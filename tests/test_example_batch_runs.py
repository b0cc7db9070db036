"""A batch run of an example says what it did (issue 37, item 8: conditioning,
qlearning_maze, planar_arm_reaching and gl_robot_builder printed nothing, so a new user
could not tell they had worked): each prints, through a Print module, what its
description promises, with the run the README and the file's own comment give."""
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(example: str, ticks: int) -> list[str]:
    out = subprocess.run([sys.executable, "-m", "ikaros", "-b", "-s", str(ticks),
                          os.path.join(ROOT, "examples", example)], capture_output=True,
                         text=True, timeout=120, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    return out.stdout.splitlines()


def values(lines: list[str], prefix: str) -> list[list[float]]:
    assert lines and all(line.startswith(prefix) for line in lines), lines
    return [[float(v) for v in line[len(prefix):].split()] for line in lines]


@pytest.mark.slow
def test_every_example_in_the_readme_says_what_it_did():
    # the conditioned response rises in acquisition and falls in extinction
    cr = [v[0] for v in values(run("conditioning.ikg", 600), "Trial: conditioned response = ")]
    assert len(cr) == 12 and max(cr[1:6]) > 0.9 and cr[-1] < 0.05, cr
    # the agent settles at the shortest path: 20 moves, 0.05 rewards per tick
    rate = [v[0] for v in values(run("qlearning_maze.ikg", 5000), "Progress: rewards per tick = ")]
    assert len(rate) == 10 and rate[0] == 0 and rate[-1] == pytest.approx(0.05), rate
    # the hand reaches the target once it has babbled
    distance = [v[0] for v in values(run("planar_arm_reaching.ikg", 3000),
                                     "Reach: distance to the target = ")]
    assert len(distance) == 12 and max(distance[-3:]) < 0.02, distance
    # the robot has put its blocks down
    where = values(run("gl_robot_builder.ikg", 480), "Where: robot x, y, held block, heading = ")
    assert len(where) == 8 and 3 in [w[2] for w in where] and where[-1][2] == 0, where
