"""The State menu acting on the module selected in the editor (issue 16, part 9), in a real
headless Chromium against the real server started with ``-W``: save one module's state,
let the run change it, load it back, reset it; the other module is left alone; at quit the
whole state is saved beside the model. Screenshots go to tmp_path only."""
from __future__ import annotations

import json

from browsing import in_own_browser

# Two Delta modules learn from the same stimuli; their weights are state (Delta.state).
MODEL = """<group name="Learn">
    <module class="Constant" name="CS" data="1, 0.5"/>
    <module class="Constant" name="US" data="10"/>
    <module class="Delta" name="A" alpha="0.1"/>
    <module class="Delta" name="B" alpha="0.1"/>
    <connection source="CS.OUTPUT" target="A.CS"/>
    <connection source="US.OUTPUT" target="A.US"/>
    <connection source="CS.OUTPUT" target="B.CS"/>
    <connection source="US.OUTPUT" target="B.US"/>
</group>
"""


def test_state_menu_saves_loads_and_resets_the_selected_module(tmp_path):
    model = tmp_path / "learn.ikg"
    model.write_text(MODEL)

    def cr(server):
        got = server.data("A.CR", "B.CR")["data"]
        return got["A.CR"][0], got["B.CR"][0]

    def state_item(page, item, label):
        page.click("#state-menu > summary")
        assert page.inner_text(f"#{item}") == label
        page.click(f"#{item}")

    def message(page, text):
        page.wait_for_function("(t) => document.body.innerText.includes(t)", arg=text)

    def check(server, page):
        assert server.step(4) == 4
        saved = cr(server)
        assert saved[0] == saved[1] > 0                      # both have learned alike
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.locator("#editor-host g.box-group[data-name='A'] rect.box").click()

        state_item(page, "state-save", "Save state of A…")
        assert page.input_value("#state-file") == "learn.A.state"
        page.click("#dialog-ok")
        message(page, "saved the state of A to learn.A.state (tick 4)")
        data = json.loads((tmp_path / "learn.A.state").read_text())
        assert data["scope"] == "A" and data["tick"] == 4
        assert sorted(data["items"]) == ["A.CR", "A.weights"]

        server.step(1)
        next_cr = cr(server)[0]
        assert server.step(2) == 7
        changed = cr(server)
        assert changed[0] == changed[1] != saved[0]

        state_item(page, "state-load", "Load state into A…")
        page.fill("#state-file", "learn.A.state")
        page.click("#dialog-ok")
        message(page, "loaded the state of A from learn.A.state (tick 7)")
        assert server.tick() == 7                            # a module's state leaves the tick
        assert cr(server) == (saved[0], changed[1])          # A is back; B goes on
        server.step(1)
        assert cr(server)[0] == next_cr                      # and so are A's weights

        state_item(page, "state-reset", "Reset state of A")
        message(page, "reset the state of A (tick 8)")
        after_reset = cr(server)
        assert after_reset[0] == 0 and after_reset[1] != 0
        server.step(1)
        assert cr(server)[0] == 0                           # weights zero: CR = CS . w = 0
        page.screenshot(path=str(tmp_path / "state-menu.png"))

        page.locator("#editor-host svg.network-view").click(position={"x": 3, "y": 3})
        page.click("#state-menu > summary")
        assert page.inner_text("#state-save") == "Save state…"   # nothing selected: the model
        page.click("#state-menu > summary")
        page.on("dialog", lambda d: d.accept())
        state_item(page, "quit", "Quit")
        assert server.proc.wait(15) == 0
        end = json.loads((tmp_path / "learn.state").read_text())   # -W: saved at the end
        assert end["scope"] == "network" and end["tick"] == 9
        assert end["items"]["B.weights"]["value"] != [0, 0]
        assert end["items"]["A.weights"]["value"] != end["items"]["B.weights"]["value"]

    in_own_browser(str(model), lambda s, p: None, check, options=("-W",))
