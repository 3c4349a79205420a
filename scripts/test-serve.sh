#!/usr/bin/env bash
# `ekb serve` in a real browser (scripts/test-serve.py): Debian's Chromium and ChromeDriver
# (installed by .ci/run), selenium from PyPI in target/serve-venv, axe-core from npm in
# target/serve-npm; the debug build of the shared target/.
#
#   scripts/test-serve.sh
#   EKB_SERVE_SCREENSHOT=docs/images/serve.png scripts/test-serve.sh   # and a screenshot of the page
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
for tool in chromium chromedriver npm; do
  command -v "$tool" >/dev/null || { echo "test-serve: needs $tool (apt-get install chromium chromium-driver npm)" >&2; exit 1; }
done
[ -x target/serve-venv/bin/python ] || python3 -m venv target/serve-venv
target/serve-venv/bin/python -c 'import selenium' 2>/dev/null ||
  target/serve-venv/bin/pip install --quiet --disable-pip-version-check 'selenium>=4.20,<5'
axe=target/serve-npm/node_modules/axe-core/axe.min.js
[ -f "$axe" ] || npm install --silent --no-audit --no-fund --prefix target/serve-npm 'axe-core@4' >/dev/null
cargo build --quiet --locked --bin ekb
target/serve-venv/bin/python scripts/test-serve.py target/debug/ekb "$axe"
