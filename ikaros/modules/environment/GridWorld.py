"""GridWorld: an agent in a grid of walls and rewards, moving cell by cell or driving freely."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

# Compass directions in the order of MOVE in the absolute modes: north, east, south, west.
# Grid coordinates are (x = column, y = row); north is up, towards row 0.
_DX = (0, 1, 0, -1)
_DY = (-1, 0, 1, 0)


class GridWorld(Module):
    """A grid world for reinforcement learning and navigation. OBSTACLES is a matrix whose
    cells of value 1 or more are walls; the outer border is always a wall. VALUES holds the
    reward of each cell. In ``motion`` = ``discrete`` the agent moves one cell per tick:
    with ``move`` = ``max`` the largest of the four MOVE elements (north, east, south, west)
    picks the direction; ``sum`` first opposes the opposite directions (N-S, E-W, S-N, W-E);
    ``relative_max`` reads MOVE as (ahead, turn left, turn right) and takes the largest, and
    ``relative_sum`` opposes the two turns first (ahead, left-right, right-left). A MOVE of
    all zeros does nothing. In ``motion`` = ``differential_drive`` the agent is a disc of
    radius ``radius`` cells that drives freely: MOVE is (left wheel, right wheel) speed in
    cells per tick (clipped to ``max_speed``), ``wheel_base`` sets how fast unequal wheels
    turn it, and a move that would overlap a wall slides along it or is refused. A cell's
    centre is at its integer coordinate. A move onto a cell with a positive value gives
    that REWARD and puts the agent back at (``start_x``, ``start_y``), so on that tick
    LOCATION and COORDINATE already show the start. COLLISION, with ``collision`` =
    ``original`` (Ikaros 2), is 0 on a discrete move that a wall blocks and 1 on one that
    succeeds (the original sets it when the agent did not collide); ``blocked`` gives 1 for
    a blocked move and 0 otherwise, and the differential drive always reports it so. IMAGE,
    with ``image`` = ``original`` (Ikaros 2), is OBSTACLES with 3 where VALUES is above 0
    and 2 at the agent; ``normalized`` gives an image in 0..1: free 0, wall 1/3, agent 2/3,
    reward 1. HEADING is an addition: the agent's direction in radians, clockwise from
    north. The golden file of Ikaros 2 shows a blocked move (COLLISION 0), IMAGE, LOCATION,
    COORDINATE, the local views and REWARD on a matrix MOVE; that Ikaros 2 read the
    parameters under other names than its class file (x_start, y_start and mode; the first
    two are accepted here as aliases), mapped the ``move`` options to other modes, never
    turned right in the relative modes and read past MOVE in ``relative_sum`` is this
    project's earlier reading of the original, not checked against it: here ``move``
    works as listed and turns go both ways (Ikaros 3 has no GridWorld)."""

    move = Parameter("max", "how MOVE is read in the discrete mode: max or sum of the four "
                     "directions N, E, S, W, or relative_max / relative_sum of (ahead, turn "
                     "left, turn right)", options="max/sum/relative_max/relative_sum")
    motion = Parameter("discrete", "discrete: one cell per tick; differential_drive: a "
                       "round robot with two wheels driving freely between cells",
                       options="discrete/differential_drive")
    start_x = Parameter(1, "starting column of the agent (kept inside the border)")
    start_y = Parameter(1, "starting row of the agent (kept inside the border)")
    x_start = Parameter(None, "Ikaros 2 code name of start_x; overrides it when given "
                        "(0 or unset: start_x is used)",
                        type="int")
    y_start = Parameter(None, "Ikaros 2 code name of start_y; overrides it when given "
                        "(0 or unset: start_y is used)",
                        type="int")
    start_heading = Parameter(0.0, "starting heading in radians clockwise from north (the "
                              "relative modes round it to the nearest compass direction)")
    collision = Parameter("original", "original: COLLISION 0 on a blocked move, 1 on a "
                          "move that succeeds (Ikaros 2); blocked: 1 on a blocked move",
                          options="original,blocked")
    image = Parameter("original", "original: IMAGE is OBSTACLES, 3 on rewards, 2 at the "
                      "agent (Ikaros 2); normalized: 0 free, 1/3 wall, 2/3 agent, 1 reward",
                      options="original,normalized")
    normalize_coordinate = Parameter(False, "map COORDINATE to 0..1: ((x+0.5)/columns, "
                                     "(y+0.5)/rows)")
    max_speed = Parameter(0.25, "differential drive: largest wheel speed, cells per tick")
    wheel_base = Parameter(0.5, "differential drive: distance between the wheels in cells; "
                           "the turn per tick is (left - right) / wheel_base radians")
    radius = Parameter(0.3, "differential drive: radius of the agent's body in cells")

    MOVE = Input("the action: 4 values (N, E, S, W) in the absolute modes, 3 (ahead, left, "
                 "right) in the relative modes, 2 (left, right wheel speed) in the "
                 "differential drive; unconnected, the agent stays", optional=True)
    OBSTACLES = Input("matrix of walls (cells of value 1 or more); sets the size of the world")
    VALUES = Input("matrix of rewards, the size of OBSTACLES; unconnected, no rewards",
                   optional=True)

    LOCATION = Output("one-hot matrix: 1 in the agent's cell", shape="OBSTACLES.shape")
    COORDINATE = Output("the agent's position (x = column, y = row); fractional in the "
                        "differential drive; see normalize_coordinate", size="2")
    LOCAL_OBSTACLES = Output("the 3x3 cells of OBSTACLES around the agent's cell",
                             size_x="3", size_y="3")
    LOCAL_VALUES = Output("the 3x3 cells of VALUES around the agent's cell",
                          size_x="3", size_y="3")
    REWARD = Output("the value of the cell the agent reached on this tick", size="1")
    COLLISION = Output("whether the move of this tick was blocked (see collision)",
                       size="1")
    IMAGE = Output("picture of the world (see image)", shape="OBSTACLES.shape")
    HEADING = Output("the agent's heading in radians clockwise from north", size="1")

    def init(self):
        if self.OBSTACLES.ndim != 2 or min(self.OBSTACLES.shape) < 3:
            raise ValueError(f"OBSTACLES must be a matrix of at least 3x3 cells, not "
                             f"{self.OBSTACLES.shape}")
        if self.VALUES is not None and self.VALUES.shape != self.OBSTACLES.shape:
            raise ValueError(f"VALUES has shape {self.VALUES.shape}; it must match OBSTACLES "
                             f"{self.OBSTACLES.shape}")
        needed = {"max": 4, "sum": 4, "relative_max": 3, "relative_sum": 3}[self.move]
        if self.motion == "differential_drive":
            needed = 2
        if self.MOVE is not None and self.MOVE.size < needed:
            raise ValueError(f"MOVE has {self.MOVE.size} elements; move={self.move} "
                             f"motion={self.motion} needs {needed}")
        self._shape = self.OBSTACLES.shape
        self._values = self.VALUES if self.VALUES is not None else \
            np.zeros(self.OBSTACLES.shape, np.float32)
        self._reset_agent()
        self.REWARD[0] = 0
        self.COLLISION[0] = 0
        self._write()

    # --- state --------------------------------------------------------------------------
    def _start(self):
        rows, cols = self._shape
        sx = self.x_start or self.start_x
        sy = self.y_start or self.start_y
        return int(min(max(sx, 1), cols - 2)), int(min(max(sy, 1), rows - 2))

    def _reset_agent(self):
        self._x, self._y = (float(v) for v in self._start())
        self._heading = float(self.start_heading)
        self._dir = int(round(self._heading / (math.pi / 2))) % 4

    def _walls(self):
        walls = self.OBSTACLES >= 1
        walls[0, :] = walls[-1, :] = True
        walls[:, 0] = walls[:, -1] = True
        return walls

    def _cell(self):
        return int(math.floor(self._x + 0.5)), int(math.floor(self._y + 0.5))

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._reset_agent()
            self._write()

    # --- moves --------------------------------------------------------------------------
    def tick(self):
        if self.motion == "differential_drive":
            self.COLLISION[0] = self._drive()
        else:
            moved = self._step()
            if moved is None:                       # no action: nothing happens
                self.REWARD[0] = 0
                self.COLLISION[0] = 0
                self._write()
                return
            self.COLLISION[0] = float(moved) if self.collision == "original" else \
                float(not moved)
        cx, cy = self._cell()
        reward = float(self._values[cy, cx])
        self.REWARD[0] = reward
        if reward > 0:
            self._reset_agent()
        self._write()

    def _step(self):
        """One discrete move; None when MOVE asks for nothing, else whether the agent moved."""
        if self.MOVE is None:
            return None
        m = np.asarray(self.MOVE, np.float64).reshape(-1)
        relative = self.move.startswith("relative")
        m = m[:3] if relative else m[:4]
        if not np.any(m):
            return None
        if self.move == "sum":
            m = m - np.roll(m, 2)
        elif self.move == "relative_sum":
            m = np.array([m[0], m[1] - m[2], m[2] - m[1]])
        choice = int(np.argmax(m))
        if relative:
            if choice == 1:
                self._dir = (self._dir - 1) % 4
            elif choice == 2:
                self._dir = (self._dir + 1) % 4
            self._heading = self._dir * math.pi / 2
            if choice != 0:
                return True                         # a turn always succeeds
            direction = self._dir
        else:
            direction = choice
            self._dir = direction
            self._heading = direction * math.pi / 2
        nx, ny = int(self._x) + _DX[direction], int(self._y) + _DY[direction]
        if self._walls()[ny, nx]:
            return False
        self._x, self._y = float(nx), float(ny)
        return True

    def _drive(self):
        """One tick of the differential drive; returns 1 when a wall blocked the move."""
        if self.MOVE is None:
            return 0
        left, right = np.clip(np.asarray(self.MOVE, np.float64).reshape(-1)[:2],
                              -self.max_speed, self.max_speed)
        v = 0.5 * (left + right)
        w = (left - right) / self.wheel_base if self.wheel_base > 0 else 0.0
        h = self._heading
        if abs(w) < 1e-9:
            dx, dy = v * math.sin(h), -v * math.cos(h)
        else:
            dx = v / w * (math.cos(h) - math.cos(h + w))
            dy = v / w * (math.sin(h) - math.sin(h + w))
        self._heading = (h + w + math.pi) % (2 * math.pi) - math.pi
        if dx == 0 and dy == 0:
            return 0
        walls = self._walls()
        x, y = self._x, self._y
        for nx, ny in ((x + dx, y + dy), (x + dx, y), (x, y + dy)):
            if not self._overlaps(walls, nx, ny):
                self._x, self._y = nx, ny
                return 0 if (nx, ny) == (x + dx, y + dy) else 1
        return 1

    def _overlaps(self, walls, x, y):
        """Whether a disc of ``radius`` at (x, y) overlaps a wall cell (cells are unit squares
        centred on integer coordinates)."""
        r = max(float(self.radius), 0.0)
        rows, cols = walls.shape
        i0, i1 = int(math.floor(x - r + 0.5)), int(math.floor(x + r + 0.5))
        j0, j1 = int(math.floor(y - r + 0.5)), int(math.floor(y + r + 0.5))
        if i0 < 0 or j0 < 0 or i1 >= cols or j1 >= rows:
            return True
        jj, ii = np.mgrid[j0:j1 + 1, i0:i1 + 1]
        px = np.clip(x, ii - 0.5, ii + 0.5)          # nearest point of each cell
        py = np.clip(y, jj - 0.5, jj + 0.5)
        near = (px - x) ** 2 + (py - y) ** 2 < r * r
        near[(jj == int(math.floor(y + 0.5))) & (ii == int(math.floor(x + 0.5)))] = True
        return bool(np.any(walls[jj, ii] & near))

    # --- outputs ------------------------------------------------------------------------
    def _write(self):
        rows, cols = self._shape
        cx, cy = self._cell()
        if self.normalize_coordinate:
            self.COORDINATE[0] = (self._x + 0.5) / cols
            self.COORDINATE[1] = (self._y + 0.5) / rows
        else:
            self.COORDINATE[0] = self._x
            self.COORDINATE[1] = self._y
        self.LOCATION.fill(0)
        self.LOCATION[cy, cx] = 1
        self.LOCAL_OBSTACLES[...] = self.OBSTACLES[cy - 1:cy + 2, cx - 1:cx + 2]
        self.LOCAL_VALUES[...] = self._values[cy - 1:cy + 2, cx - 1:cx + 2]
        self.HEADING[0] = self._heading
        image = self.IMAGE
        if self.image == "original":
            image[...] = self.OBSTACLES
            image[self._values > 0] = 3
            image[cy, cx] = 2
            return
        np.clip(self.OBSTACLES, 0, 1, out=image)
        image *= 1 / 3
        image[self._values > 0] = 1
        image[cy, cx] = 2 / 3
