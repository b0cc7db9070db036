"""Every description of every class is shown the same way (issue 37, item 7: ``**linear**``
of ColorTransform and ``**of the previous tick**`` of WilsonCowan showed their asterisks in
the class list and tooltips): the page's renderer (static/describe.js) turns the inline
Markdown the module reference renders (code, strong, emphasis) into elements and leaves no
mark in the text; the tooltip text is the same words. Checked in a real headless Chromium
over /api/classes."""
from __future__ import annotations

import os

from browsing import ROOT, in_own_browser

MODEL = os.path.join(ROOT, "examples", "hello.ikg")

RENDERED = """async () => {
    const { describe, plainText } = await import('/static/describe.js');
    const classes = await (await fetch('/api/classes')).json();
    const found = {problems: [], strong: [], em: [], code: 0, texts: 0, classes: 0};
    const mark = /`|\\*\\*|(^|[\\s(])\\*[^\\s*][^*]*[^\\s*]\\*(?=$|[\\s.,;:)])/;
    for (const [name, c] of Object.entries(classes)) {
        found.classes++;
        const texts = [['class', c.description], ...(c.parameters || []).map((p) => [p.name, p.description]),
            ...(c.inputs || []).map((p) => [p.name, p.description]), ...(c.outputs || []).map((p) => [p.name, p.description])];
        for (const [where, text] of texts) {
            if (!text) continue;
            found.texts++;
            const el = document.createElement('div');
            el.append(...describe(text));
            const shown = el.textContent;
            if (mark.test(shown)) found.problems.push([name, where, 'shown', shown.match(mark)[0], shown.slice(0, 80)]);
            if (mark.test(plainText(text))) found.problems.push([name, where, 'tooltip', plainText(text).slice(0, 80)]);
            if (shown !== plainText(text)) found.problems.push([name, where, 'differs']);
            el.querySelectorAll('strong').forEach((s) => found.strong.push([name, s.textContent]));
            el.querySelectorAll('em').forEach((s) => found.em.push([name, s.textContent]));
            found.code += el.querySelectorAll('code').length;
        }
    }
    return found;
}"""


def test_every_class_description_is_rendered_without_raw_marks():
    def check(server, page):
        found = page.evaluate(RENDERED)
        assert found["classes"] >= 200 and found["texts"] > 2000, found
        assert found["problems"] == [], found["problems"][:10]
        assert ["ColorTransform", "linear"] in found["strong"], found["strong"]
        assert ["WilsonCowan", "of the previous tick"] in found["strong"], found["strong"]
        assert ["MotionRecorder", "record"] in found["em"], found["em"]
        assert found["code"] > 1000
        assert not page.errors, page.errors

    in_own_browser(MODEL, lambda s, p: None, check)
