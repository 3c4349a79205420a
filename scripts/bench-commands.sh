#!/usr/bin/env bash
# Whole-process time and peak memory of every command that reads the 100k file, against
# `ekb check` on the same file (the targets in BENCHMARKS.md).
#
#   scripts/bench-commands.sh [WORKDIR]
#
# Builds the release binaries, generates the 100,000-location file (the ekb-generate example, seed
# dialect, ascending ids) and a copy of it with four values changed (for `diff A B`), times
# each command with hyperfine (all in one run, output to /dev/null), measures peak memory
# with /usr/bin/time -v, and prints each as a ratio to the check's median time and to the
# file's size. Nothing is written: `fmt --check` and `fix --diff` print diffs instead.
# `export --as-loaded` is measured when this ekb has it. RUNS (default 10) runs each.
# Needs hyperfine (Debian: apt-get install hyperfine).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
runs="${RUNS:-10}"

cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ekb --example ekb-generate
ekb="$root/target/release/ekb"
a="$work/kb-100k.dat"
b="$work/kb-100k-changed.dat"
"$root/target/release/examples/ekb-generate" 100000 > "$a"
# Three descriptions and a pose changed.
sed -E 's/^(robotLocationDescription +(500|50000|99999) ).*/\1Changed exhibit description/;
        s/^(robotLocation +77777 ).*/\11.00 2.00 90/' "$a" > "$b"
# The same locations in another order: 100,000 ascending ids crash every version of the
# robot's reader, so `export --as-loaded` refuses the file above; shuffled, it loads.
shuffled="$work/kb-100k-shuffled.dat"
"$root/target/release/examples/ekb-generate" 100000 --shuffle > "$shuffled"
size=$(stat -c %s "$a")
# The configuration is found from the working directory.
cd "$root"

names=(check export locations locations-json tour tour-json diff-same diff-changed fmt-check fix-diff)
commands=(
  "$ekb check $a"
  "$ekb export --allow-errors $a"
  "$ekb locations $a"
  "$ekb locations --format json $a"
  "$ekb tour --lang en $a"
  "$ekb tour --lang en --format json $a"
  "$ekb diff $a $a"
  "$ekb diff $a $b"
  "$ekb fmt --check $a"
  "$ekb fix --diff $a"
)
# Each command is compared with the check of the same file: row 0, or the row named here.
bases=(0 0 0 0 0 0 0 0 0 0)
if "$ekb" export --help | grep -q -- '--as-loaded'; then
  names+=(check-shuffled export-as-loaded)
  commands+=("$ekb check $shuffled" "$ekb export --as-loaded --allow-errors $shuffled")
  bases+=(10 10)
else
  echo "(export --as-loaded: not in this ekb, skipped)"
fi

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC'), load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "ekb:     $("$ekb" --version), commit $(git -C "$root" rev-parse --short HEAD)"
echo "file:    $a, $(awk -v s="$size" 'BEGIN { printf "%.2f MB", s / 1e6 }')"
echo

# One hyperfine run for all, so that they see the same minutes; -i: findings exit 1.
hyperfine -N -i --warmup 1 --runs "$runs" --export-csv "$work/commands.csv" \
  "${commands[@]}" > /dev/null 2>&1

peak_kb() { # the command (which may exit 1: findings are not a failure here)
  { /usr/bin/time -v "$@" 2>&1 >/dev/null || true; } |
    awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }'
}

medians=()
printf '%-18s %10s %10s %10s %9s %10s\n' command median_s mean_s /check peak_MB /size
for i in "${!names[@]}"; do
  # hyperfine's CSV: command,mean,stddev,median,...; one line per command, in order.
  read -r mean median < <(awk -F, -v row=$((i + 2)) 'NR == row { print $2, $4 }' "$work/commands.csv")
  medians[i]=$median
  check_median=${medians[${bases[$i]}]}
  # shellcheck disable=SC2086 # the command is split into its words on purpose
  peak=$(peak_kb ${commands[$i]})
  awk -v n="${names[$i]}" -v m="$median" -v a="$mean" -v c="$check_median" -v p="$peak" -v s="$size" 'BEGIN {
    printf "%-18s %10.3f %10.3f %9.1fx %9.1f %9.2fx\n", n, m, a, m / c, p * 1024 / 1e6, p * 1024 / s }'
done
echo
echo "targets: each command <= 3x the check's time and <= 2x the file's size; files kept in $work"
