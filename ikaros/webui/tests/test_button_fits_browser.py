"""Buttons show their labels inside their outline (issue 37, item 3: in lucs_arm's "Arm" view
"Torque off now" and "Resume" had an outline about 12 px high under a title bar, the label
spilling over it), in a real headless Chromium against the examples on their simulated
robots. Screenshot: test-artifacts/arm-buttons.png."""
from __future__ import annotations

import os

from browsing import ARTIFACTS, ROOT, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")

BUTTONS = """() => window.ikaros.mainView.widgets.filter((w) => w.attrs.class === 'button').map((w) => {
    const b = w.button, r = b.getBoundingClientRect(), box = w.el.getBoundingClientRect();
    const text = document.createRange();
    text.selectNodeContents(b);
    const t = text.getBoundingClientRect();
    return {label: b.textContent, height: r.height, top: r.top, bottom: r.bottom,
            left: r.left, right: r.right, textTop: t.top, textBottom: t.bottom,
            textLeft: t.left, textRight: t.right, widgetBottom: box.bottom};
})"""


def test_the_arm_views_buttons_hold_their_labels():
    for model in ("lucs_arm.ikg", "arm_playback.ikg"):
        def check(server, page, model=model):
            page.wait_for_function("() => window.ikaros.mainView && window.ikaros.mainView.widgets.length")
            buttons = page.evaluate(BUTTONS)
            assert buttons, model
            for b in buttons:
                assert b["height"] >= 22, (model, b)
                assert b["top"] <= b["textTop"] and b["textBottom"] <= b["bottom"], (model, b)
                assert b["left"] <= b["textLeft"] and b["textRight"] <= b["right"], (model, b)
                assert b["bottom"] <= b["widgetBottom"], (model, b)
            page.screenshot(path=os.path.join(ARTIFACTS, f"buttons-{model[:-4]}.png"))
            assert page.errors == []
        in_own_browser(os.path.join(EXAMPLES, model), lambda s, p: None, check)
