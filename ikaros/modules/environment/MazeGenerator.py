"""MazeGenerator: random perfect mazes, L-mazes and T-mazes as obstacle matrices."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class MazeGenerator(Module):
    """Outputs a maze as a matrix of (2·size+1) x (2·size+1) cells, 1 for wall and 0 for
    floor, ready for the OBSTACLES input of GridWorld. The floor cells are the odd rows and
    columns: a size x size lattice of rooms (room (i, j) is cell (2j+1, 2i+1)) separated by
    walls. ``perfect`` carves a random depth-first spanning tree, so there is exactly one
    path between any two rooms; ``l-maze`` is a single corridor down the first room column
    and along the bottom room row; ``t-maze`` is a corridor up the middle room column that
    meets one along the top room row. The maze is made in init and, when ``regenerate`` is
    more than 0, again on every tick that is a multiple of it (tick ``regenerate``,
    2·``regenerate``, ...). The same ``seed`` gives the same mazes. Ikaros 2 (Ikaros 3
    has no MazeGenerator) draws its mazes from the C library's rand(), seeded by the
    command line's -z, so a run without -z makes the same maze every time; the golden file
    of Ikaros 2 shows that maze for the defaults, and this class, whose random numbers and
    depth-first order are its own, makes another: an Ikaros 2 model gets a maze of the same
    kind but not the original's. The class description says the l-maze and t-maze types
    exist; their layouts here are this project's."""

    size = Parameter(8, "number of rooms along each side; the matrix is 2*size+1 square",
                     range=(1, None))
    type = Parameter("perfect", "the kind of maze", options="perfect/l-maze/t-maze")
    regenerate = Parameter(0, "make a new maze every this many ticks (0 = never)")
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives a different "
                     "maze every run", type="int")
    OUTPUT = Output("the maze: 1 wall, 0 floor", shape="2*@size+1, 2*@size+1")

    def init(self):
        if self.size < 1:
            raise ValueError(f"size must be at least 1, not {self.size}")
        self._rng = np.random.default_rng(self.seed or None)
        self._generate()

    def tick(self):
        if self.regenerate > 0 and self.clock.tick > 0 and self.clock.tick % self.regenerate == 0:
            self._generate()

    def command(self, name, x=0, y=0, value=None):
        if name in ("regenerate", "reset"):
            self._generate()

    def _generate(self):
        n = (self.OUTPUT.shape[0] - 1) // 2
        maze = self.OUTPUT
        maze.fill(1)
        last = 2 * n - 1
        if self.type == "l-maze":
            maze[1:last + 1, 1] = 0
            maze[last, 1:last + 1] = 0
        elif self.type == "t-maze":
            middle = 2 * (n // 2) + 1
            maze[1:last + 1, middle] = 0
            maze[1, 1:last + 1] = 0
        else:
            self._perfect(maze, n)

    def _perfect(self, maze, n):
        """Depth-first backtracker over the n x n rooms (iterative, random neighbour order)."""
        rng = self._rng
        visited = np.zeros((n, n), bool)
        start = (int(rng.integers(n)), int(rng.integers(n)))
        visited[start] = True
        maze[2 * start[0] + 1, 2 * start[1] + 1] = 0
        stack = [start]
        steps = np.array([(-1, 0), (0, 1), (1, 0), (0, -1)])
        while stack:
            r, c = stack[-1]
            nbrs = np.array((r, c)) + steps
            ok = (nbrs[:, 0] >= 0) & (nbrs[:, 0] < n) & (nbrs[:, 1] >= 0) & (nbrs[:, 1] < n)
            nbrs = nbrs[ok]
            nbrs = nbrs[~visited[nbrs[:, 0], nbrs[:, 1]]]
            if len(nbrs) == 0:
                stack.pop()
                continue
            nr, nc = (int(v) for v in nbrs[rng.integers(len(nbrs))])
            visited[nr, nc] = True
            maze[r + nr + 1, c + nc + 1] = 0          # the wall between the two rooms
            maze[2 * nr + 1, 2 * nc + 1] = 0
            stack.append((nr, nc))
