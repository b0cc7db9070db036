"""A module inspector opened from the navigator is in view and has the focus (issue 37,
item 2: at 1400 x 900 it opened below the tall System inspector with only its title bar in
view), in a real headless Chromium. Screenshot: test-artifacts/module-inspector.png."""
from __future__ import annotations

import os

from browsing import ARTIFACTS, ROOT, in_own_browser

DEMO = os.path.join(ROOT, "examples", "demo.ikg")

PLACED = """() => {
    const el = document.getElementById('module-inspector');
    const pane = document.getElementById('inspector').getBoundingClientRect();
    const r = el.getBoundingClientRect();
    return {top: r.top, bottom: r.bottom, height: r.height, paneTop: pane.top,
            paneBottom: pane.bottom, viewport: window.innerHeight,
            title: el.querySelector('.pane-title')?.textContent || '',
            focused: el.contains(document.activeElement)};
}"""


def test_a_module_inspector_opens_in_view_with_the_focus():
    def check(server, page):
        assert page.viewport_size == {"width": 1400, "height": 900}
        link = page.locator("#navigator a[data-module]").first
        path = link.get_attribute("data-module")
        link.click()
        page.wait_for_function("(p) => (document.querySelector('#module-inspector .pane-title')"
                               "?.textContent || '').startsWith(p)", arg=path)
        page.wait_for_timeout(300)
        d = page.evaluate(PLACED)
        top, bottom = max(d["top"], d["paneTop"]), min(d["bottom"], d["paneBottom"], d["viewport"])
        visible = bottom - top
        assert visible >= min(d["height"], 400), d
        assert d["paneTop"] <= d["top"] <= d["paneBottom"] - 100, d     # its title in view
        assert d["focused"], d
        page.screenshot(path=os.path.join(ARTIFACTS, "module-inspector.png"))
        assert not page.errors, page.errors

    in_own_browser(DEMO, lambda server, page: None, check)
