"""MazeGenerator: random perfect mazes, L-mazes and T-mazes as obstacle matrices."""
from ikaros.module import Module, Output, Parameter

from .._crand import module_rand

# the four steps (dx, dy) a room tries, in this order from a random first one:
# left, right, up, down (x along a row, y down the rows)
STEPS = ((-1, 0), (1, 0), (0, -1), (0, 1))


class MazeGenerator(Module):
    """Outputs a maze as a matrix of (2·size+1) x (2·size+1) cells, 1 for wall and 0 for
    floor, ready for the OBSTACLES input of GridWorld. The floor cells are the odd rows and
    columns: a size x size lattice of rooms (room (x, y) is cell (2y+1, 2x+1)) separated by
    walls. ``perfect`` carves a random depth-first spanning tree, so there is exactly one
    path between any two rooms; ``l-maze`` is a single corridor down the first room column
    and along the bottom room row; ``t-maze`` is a corridor up the middle room column that
    meets one along the top room row. The maze is made in init and, when ``regenerate`` is
    more than 0, again on every tick that is a multiple of it (tick ``regenerate``,
    2·``regenerate``, ...).

    The perfect maze is Ikaros 2's (Ikaros 3 has no MazeGenerator): with s = rand() % size²
    it starts in room (s % size, s / size); every room it enters draws k = rand() % 4 and
    tries the four steps left, right, up, down in turn from the k-th (k, k+1, ... mod 4),
    going on from each unvisited neighbour it reaches, opening the wall to it, before it
    tries the next step. rand() is the C library's generator (glibc's), which Ikaros 2 seeds
    only with the command line's -z: the modules of a network share it, unseeded as there
    unless the top group's random_seed (``ikaros -z N``) seeds it, so a model gives the
    original's maze (its golden file, the default 8 x 8 maze, is reproduced wall for
    wall). ``seed`` gives the module a generator of its own, seeded as
    srand does (a negative seed: a different maze every run). The golden maze fits as well
    a variant that draws k anew each time it comes back to a room instead of going on with
    the turn (it differs in about one maze of eight, and draws once less for each dead end);
    which one Ikaros 2 uses is not known, and this class takes the one above. The class
    description says the l-maze and t-maze types exist; their layouts here are this
    project's."""

    size = Parameter(8, "number of rooms along each side; the matrix is 2*size+1 square",
                     range=(1, None))
    type = Parameter("perfect", "the kind of maze", options="perfect/l-maze/t-maze")
    regenerate = Parameter(0, "make a new maze every this many ticks (0 = never)")
    seed = Parameter(None, "seed of the C library generator (as srand); unset: Ikaros 2's "
                     "unseeded sequence; negative: a different maze every run", type="int")
    OUTPUT = Output("the maze: 1 wall, 0 floor", shape="2*@size+1, 2*@size+1")

    def init(self):
        if self.size < 1:
            raise ValueError(f"size must be at least 1, not {self.size}")
        self._rand = module_rand(self)
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

    def _enter(self, maze, visited, x, y) -> list:
        """Mark room (x, y) visited and open; its place on the stack: the room, the first
        step it tries and how many it has tried."""
        visited[y][x] = True
        maze[2 * y + 1, 2 * x + 1] = 0
        return [x, y, self._rand.rand() % 4, 0]

    def _perfect(self, maze, n):
        """The depth-first walk of the class description, with a stack for the recursion."""
        visited = [[False] * n for _ in range(n)]
        start = self._rand.rand() % (n * n)
        stack = [self._enter(maze, visited, start % n, start // n)]
        while stack:
            room = stack[-1]
            x, y, first, tried = room
            if tried == len(STEPS):
                stack.pop()
                continue
            room[3] += 1
            dx, dy = STEPS[(first + tried) % len(STEPS)]
            nx, ny = x + dx, y + dy
            if 0 <= nx < n and 0 <= ny < n and not visited[ny][nx]:
                maze[y + ny + 1, x + nx + 1] = 0          # the wall between the two rooms
                stack.append(self._enter(maze, visited, nx, ny))
