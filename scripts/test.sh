#!/usr/bin/env bash
# Install what the tests need and run them all: a virtual environment with the package and
# its test extras, and Debian's Chromium for the browser tests (installed when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x /usr/bin/chromium ]; then
    SUDO=""
    [ "$(id -u)" = 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq chromium
fi
python3 -m venv .venv
. .venv/bin/activate
pip install -q -e '.[test]'
python -m pytest -q "$@"
