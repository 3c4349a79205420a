#!/usr/bin/env bash
# Builds the Debian package into target/debian with cargo-deb (`[package.metadata.deb]` in
# Cargo.toml): the `ekb` executable of the release build (the one in the wheel, built once:
# scripts/build-wheel.sh), stripped, its man page and the bash, zsh and fish completions, and
# the loader library (crates/ekb-capi) with its headers and CMake package.
#
#   scripts/build-deb.sh          # prints the package's path
#
# Needs cargo-deb (`cargo install cargo-deb`, done here when missing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

command -v cargo-deb >/dev/null || cargo install --quiet --locked cargo-deb
cargo build --quiet --locked --release -p ekb -p ekb-python -p ekb-capi --bin ekb --lib
# The CMake package of an install tree (configured only: the library is built above).
cmake -S crates/ekb-capi -B target/deb-cmake -DEKB_BUILD_TESTS=OFF >/dev/null
# The static library without its line tables (200 MB with them, most of the package).
strip --strip-debug -o target/deb-cmake/libekb_capi.a target/release/libekb_capi.a
mkdir -p target/man
target/release/ekb man > target/man/ekb.1
cargo deb --quiet --locked --no-build --strip -p ekb -o target/debian >&2
version=$(target/release/ekb --version | awk '{ print $2 }')
ls "$root"/target/debian/ekb_"$version"-*.deb
