#!/usr/bin/env bash
# Time and peak memory of every command on hostile inputs (huge values, a huge tour, huge files),
# each against `ekb check` of the same file, measured back to back.
#
#   scripts/bench-hostile.sh [WORKDIR]
#
# Generates, in WORKDIR (default: a new folder under /tmp; nothing is committed):
#   msg-1mb.dat      the real file with location 1's first English message 1 MB long
#   msg-50mb.dat     the same, 50 MB
#   desc-50mb.dat    the real file with location 1's description 50 MB long
#   tour-1m.dat      the real file with a tour of 1,000,000 stops (2 MB on one line)
#   lines-528mb.dat  the real file, then 88 million short lines (`k 1 v`, 6 bytes: an
#                    entry of location 1 each, with an unknown key): 528 MB
#   miscased-1m.dat  1,000,000 lines `robotlocationdescription 1 Roomba` (a miscased key
#                    each, for `fix`) and a tour: 34 MB
# Then, for each command on the inputs of the issue, runs `ekb check FILE` and the command
# one after the other RUNS times (default 3; hyperfine -N, output to /dev/null), and takes
# each one's median wall time and mean CPU time (user + system: less moved by other work on
# the machine); and measures each one's peak resident memory with /usr/bin/time -v. It
# prints the command's times as ratios to the check's (target ≤ 10×) and its peak as a
# ratio to the file's size (target ≤ 3×), both whole and less the same command's peak on the
# 46-line real file (what the program's own code and libraries take, about 6-7 MB, which no
# file of 1 MB can be within 3× of: the last column is what the file costs). Commands that write (`fmt`, `fix`) write a copy
# of the file, made before each run (hyperfine --prepare; not timed).
# Needs hyperfine (Debian: apt-get install hyperfine).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-$(mktemp -d /tmp/ekb-hostile.XXXXXX)}"
mkdir -p "$work"
runs="${RUNS:-3}"

cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ekb
ekb="$root/target/release/ekb"
base="$root/data/environmentKnowledgeBaseInput.dat"

# The real file with the value of the first line of `key` and id 1 replaced by `bytes`
# bytes of words.
with_long_value() { # key bytes out
  python3 - "$base" "$1" "$2" "$3" <<'EOF'
import re, sys
base, key, size, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
text = open(base).read()
words = ("the robot greets every visitor " * (size // 31 + 1))[:size].rstrip()
line = re.compile(r"^(" + key + r" +1 ).*$", re.M)
open(out, "w").write(line.sub(lambda m: m.group(1) + words, text, count=1))
EOF
}

# `line`, `count` times. (`yes` ends on SIGPIPE once `head` has enough: under pipefail that
# would end the script, and leave the file being written cut short.)
repeated() { # line count
  (set +o pipefail; yes "$1" | head -n "$2")
}

[ -f "$work/msg-1mb.dat" ] || with_long_value preGestureMessageEnglish 1000000 "$work/msg-1mb.dat"
[ -f "$work/msg-50mb.dat" ] || with_long_value preGestureMessageEnglish 50000000 "$work/msg-50mb.dat"
[ -f "$work/desc-50mb.dat" ] || with_long_value robotLocationDescription 50000000 "$work/desc-50mb.dat"
if [ ! -f "$work/tour-1m.dat" ]; then
  { grep -v '^tourSpecification' "$base"
    printf 'tourSpecification 1000000'
    # Ids 1 to 5 (the file's five locations) over and over.
    repeated ' 1 2 3 4 5' 200000 | tr -d '\n'
    printf '\n'
  } > "$work/tour-1m.dat.new" && mv "$work/tour-1m.dat.new" "$work/tour-1m.dat"
fi
if [ ! -f "$work/lines-528mb.dat" ]; then
  { cat "$base"; repeated 'k 1 v' 88000000; } > "$work/lines-528mb.dat.new" &&
    mv "$work/lines-528mb.dat.new" "$work/lines-528mb.dat"
fi
if [ ! -f "$work/miscased-1m.dat" ]; then
  { repeated 'robotlocationdescription 1 Roomba' 1000000
    echo 'tourSpecification 1 1'
  } > "$work/miscased-1m.dat.new" && mv "$work/miscased-1m.dat.new" "$work/miscased-1m.dat"
fi

# name|file|command (the file is appended)
cases=(
  "show 1|msg-1mb.dat|show 1"
  "show 1|msg-50mb.dat|show 1"
  "locations|msg-50mb.dat|locations"
  "show 1|desc-50mb.dat|show 1"
  "locations|desc-50mb.dat|locations"
  "tour|desc-50mb.dat|tour"
  "locations|tour-1m.dat|locations"
  "tour|tour-1m.dat|tour"
  "show 1|tour-1m.dat|show 1"
  "diff A A|tour-1m.dat|diff FILE"
  "fmt|lines-528mb.dat|fmt"
  "fix|miscased-1m.dat|fix"
)

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC'), load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "ekb:     $("$ekb" --version), commit $(git -C "$root" rev-parse --short HEAD)"
echo

peak_kb() { # the command (findings and refusals are not failures here)
  { /usr/bin/time -v "$@" 2>&1 >/dev/null || true; } |
    awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }'
}

# The command line of a case on `file`; `fmt` and `fix` work on a copy.
command_line() { # command file
  local command="$1" file="$2"
  case "$command" in
    "diff FILE") echo "$ekb diff $file $file" ;;
    fmt | fix) echo "$ekb $command $work/copy.dat" ;;
    *) echo "$ekb $command $file" ;;
  esac
}

