#!/usr/bin/env bash
# The loader's weight (a benchmark, not a test; BENCHMARKS.md, "The loader's weight"): the
# smallest C program on ekb.h (crates/ekb-capi/bench/smallest.c: open a file, print its
# tour), linked through CMake against ekb::ekb from a release build, and the Python
# extension module, each stripped, in bytes; and that the program prints the seed file's
# tour once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-$PWD/target}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S crates/ekb-capi -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DEKB_BUILD_TESTS=OFF \
  -DEKB_BUILD_BENCHMARK=ON >/dev/null
cmake --build "$work/build" -j2 --target ekb-smallest >/dev/null
cargo build --release --quiet -p ekb-python --lib
cargo build --release --quiet --bin ekb
strip -o "$work/smallest" "$work/build/ekb-smallest"
strip -o "$work/_ekb.so" "$target/release/lib_ekb.so"
cp data/environmentKnowledgeBaseInput.dat "$work/seed.dat"
"$target/release/ekb" fix --isolated "$work/seed.dat" >/dev/null 2>&1 || true
tour=$("$work/smallest" "$work/seed.dat" | tr '\n' ' ')
[ "$tour" = "1 4 3 2 5 " ] || { echo "bench-loader-size: the program printed the tour '$tour'" >&2; exit 1; }
printf 'smallest C program on ekb.h, stripped\t%s bytes\n' "$(stat -c %s "$work/smallest")"
printf 'Python extension module, stripped\t%s bytes\n' "$(stat -c %s "$work/_ekb.so")"
