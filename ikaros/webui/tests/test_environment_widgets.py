"""The environment widgets (grid-world, planar-arm, world-2d) in a real headless Chromium,
against the real server running the demonstration models: after some ticks the canvas
shows the agent, the arm and the robot where the modules' outputs (read through
GET /api/data) say they are.

Screenshots are kept in test-artifacts/."""
from __future__ import annotations

import base64
import math
import os
import time

import pytest

from browsing import ARTIFACTS, ROOT, Server, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")


# the widgets' default colours (COLORS in the widget files)
AGENT = (0x1f, 0x6f, 0xd0)        # grid-world agent, planar-arm hand, world-2d robot
WALL = (0x3f, 0x46, 0x54)
REWARD = (0xf0, 0xa8, 0x1c)
FREE = (0xf4, 0xf3, 0xee)
POINTER = (0xff, 0xff, 0xff)      # the heading pointer
TARGET = (0xd8, 0x3a, 0x2e)       # planar-arm target, world-2d ray ends
LINK = (0x3f, 0x46, 0x54)
OBJECT = (0xe0, 0x8a, 0x1e)


def in_browser(model: str, view: int, check):
    """Serve a model, open the app at one of its views in Chromium and run
    check(server, page)."""
    def open_view(server, page):
        page.click(f"#navigator a[data-group=''][data-view='{view}']")
        page.wait_for_function(
            "(v) => { const c = window.ikaros.built; return c && c.group === '' && "
            "c.view === v; }", arg=view)
        assert server.get("/api/status")["state"] != "play"

    in_own_browser(os.path.join(EXAMPLES, model), open_view, check)


# --- helpers ------------------------------------------------------------------------------

def canvas_of(page, cls: str):
    loc = page.locator(f"#view-host .widget[data-widget='{cls}'] canvas").first
    loc.wait_for()
    return loc


def wait_drawn(page, canvas, tick: int):
    """Wait until the browser has a data frame of tick (or later) and the canvas is drawn."""
    page.wait_for_function(
        "(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t", arg=tick)
    page.wait_for_function("(c) => c.width > 0 && c.height > 0", arg=canvas.element_handle())
    time.sleep(0.1)


class Pixels:
    """The canvas as RGBA pixels, addressed in CSS pixels."""

    def __init__(self, canvas):
        self.canvas = canvas
        info = canvas.evaluate("""(c) => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            return {w: c.width, h: c.height, css_w: c.clientWidth, css_h: c.clientHeight,
                    b64: (() => { let s = ''; for (let i = 0; i < d.length; i += 8192)
                        s += String.fromCharCode.apply(null, d.subarray(i, i + 8192)); return btoa(s); })()};
        }""")
        self.w, self.h = info["w"], info["h"]
        self.css_w, self.css_h = info["css_w"], info["css_h"]
        self.dpr = self.w / self.css_w
        self.data = base64.b64decode(info["b64"])

    def at(self, x: float, y: float):
        px = min(max(int(x * self.dpr), 0), self.w - 1)
        py = min(max(int(y * self.dpr), 0), self.h - 1)
        i = 4 * (py * self.w + px)
        return tuple(self.data[i:i + 3])

    def is_color(self, x, y, color, tol=24):
        return all(abs(a - b) <= tol for a, b in zip(self.at(x, y), color))

    def centroid(self, color, tol=24):
        """The centre (CSS pixels) and the count of the pixels of a colour, or None."""
        res = self.canvas.evaluate("""(c, [color, tol]) => {
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let sx = 0, sy = 0, n = 0;
            for (let i = 0; i < d.length; i += 4) {
                if (Math.abs(d[i] - color[0]) <= tol && Math.abs(d[i+1] - color[1]) <= tol &&
                    Math.abs(d[i+2] - color[2]) <= tol) {
                    const p = i / 4; sx += p % c.width; sy += Math.floor(p / c.width); n++;
                }
            }
            return n ? [sx / n, sy / n, n] : null;
        }""", [list(color), tol])
        if res is None:
            return None
        return (res[0] + 0.5) / self.dpr, (res[1] + 0.5) / self.dpr, res[2]


