"""Editors that save one file: a save carries the version of the file its edits were made
from, and a save over another editor's is refused with 409 (never lost without a word);
in the browser the editor says so and offers to reload or overwrite."""
from __future__ import annotations

import shutil
import threading
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

from starlette.testclient import TestClient  # noqa: E402

import ikaros  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = '<group name="E"><module class="Constant" name="C" data="1 2"/></group>\n'


@pytest.fixture
def client(tmp_path):
    (tmp_path / "e.ikg").write_text(MODEL)
    net = ikaros.load(str(tmp_path / "e.ikg"))
    with TestClient(create_app(net, models_dir=str(tmp_path))) as c:
        yield c
    net.close()


def edited(tree: dict, mark: str) -> dict:
    return {**tree, "attrs": {**tree["attrs"], "edited_by": mark}}


def test_a_save_over_another_editor_s_save_is_409_and_overwrites_only_when_asked(
        client, tmp_path):
    loaded = client.get("/api/model").json()
    a, b = loaded["version"], loaded["version"]      # two editors load the file
    assert isinstance(a, str)
    first = client.post("/api/save", json={"tree": edited(loaded["tree"], "A"),
                                           "version": a})
    assert first.status_code == 200
    a = first.json()["version"]
    assert a != b
    refused = client.post("/api/save", json={"tree": edited(loaded["tree"], "B"),
                                             "version": b})
    assert refused.status_code == 409
    assert refused.json() == {"error": "e.ikg was saved by another editor (or changed on "
                                       "disk) since these edits began", "version": a}
    assert 'edited_by="A"' in (tmp_path / "e.ikg").read_text()     # A's save is kept
    again = client.post("/api/save", json={"tree": edited(loaded["tree"], "B"),
                                           "version": refused.json()["version"]})
    assert again.status_code == 200                 # B chose to overwrite
    assert 'edited_by="B"' in (tmp_path / "e.ikg").read_text()
    assert client.get("/api/model").json()["version"] == again.json()["version"]
    (tmp_path / "e.ikg").write_text(MODEL.replace("1 2", "3 4"))     # edited on disk
    assert client.post("/api/save", json={"tree": loaded["tree"], "version": again.json()[
        "version"]}).status_code == 409
    # a save without a version writes as told (scripts); a bad version is 400
    assert client.post("/api/save", json={"tree": loaded["tree"]}).status_code == 200
    assert client.post("/api/save", json={"tree": loaded["tree"],
                                          "version": 3}).status_code == 400


def test_eight_editors_saving_at_once_from_one_version_one_wins_and_seven_hear_409(
        client, tmp_path):
    loaded = client.get("/api/model").json()
    answers = [None] * 8

    def editor(k):
        answers[k] = client.post("/api/save", json={"tree": edited(loaded["tree"], f"E{k}"),
                                                    "version": loaded["version"]})
    threads = [threading.Thread(target=editor, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(60)
    codes = sorted(a.status_code for a in answers)
    assert codes == [200] + [409] * 7
    winner = next(k for k, a in enumerate(answers) if a.status_code == 200)
    assert f'edited_by="E{winner}"' in (tmp_path / "e.ikg").read_text()
    assert {a.json()["version"] for a in answers} == {answers[winner].json()["version"]}


def test_the_editor_says_so_and_offers_to_reload_or_overwrite(tmp_path):
    pytest.importorskip("playwright")
    from test_editor_browser import ADD_EXAMPLE, box, in_browser, wait_boxes
    shutil.copy(ADD_EXAMPLE, tmp_path / "add.ikg")

    def other_editor_saves(server, mark):
        model = server.get("/api/model")
        server.post("/api/save", {"tree": edited(model["tree"], mark),
                                  "version": model["version"]})

    def check(server, page):
        wait_boxes(page, ["Ramp", "Offset", "Add"])
        box(page, "Ramp").click()
        page.keyboard.press("Delete")
        other_editor_saves(server, "other")
        page.click("#ed-save")
        page.wait_for_selector("#conflict-overwrite")
        assert "saved by another editor" in page.inner_text(".editor-dialog")
        assert "Not saved" in page.inner_text("#editor-status")
        page.click("#conflict-overwrite")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent"
                               ".includes('Saved add.ikg')")
        text = (tmp_path / "add.ikg").read_text()
        assert 'name="Ramp"' not in text and "edited_by" not in text       # overwritten

        box(page, "Offset").click()
        page.keyboard.press("Delete")
        other_editor_saves(server, "again")
        page.click("#ed-save")
        page.click("#conflict-reload")
        wait_boxes(page, ["Offset"])                 # the file as the other editor saved it
        assert 'edited_by="again"' in (tmp_path / "add.ikg").read_text()
        page.click("#ed-save")                      # from the reloaded version: no conflict
        page.wait_for_function("() => document.querySelector('#editor-status').textContent"
                               ".includes('Saved add.ikg')")

    in_browser(str(tmp_path / "add.ikg"), check)
