"""The documentation site (mkdocs.yml): a strict build (a broken link, a missing page or
anchor fails it), a page per standard class, the Python API from its docstrings, the
benchmark plots, and search in Chromium."""
import functools
import http.server
import os
import re
import subprocess
import sys
import threading
import xml.etree.ElementTree as ET

import pytest

from ikaros.docgen import standard_classes

pytest.importorskip("mkdocs")
pytestmark = pytest.mark.slow

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHROMIUM = "/usr/bin/chromium"
PLOTTED = ("FunctionGenerator", "GaussianFilter")     # a line plot and an image
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    folder = tmp_path_factory.mktemp("site")
    # plots of two classes only: drawing all of them takes minutes (every example is run by
    # tests/test_examples.py; the drawing is the same code for every class)
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1", DISABLE_MKDOCS_2_WARNING="true",
               IKAROS_SITE_PLOTS=",".join(PLOTTED))
    done = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-q", "-d",
                           str(folder)], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, f"mkdocs build --strict failed:\n{done.stderr[-3000:]}"
    return folder


def _page(site, path: str) -> str:
    with open(os.path.join(site, path), encoding="utf-8") as f:
        return f.read()


def test_every_standard_class_has_a_page_with_its_ports_and_parameters(site):
    index = _page(site, "classes/index.html")
    missing = []
    for name, desc in standard_classes().items():
        path = os.path.join(site, "classes", f"{name}.html")
        if not os.path.exists(path):
            missing.append(f"{name}: no page")
            continue
        page = _page(site, f"classes/{name}.html")
        for spec in desc.parameters + desc.inputs + desc.outputs:
            if f"<code>{spec.name}</code>" not in page:
                missing.append(f"{name}: {spec.name} not on its page")
        if f'href="{name}.html"' not in index:
            missing.append(f"{name}: not in the class index")
    assert not missing, "\n".join(missing[:20])


def test_a_class_page_shows_its_example_and_a_plot_of_its_outputs(site):
    page = _page(site, "classes/FunctionGenerator.html")
    assert "examples/modules/FunctionGenerator_example.ikg" in page
    for name in PLOTTED:
        assert f'src="images/{name}.svg"' in _page(site, f"classes/{name}.html"), name
        ET.parse(os.path.join(site, "classes", "images", f"{name}.svg"))
    # the dialect differences of docs/language.md's tables that name the class
    assert "Ikaros 2, Ikaros 3 and this project" in page


def test_the_python_api_comes_from_the_docstrings(site):
    page = _page(site, "api.html")
    for name in ("ikaros.load", "ikaros.Network", "ikaros.Group", "ikaros.Module",
                 "open_recording", "ikaros.ModelError"):
        assert name in page, name
    # members of the public Network, its own and those it inherits from the kernel's
    for member in ("record", "step", "output", "set_parameter"):
        assert re.search(rf'id="ikaros\.Network\.{member}"', page), member


def test_the_benchmark_figures_are_plotted_beside_their_tables(site):
    page = _page(site, "benchmarks.html")
    plots = re.findall(r'src="(images/bench-[^"]+\.svg)"', page)
    assert any("speedup" in p for p in plots) and any("cpu" in p for p in plots)
    for plot in plots:
        ET.parse(os.path.join(site, plot))


def test_getting_started_is_the_readmes_quick_start(site):
    page = _page(site, "getting-started.html")
    text = re.sub(r"<[^>]+>", "", page)
    assert "pip install '.[web]' &amp;&amp; ikaros examples/demo.ikg" in text
    assert 'href="webui.html"' in page          # README's docs/webui.md, as a site link


def _serve(folder):
    handler = functools.partial(_QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.mark.skipif(not os.path.exists(CHROMIUM), reason="Debian's Chromium is not installed")
def test_search_finds_a_class_by_name_and_by_a_word_of_its_description(site):
    playwright = pytest.importorskip("playwright.sync_api")
    server = _serve(site)
    failure = []

    def search():
        # in a thread of its own: Playwright's sync API cannot start while another test's
        # session Playwright runs in this thread (ikaros/webui/tests/test_browser.py)
        try:
            with playwright.sync_playwright() as p:
                browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
                try:
                    page = browser.new_page()
                    for query, expected in (("PIDController", "classes/PIDController.html"),
                                            ("ticksquare", "classes/FunctionGenerator.html")):
                        page.goto(f"http://127.0.0.1:{server.server_port}/index.html")
                        page.click(".md-search__input", timeout=10_000)
                        page.locator("input.md-search__input").fill(query)
                        link = page.locator(f'.md-search-result a[href*="{expected}"]').first
                        link.wait_for(timeout=20_000)
                finally:
                    browser.close()
        except BaseException as e:      # noqa: BLE001 - handed to the test's thread
            failure.append(e)
    try:
        thread = threading.Thread(target=search, daemon=True)
        thread.start()
        thread.join(timeout=180)
        assert not thread.is_alive(), "the search in Chromium did not end within 180 s"
        if failure:
            raise failure[0]
    finally:
        server.shutdown()