def world_mapping(width, height, xmin, xmax, ymin, ymax, margin=4):
    """The mapping of planar-arm and world-2d: aspect kept, centred, y up, 4 px margin."""
    scale = min((width - 2 * margin) / (xmax - xmin), (height - 2 * margin) / (ymax - ymin))
    ox = (width - (xmax - xmin) * scale) / 2
    oy = (height - (ymax - ymin) * scale) / 2
    return scale, (lambda x: ox + (x - xmin) * scale), (lambda y: oy + (ymax - y) * scale)


def screenshot(page, name):
    page.screenshot(path=os.path.join(ARTIFACTS, f"webui-{name}.png"))


# --- the tests ----------------------------------------------------------------------------

def check_grid_world(server, page):
    canvas = canvas_of(page, "grid-world")
    positions = set()
    for round_ in range(3):
        tick = server.step(4)
        wait_drawn(page, canvas, tick)
        d = server.data("World.IMAGE", "World.COORDINATE", "World.HEADING")["data"]
        image = d["World.IMAGE"]
        x, y = d["World.COORDINATE"]
        heading = d["World.HEADING"][0]
        positions.add((x, y))
        rows, cols = len(image), len(image[0])
        px = Pixels(canvas)
        cell = min(px.css_w / cols, px.css_h / rows)
        ox, oy = (px.css_w - cols * cell) / 2, (px.css_h - rows * cell) / 2

        def centre(c, r):
            return ox + (c + 0.5) * cell, oy + (r + 0.5) * cell

        # the agent's cell: the agent's colour at its centre
        ax, ay = centre(x, y)
        assert px.is_color(ax, ay, AGENT), (round_, x, y, px.at(ax, ay))
        # its heading pointer (clockwise from north = up) is white; behind it, the body
        r = 0.3 * cell
        dx, dy = math.sin(heading), -math.cos(heading)
        assert px.is_color(ax + dx * r * 0.5, ay + dy * r * 0.5, POINTER, tol=40)
        assert px.is_color(ax - dx * r * 0.6, ay - dy * r * 0.6, AGENT)
        # the agent's colour is nowhere else: its blob is centred on the agent
        cx, cy, n = px.centroid(AGENT)
        assert abs(cx - ax) < cell * 0.25 and abs(cy - ay) < cell * 0.25
        assert n < (cell * px.dpr) ** 2
        # every other cell: wall, reward or free as IMAGE says
        for row in range(rows):
            for col in range(cols):
                if (col, row) == (round(x), round(y)):
                    continue
                v = image[row][col]
                expected = REWARD if v > 0.99 else WALL if v > 0.3 else FREE
                if row in (0, rows - 1) or col in (0, cols - 1):
                    expected = WALL
                # a point off the cell's centre, away from the grid lines
                sx, sy = centre(col - 0.25, row - 0.25)
                assert px.is_color(sx, sy, expected), (row, col, v, px.at(sx, sy))
    # the agent moved between the rounds and the picture followed it
    assert len(positions) > 1
    screenshot(page, "grid-world")
    assert page.errors == []


def check_planar_arm(server, page):
    canvas = canvas_of(page, "planar-arm")
    checked_target = False
    for round_ in range(3):
        tick = server.step(5)
        wait_drawn(page, canvas, tick)
        d = server.data("Arm.JOINTS", "Arm.TARGET", "Arm.HAND_POSITION")["data"]
        joints, target, hand = d["Arm.JOINTS"], d["Arm.TARGET"], d["Arm.HAND_POSITION"]
        px = Pixels(canvas)
        scale, mx, my = world_mapping(px.css_w, px.css_h, 0, 1, 0, 1)
        # the hand (drawn last, on top) at HAND_POSITION
        hx, hy = mx(hand[0]), my(hand[1])
        assert px.is_color(hx, hy, AGENT), (round_, hand, px.at(hx, hy))
        assert (hand[0], hand[1]) == pytest.approx(joints[-1], abs=1e-5)
        # the links: the middle of each of the first two segments (the third ends at the hand)
        for a, b in zip(joints[:2], joints[1:3]):
            lx, ly = mx((a[0] + b[0]) / 2), my((a[1] + b[1]) / 2)
            assert px.is_color(lx, ly, LINK), (round_, a, b, px.at(lx, ly))
        # the target, where the hand does not cover it
        dist = math.dist(hand, target)
        tx, ty = mx(target[0]), my(target[1])
        if dist > 0.05:
            assert px.is_color(tx, ty, TARGET), (round_, target, px.at(tx, ty))
            checked_target = True
            cx, cy, _ = px.centroid(TARGET)
            assert math.hypot(cx - tx, cy - ty) < 0.05 * scale
    assert checked_target
    screenshot(page, "planar-arm")
    assert page.errors == []


