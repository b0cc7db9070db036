"""The robot examples' views in a real headless Chromium, against the real server running
the models on their simulated robots: every widget is built without a page error, and the
Epi head's 3-D view gets the six transforms of its pose."""
from __future__ import annotations

import os

from browsing import ROOT, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")


def open_first_view(server, page):
    page.click("#navigator a[data-group=''][data-view='0']")
    page.wait_for_function("() => { const c = window.ikaros.built; return c && c.group === '' && c.view === 0; }")


def widgets(page) -> list[str]:
    return page.evaluate("() => window.ikaros.mainView.widgets.map(w => w.attrs.class)")


def test_the_epi_view_shows_the_head_pose_in_3d():
    def check(server, page):
        assert sorted(widgets(page)) == ["canvas3d", "path", "path", "plot", "plot", "table", "table"]
        server.step(5)
        page.wait_for_function(
            "() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'canvas3d').transforms.length === 6")
        assert page.errors == []
    in_own_browser(os.path.join(EXAMPLES, "epi.ikg"), open_first_view, check)


def test_the_arm_views_build():
    for model, expected in (("lucs_arm.ikg", ["bar-graph", "button", "button", "plot", "plot", "table", "table"]),
                            ("arm_playback.ikg", ["button"] * 6 + ["plot", "plot", "table", "table"])):
        def check(server, page, expected=expected):
            assert sorted(widgets(page)) == expected
            server.step(3)
            assert page.errors == []
        in_own_browser(os.path.join(EXAMPLES, model), open_first_view, check)
