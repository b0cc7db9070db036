"""Ikaros 3's read-only routes /json/<path> and /csv/<path> (webui/compat.py)."""
import warnings

import pytest

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore:.*httpx.*")

MODEL = """<group name="Model">
    <module class="Constant" name="M" data="1 2; 3 4"/>
    <module class="Constant" name="V" data="0.5 1.25 -2"/>
    <module class="Constant" name="T" data="1 2"/>
</group>"""


@pytest.fixture
def client(tmp_path):
    path = tmp_path / "model.ikg"
    path.write_text(MODEL)
    net = ikaros.load(str(path))
    net.run(ticks=1)
    with TestClient(create_app(net)) as c:
        yield c
    net.close()


def test_json_of_outputs_and_parameters(client):
    assert client.get("/json/M.OUTPUT").json() == {
        "path": "M.OUTPUT", "shape": [2, 2], "value": [[1, 2], [3, 4]]}
    # Ikaros 3's forms: the top group's name, or a leading dot
    assert client.get("/json/Model.V.OUTPUT").json()["value"] == [0.5, 1.25, -2]
    assert client.get("/json/.V.OUTPUT").json()["path"] == "V.OUTPUT"
    answer = client.get("/json/T.data").json()
    assert answer == {"path": "T.data", "shape": [2], "value": [1, 2]}


def test_csv_rows(client):
    answer = client.get("/csv/M.OUTPUT")
    assert answer.status_code == 200 and answer.headers["content-type"].startswith("text/csv")
    assert answer.text == "1,2\n3,4\n"
    assert client.get("/csv/Model.V.OUTPUT").text == "0.5,1.25,-2\n"


def test_unknown_paths_and_queries_are_refused(client):
    answer = client.get("/json/Nope.OUTPUT")
    assert answer.status_code == 404
    assert answer.json() == {"error": 'no output, input or parameter "Nope.OUTPUT" in Model'}
    assert client.get("/csv/M.nothing").status_code == 404
    assert client.get("/json/M.OUTPUT?x=1").status_code == 400
    assert client.post("/json/M.OUTPUT").status_code == 405


def test_described_in_openapi(client):
    paths = client.get("/api/openapi.json").json()["paths"]
    assert set(paths["/json/{path}"]) == {"get"} and set(paths["/csv/{path}"]) == {"get"}