def check_world_2d(server, page):
    canvas = canvas_of(page, "world-2d")
    start = None
    for round_ in range(3):
        tick = server.step(10)
        wait_drawn(page, canvas, tick)
        d = server.data("World.POSE", "World.OBJECTS", "World.WALLS", "World.RANGE_POINTS")["data"]
        (x, y, heading), objects = d["World.POSE"], d["World.OBJECTS"]
        start = start or (x, y)
        px = Pixels(canvas)
        scale, mx, my = world_mapping(px.css_w, px.css_h, 0, 4, 0, 3)
        # the robot at POSE, its pointer towards the heading (counter-clockwise from x, y up)
        rx, ry = mx(x), my(y)
        r = 0.15 * scale
        assert px.is_color(rx, ry, AGENT), (round_, x, y, px.at(rx, ry))
        dx, dy = math.cos(heading), -math.sin(heading)
        assert px.is_color(rx + dx * r * 0.5, ry + dy * r * 0.5, POINTER, tol=40)
        assert px.is_color(rx - dx * r * 0.6, ry - dy * r * 0.6, AGENT)
        cx, cy, _ = px.centroid(AGENT)
        assert math.hypot(cx - rx, cy - ry) < 0.3 * r
        # the objects where OBJECTS says (those not under the robot)
        for ox_, oy_, _angle, radius in objects:
            if radius > 0 and math.hypot(ox_ - x, oy_ - y) > radius + 0.2:
                # off the centre: the spoke of the rotation starts there
                sx, sy = mx(ox_) + 0.3 * radius * scale * math.cos(_angle + 2), \
                    my(oy_) - 0.3 * radius * scale * math.sin(_angle + 2)
                assert px.is_color(sx, sy, OBJECT), (round_, ox_, oy_, px.at(sx, sy))
        # the walls: the arena's edges (mostly; sensor rays may cross them)
        for edge in [lambda t: (4 * t, 0), lambda t: (4 * t, 3), lambda t: (0, 3 * t),
                     lambda t: (4, 3 * t)]:
            points = [edge(k / 40) for k in range(1, 40)]
            walls = sum(px.is_color(mx(wx), my(wy), WALL) for wx, wy in points)
            assert walls >= 0.8 * len(points), (edge(0.5), walls)
        # the end of every sensor ray
        for ex, ey in d["World.RANGE_POINTS"]:
            assert px.is_color(mx(ex), my(ey), TARGET, tol=30), (ex, ey, px.at(mx(ex), my(ey)))
    assert math.dist(start, (x, y)) > 0.01        # the robot has moved and the view followed
    screenshot(page, "world-2d")
    assert page.errors == []


def test_grid_world_shows_walls_reward_and_the_agent():
    in_browser("qlearning_maze.ikg", 1, check_grid_world)


def test_planar_arm_shows_links_target_and_hand():
    in_browser("planar_arm_reaching.ikg", 1, check_planar_arm)


def test_world_2d_shows_walls_objects_robot_and_rays():
    in_browser(os.path.join("modules", "World2D_example.ikg"), 1, check_world_2d)


def test_the_new_views_are_added_beside_the_old_ones():
    for model, names, cls in [
            ("qlearning_maze.ikg", ["Q-learning in a maze", "Maze world"], "grid-world"),
            ("planar_arm_reaching.ikg", ["Reaching", "Arm"], "planar-arm"),
            (os.path.join("modules", "World2D_example.ikg"), ["World2D", "Arena"], "world-2d")]:
        server = Server(os.path.join(EXAMPLES, model))
        try:
            views = server.get("/api/network")["top"]["views"]
        finally:
            server.stop()
        assert [v["name"] for v in views] == names
        first = views[1]["widgets"][0]
        assert first["class"] == cls and first["module"] in ("World", "Arm")
