"""An MkDocs hook that keeps the links of docs/ working on the site as they work on the
repository page: headings get GitHub's anchors, links to docs/modules.md (the one-file
module reference, left out of the site) point at the class pages, and links out of docs/
to the README, CONTRIBUTING.md and benchmarks/README.md at their pages on the site."""
import posixpath
import re

_MODULES = re.compile(r"\]\((?:\.\./docs/|)modules\.md(?:#(?P<anchor>[^)\s]*))?\)")
_OUTSIDE = {"../README.md": "getting-started.md", "../CONTRIBUTING.md": "contributing.md",
            "../benchmarks/README.md": "benchmarks.md"}
_OUT = re.compile(r"\]\((?P<path>" + "|".join(re.escape(p) for p in _OUTSIDE) +
                  r")(?P<anchor>#[^)\s]*)?\)")
# a[i][j] in a description is an index, not a reference link
_INDEX = re.compile(r"(?<=[\w\])])\[([^\]\[()]*)\](?=\[)")


def github_slug(text: str, separator: str = "-") -> str:
    """The anchor GitHub gives a heading: lower case, punctuation dropped, each space a
    hyphen (not collapsed), so that links written for the repository page work here."""
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", separator)


def on_config(config):
    config.mdx_configs.setdefault("toc", {})["slugify"] = github_slug
    return config


def on_page_markdown(markdown, page, config, files):
    names = {f.src_uri[len("classes/"):-3].lower(): f.src_uri[len("classes/"):-3]
             for f in files if f.src_uri.startswith("classes/") and f.src_uri.endswith(".md")}
    base = posixpath.dirname(page.file.src_uri) or "."

    def class_link(match):
        anchor = match.group("anchor") or ""
        target = f"classes/{names[anchor]}.md" if anchor in names else \
            "classes/index.md" + (f"#{anchor}" if anchor else "")
        return "](" + posixpath.relpath(target, base) + ")"

    def outside(match):
        return "](" + posixpath.relpath(_OUTSIDE[match.group("path")], base) + \
            (match.group("anchor") or "") + ")"
    markdown = _OUT.sub(outside, _MODULES.sub(class_link, markdown))
    if page.file.src_uri.startswith("classes/"):
        markdown = _INDEX.sub(r"\\[\1\\]", markdown)
    return markdown
