"""Run by mkdocs-gen-files at every build of the site (mkdocs.yml): adds the generated pages
to the ones in docs/."""
import os
import sys
import tempfile

import mkdocs_gen_files

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from api_page import api_page  # noqa: E402
from class_pages import class_pages  # noqa: E402
from repo_pages import benchmarks, contributing, getting_started  # noqa: E402


def _write(path: str, text: str) -> None:
    with mkdocs_gen_files.open(path, "w") as f:
        f.write(text)


def _copy_images(folder: str, into: str) -> None:
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as src, \
                mkdocs_gen_files.open(f"{into}/{name}", "wb") as dst:
            dst.write(src.read())


with tempfile.TemporaryDirectory() as images:
    for name, text in class_pages(images).items():
        _write(f"classes/{name}", text)
    _copy_images(images, "classes/images")
with tempfile.TemporaryDirectory() as images:
    _write("benchmarks.md", benchmarks(images))
    _copy_images(images, "images")
_write("getting-started.md", getting_started())
_write("contributing.md", contributing())
_write("api.md", api_page())
