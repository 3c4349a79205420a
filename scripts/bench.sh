#!/usr/bin/env bash
# Whole-process benchmark of `ekb check` against `wc -l` on the same files, and peak memory.
#
#   scripts/bench.sh [WORKDIR]
#
# Builds the release binaries, generates knowledge bases of 10,000 and 100,000 locations
# (the ekb-generate example), times `ekb check` and `wc -l` on each with hyperfine (side by side, in
# one run), measures peak memory with /usr/bin/time -v, and prints a table with the
# targets of BENCHMARKS.md. Needs hyperfine (Debian: apt-get install hyperfine).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
runs="${RUNS:-10}"

cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ekb --example ekb-generate
ekb="$root/target/release/ekb"
gen="$root/target/release/examples/ekb-generate"

"$gen" 10000 > "$work/kb-10k.dat"
"$gen" 100000 > "$work/kb-100k.dat"
"$gen" 100000 --dialect current --shuffle > "$work/kb-100k-current-shuffled.dat"
cp "$root/data/environmentKnowledgeBaseInput.dat" "$work/kb-real-46-lines.dat"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC'), load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "ekb:     $("$ekb" --version)"
echo

# mean and median whole-process seconds of a command, from hyperfine's CSV.
time_of() { # name, then the command
  local name="$1"; shift
  # -i: the real file has errors, so `ekb check` exits 1 on it.
  hyperfine -N -i --warmup 2 --runs "$runs" --export-csv "$work/$name.csv" "$*" > /dev/null 2>&1
  awk -F, 'NR == 2 { printf "%.4f %.4f\n", $2, $4 }' "$work/$name.csv"
}

peak_kb() { # the command (which may exit 1: findings are not a failure here)
  { /usr/bin/time -v "$@" 2>&1 >/dev/null || true; } | awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }'
}

# peak: the default (human) format; peak_concise: --format concise, which needs no index of
# the file's lines to cut excerpts from.
printf '%-28s %10s %12s %12s %10s %8s %10s %9s %13s %9s\n' \
  file size_MB check_mean_s check_med_s wc_mean_s ratio peak_MB peak/size peak_concise peak/size
for name in kb-real-46-lines kb-10k kb-100k kb-100k-current-shuffled; do
  file="$work/$name.dat"
  size=$(stat -c %s "$file")
  read -r check_mean check_median < <(time_of "check-$name" "$ekb" check "$file")
  read -r wc_mean _ < <(time_of "wc-$name" wc -l "$file")
  peak=$(peak_kb "$ekb" check "$file")
  peak_concise=$(peak_kb "$ekb" check --format concise "$file")
  awk -v n="$name" -v s="$size" -v c="$check_mean" -v m="$check_median" -v w="$wc_mean" -v p="$peak" -v q="$peak_concise" 'BEGIN {
    printf "%-28s %10.2f %12.4f %12.4f %10.4f %8.1f %10.1f %9.2f %13.1f %9.2f\n",
      n, s / 1e6, c, m, w, c / w, p * 1024 / 1e6, p * 1024 / s, q * 1024 / 1e6, q * 1024 / s }'
  eval "mean_${name//-/_}=$check_mean"
done

echo
awk -v a="$mean_kb_10k" -v b="$mean_kb_100k" 'BEGIN { printf "linearity: 100k / 10k = %.1f (target <= 11)\n", b / a }'
echo "files kept in $work"
