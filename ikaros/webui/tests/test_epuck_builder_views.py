"""The e-puck and builder-robot examples' views in a real headless Chromium, against the real
server running the models: the e-puck's arena view gets the robot's pose and the walls, and
the builder robot's 3-D view gets one transform per body part and object."""
from __future__ import annotations

import os

from browsing import ROOT, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")


def open_first_view(server, page):
    page.click("#navigator a[data-group=''][data-view='0']")
    page.wait_for_function(
        "() => { const c = window.ikaros.built; return c && c.group === '' && c.view === 0; }")


def widgets(page) -> list[str]:
    return page.evaluate("() => window.ikaros.mainView.widgets.map(w => w.attrs.class)")


def test_the_epuck_arena_view_follows_the_robot():
    def check(server, page):
        assert sorted(widgets(page)) == ["bar-graph", "image", "plot", "table", "table",
                                         "world-2d"]
        tick = server.step(20)
        pose = server.data("Robot.POSE")["data"]["Robot.POSE"]
        page.wait_for_function(
            "(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t", arg=tick)
        assert pose[0] > 0.2                           # it drove forward along x
        assert page.errors == []
    in_own_browser(os.path.join(EXAMPLES, "epuck_obstacles.ikg"), open_first_view, check)


def test_the_builder_robot_is_drawn_in_3d():
    def check(server, page):
        assert sorted(widgets(page)) == ["bar-graph", "bar-graph", "bar-graph", "bar-graph",
                                         "canvas3d", "plot", "table"]
        server.step(5)
        # body, upper arm, forearm, gripper, charging station and the five objects
        page.wait_for_function(
            "() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'canvas3d')"
            ".transforms.length === 10")
        assert page.errors == []
    in_own_browser(os.path.join(EXAMPLES, "gl_robot_builder.ikg"), open_first_view, check)
