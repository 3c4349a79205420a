#!/usr/bin/env bash
# The loader's weight (a benchmark, not a test; BENCHMARKS.md, "The loader's weight"): the
# smallest C program on ekb.h (crates/ekb-capi/bench/smallest.c: open a file, print its
# tour) linked against the release static library as ekb::ekb links it, and the Python
# extension module, each stripped, in bytes; and that the program prints the seed file's
# tour once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-$PWD/target}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo build --release --quiet -p ekb-capi --lib
cargo build --release --quiet -p ekb-python --lib
cargo build --release --quiet --bin ekb
cc=${CC:-cc}
libs=(-lpthread -ldl -lm -lrt -lutil -lgcc_s)
"$cc" -O2 -Icrates/ekb-capi/include crates/ekb-capi/bench/smallest.c "$target/release/libekb_capi.a" \
  "${libs[@]}" -Wl,--gc-sections -o "$work/smallest"
strip "$work/smallest"
cp data/environmentKnowledgeBaseInput.dat "$work/seed.dat"
"$target/release/ekb" fix --isolated "$work/seed.dat" >/dev/null 2>&1 || true
tour=$("$work/smallest" "$work/seed.dat" | tr '\n' ' ')
[ "$tour" = "1 4 3 2 5 " ] || { echo "bench-loader-size: the program printed the tour '$tour'" >&2; exit 1; }
cp "$target/release/lib_ekb.so" "$work/_ekb.so"
strip "$work/_ekb.so"
printf 'smallest C program, stripped\t%s bytes\n' "$(stat -c %s "$work/smallest")"
printf 'Python extension module, stripped\t%s bytes\n' "$(stat -c %s "$work/_ekb.so")"
printf 'libekb_capi.a, as built\t%s bytes\n' "$(stat -c %s "$target/release/libekb_capi.a")"
