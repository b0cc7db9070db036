#!/usr/bin/env bash
# Install what the tests need and run them all: a virtual environment of their own
# (.venv-test: the README's demo step makes .venv, and a server running from it keeps its
# files) with the package and its test extras, and Debian's Chromium for the browser tests
# (installed when missing). Arguments go to pytest; the 25 slowest tests are listed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x /usr/bin/chromium ]; then
    SUDO=""
    [ "$(id -u)" = 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq chromium
fi
python3 -m venv .venv-test
. .venv-test/bin/activate
# --no-compile: no bytecode for every file of every dependency now (two minutes of the
# install); Python compiles what the tests import as they import it
pip install -q --no-compile -e '.[test]'
python -m pytest -q --durations=25 "$@"