# The peak of a case's command on `file` (a copy of it for `fmt` and `fix`).
command_peak() { # command file
  case "$1" in fmt | fix) cp "$2" "$work/copy.dat" ;; esac
  # shellcheck disable=SC2046 # the command is split into its words on purpose
  peak_kb $(command_line "$1" "$2")
}

printf '| command | file | size | check: median, CPU | command: median, CPU | / check: wall, CPU | check peak | peak | / size | peak on the real file | (peak − that) / size |\n'
printf '|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n'
for entry in "${cases[@]}"; do
  IFS='|' read -r name file command <<< "$entry"
  path="$work/$file"
  size=$(stat -c %s "$path")
  line=$(command_line "$command" "$path")
  prepare=()
  case "$command" in fmt | fix) prepare=(--prepare "cp $path $work/copy.dat") ;; esac
  # Back to back, in one hyperfine run; -i: findings exit 1.
  hyperfine -N -i --runs "$runs" --export-csv "$work/case.csv" "${prepare[@]}" \
    "$ekb check $path" "$line" > /dev/null 2>&1
  # hyperfine's CSV: command,mean,stddev,median,user,system,min,max.
  read -r check_s check_cpu < <(awk -F, 'NR == 2 { print $4, $5 + $6 }' "$work/case.csv")
  read -r command_s command_cpu < <(awk -F, 'NR == 3 { print $4, $5 + $6 }' "$work/case.csv")
  check_peak=$(peak_kb "$ekb" check "$path")
  peak=$(command_peak "$command" "$path")
  floor=$(command_peak "$command" "$base")
  awk -v n="$name" -v f="$file" -v s="$size" -v c="$check_s" -v cc="$check_cpu" \
      -v t="$command_s" -v tc="$command_cpu" -v cp="$check_peak" -v p="$peak" -v b="$floor" 'BEGIN {
    printf "| `%s` | %s | %.1f MB | %.2f s, %.2f s | %.2f s, %.2f s | %.1f×, %.1f× | %.0f MB | %.1f MB | %.2f× | %.1f MB | %.2f× |\n",
      n, f, s / 1e6, c, cc, t, tc, t / c, tc / cc, cp * 1024 / 1e6, p * 1024 / 1e6, p * 1024 / s,
      b * 1024 / 1e6, (p - b) * 1024 / s }'
done
rm -f "$work/copy.dat" "$work/case.csv"
