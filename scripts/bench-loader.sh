#!/usr/bin/env bash
# Loading through the C++ API in process (SPEC §12; a benchmark, not a test): the seed file
# (fixed with `ekb fix`) and generated files of 1k, 10k and 100k locations in ascending id
# order. Prints, per file: its size, the best and median load time, and the peak resident
# memory of the process before the first load and after. Release build (cargo's release
# profile, through CMake).
#
# The generated files in ascending id order would crash the robot's own reader (SPEC §2.10),
# and `ekb check` says so (compat-reader-crash): a robot that loads through ekb has no such
# tree, so an ekb.toml beside them ignores that rule and compat-slow-load.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-$PWD/target}
work=${EKB_BENCH_DIR:-$(mktemp -d)}
repeats=${EKB_BENCH_REPEATS:-10}
cmake -S crates/ekb-capi -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DEKB_BUILD_TESTS=OFF \
  -DEKB_BUILD_BENCHMARK=ON >/dev/null
cmake --build "$work/build" -j2 >/dev/null
cargo build --release --quiet --bin ekb --example ekb-generate
mkdir -p "$work/files"
cp data/environmentKnowledgeBaseInput.dat "$work/files/seed.dat"
"$target/release/ekb" fix --isolated "$work/files/seed.dat" >/dev/null 2>&1
printf '[check]\nignore = ["compat-reader-crash", "compat-slow-load"]\n' >"$work/files/ekb.toml"
for n in 1000 10000 100000; do
  "$target/release/examples/ekb-generate" "$n" >"$work/files/ascending-$n.dat"
done
for file in seed ascending-1000 ascending-10000 ascending-100000; do
  path=$work/files/$file.dat
  printf '%s bytes\t' "$(stat -c %s "$path")"
  "$work/build/ekb-load-benchmark" "$path" "$repeats"
done
