#!/usr/bin/env bash
# Instructions executed by one `ekb check`, counted by cachegrind: the same every run,
# so that a change of 1% shows, where timings on this machine move by 10-20%.
#
#   scripts/instructions.sh [FILE] [EKB]
#
# FILE defaults to a generated knowledge base of 10,000 locations, EKB to the release
# binary (the file is made by the ekb-generate example). The check runs on one core
# (taskset). Needs valgrind.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
ekb="${2:-$root/target/release/ekb}"
if [ -z "${2:-}" ]; then
  cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ekb --example ekb-generate
fi
file="${1:-}"
if [ -z "$file" ]; then
  file="$(mktemp)"
  trap 'rm -f "$file"' EXIT
  "$root/target/release/examples/ekb-generate" 10000 > "$file"
fi
taskset -c 0 valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
  "$ekb" check --format concise "$file" 2>&1 >/dev/null | awk '/I *refs/ { print $NF }'
