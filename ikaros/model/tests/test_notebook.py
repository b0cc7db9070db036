"""Notebooks: HTML tables, the web UI in a cell, a progress bar, and the example notebook
run top to bottom."""
import os
import re

import httpx
import pytest

import ikaros
from ikaros import notebook

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
NOTEBOOK = os.path.join(ROOT, "examples", "notebooks", "building_models_in_code.ipynb")


def small_model():
    model = ikaros.Group("Small", gain=2)
    c = model.module("Constant", "C", data="1, 2, 3")
    s = model.module("Scale", "S", factor="@gain")
    model.connect(c.OUTPUT, s.INPUT, delay=2)
    return model


def test_a_model_and_a_network_show_themselves_as_tables():
    model = small_model()
    text = model._repr_html_()
    assert "<td style='text-align:left'>S</td><td style='text-align:left'>Scale</td>" in text
    assert "<td style='text-align:left'>C.OUTPUT</td><td style='text-align:left'>S.INPUT</td>" \
           "<td style='text-align:left'>2</td>" in text
    net = model.build()
    text = net._repr_html_()
    assert "<td style='text-align:left'>S</td><td style='text-align:left'>Scale</td>" \
           "<td style='text-align:left'>INPUT 3, SCALE unconnected</td>" \
           "<td style='text-align:left'>OUTPUT 3</td>" in text
    assert "<td style='text-align:left'>C.OUTPUT</td><td style='text-align:left'>S.INPUT</td>" \
           "<td style='text-align:left'>2</td><td style='text-align:left'>3</td>" in text
    assert "tick 0" in text


def test_names_are_escaped_in_tables():
    model = ikaros.Group("M")
    model.module("Constant", "C", data="1", note="<b>")
    assert "note=&lt;b&gt;" in model._repr_html_()


def test_show_serves_the_web_ui_on_the_loopback_until_stopped():
    net = small_model().build()
    net.run(ticks=3)
    view = net.show(height=400)
    try:
        assert view.url.startswith("http://127.0.0.1:")
        assert f'src="{view.url}"' in view._repr_html_() and "height:400px" in \
            view._repr_html_()
        assert net.show() is view                  # one server per network
        status = httpx.get(view.url + "api/status", timeout=10).json()
        assert status["tick"] == 3
        assert "<html" in httpx.get(view.url, timeout=10).text.lower()
    finally:
        view.stop()
    assert not view.running
    with pytest.raises(httpx.ConnectError):
        httpx.get(view.url + "api/status", timeout=2)


def test_showing_a_network_stops_the_servers_of_ended_ones():
    model = small_model()
    net = model.build()
    first = net.show()
    net = net.apply(model)
    second = net.show()
    try:
        assert not first.running and second.running and second is not first
        assert httpx.get(second.url + "api/status", timeout=10).json()["tick"] == 0
    finally:
        second.stop()


def test_run_shows_a_progress_bar_only_in_a_notebook(monkeypatch, capsys):
    net = small_model().build()
    net.run(ticks=5)
    assert "tick" not in capsys.readouterr().err
    monkeypatch.setattr(notebook, "in_notebook", lambda: True)
    assert net.run(ticks=7) == 12
    err = capsys.readouterr().err
    assert "7/7" in err and "tick" in err
    assert net.controller.tick_hooks == []


def test_the_example_notebook_runs_top_to_bottom():
    import nbformat
    from nbclient import NotebookClient
    nb = nbformat.read(NOTEBOOK, as_version=4)
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": os.path.dirname(NOTEBOOK)}}).execute()
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    html = [o["data"]["text/html"] for o in outputs if "text/html" in o.get("data", {})]
    assert any("ikaros network PIDSweep" in h for h in html)
    assert any("ikaros model PIDSweep" in h for h in html)
    assert any("<iframe src=\"http://127.0.0.1:" in h for h in html)
    assert any("image/png" in o.get("data", {}) for o in outputs)
    printed = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    # issue 27, item 9: the progress bar is a widget (ipywidgets is in the notebook extra)
    assert "IProgress not found" not in printed and "TqdmWarning" not in printed, printed
    assert any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in outputs)
    assert re.search(r'Cell In\[\d+\]:2: <module name="PID">: parameter "Kp" of PID: '
                     r'"fast" is not a number', printed), printed
