#!/usr/bin/env bash
# Builds the wheel `ekb` (SPEC §13) into target/wheels: the `ekb` executable in the wheel's
# scripts (pip, pipx and `uv tool install` put it on PATH, as ruff's wheel does) and the
# module `import ekb` (crates/ekb-python). Both come from one release build in the shared
# target/, stripped as they go in; the Debian package takes the same executable
# (scripts/build-deb.sh).
#
#   scripts/build-wheel.sh        # prints the wheel's path
#
# Needs maturin (`pip install maturin`; installed in target/build-venv when missing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

maturin=$(command -v maturin || true)
if [ -z "$maturin" ]; then
  [ -x target/build-venv/bin/maturin ] || {
    python3 -m venv target/build-venv
    target/build-venv/bin/pip install --quiet --disable-pip-version-check 'maturin>=1.9,<2'
  }
  maturin=target/build-venv/bin/maturin
fi

# With ekb-python in the same build, its dependencies' features are those of maturin's build
# below, which then reuses the compiled library instead of compiling it again; with the same
# packages as scripts/build-deb.sh, which then builds nothing again.
cargo build --quiet --locked --release -p ekb -p ekb-python -p ekb-capi --bin ekb --lib
# What maturin lays in the wheel's .data (pyproject.toml: `data`): the executable in scripts/,
# and in data/ (the environment's own root once installed) the man page and the
# documentation, laid out as the Debian package lays them (share/doc/ekb).
rm -rf target/wheel-data
mkdir -p target/wheel-data/scripts target/wheel-data/data/share/man/man1
strip -o target/wheel-data/scripts/ekb target/release/ekb
target/release/ekb man >target/wheel-data/data/share/man/man1/ekb.1
doc=target/wheel-data/data/share/doc/ekb
mkdir -p "$doc/docs/images" "$doc/editors/vscode"
cp README.md CHANGELOG.md ARCHITECTURE.md BENCHMARKS.md "$doc/"
cp docs/*.md "$doc/docs/"
cp docs/images/*.png "$doc/docs/images/"
cp editors/README.md "$doc/editors/"
cp editors/vscode/README.md "$doc/editors/vscode/"
"$maturin" build --quiet --locked --release --strip -m crates/ekb-python/Cargo.toml \
  --out target/wheels >&2
version=$(target/release/ekb --version | awk '{ print $2 }')
ls "$root"/target/wheels/ekb-"$version"-*.whl
