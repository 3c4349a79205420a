#!/usr/bin/env bash
# What inputs of 10 MB or less cost, in every command: wall time and peak memory, each input
# against the goal (no input of 10 MB or less costs more than 1 s or 200 MB), and two large
# files (100 MB) for the rewriting commands.
#
#   scripts/bench-costs.sh [WORKDIR]
#
# Generates, in WORKDIR (default: a new folder under /tmp; nothing is committed), from the
# real file (data/environmentKnowledgeBaseInput.dat, its key-case error corrected):
#   ignores.dat      100,000 lines `# ekb: ignore[untranslated-message]`, then the file (3.6 MB)
#   paren.dat        the file, then one line of 10,000,000 `(` (10 MB)
#   eacute.dat       the file, then one line of 5,000,000 `é` (10 MB)
#   long-value.dat   the file with location 1's description 10,000,000 `(` (10 MB)
#   tour-1m.dat      the file with a tour of 1,000,000 stops (2 MB)
#   many-50k.dat     50,000 locations with a pose each and a tour (1.7 MB)
#   subtrees.xml     a mission of 30,000 behaviour trees, each the SubTree of the one before
#   paren.xml, eacute.xml   the mission with a 10 MB attribute of `(` and of `é`
#   big-100mb.dat    the file's locations repeated to 100 MB (170,000 locations)
# and runs each command once under /usr/bin/time (stopped after 60 s), printing seconds and
# peak MB, and OVER for a 10 MB-or-less input over the goal. Needs python3.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
work="${1:-$(mktemp -d /tmp/ekb-costs.XXXXXX)}"
mkdir -p "$work"
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ekb
ekb="$root/target/release/ekb"
corpus="$root/tests/fixtures/mission/corpus"

python3 - "$root/data/environmentKnowledgeBaseInput.dat" "$corpus/data/labTour.xml" "$work" <<'PY'
import os, re, sys
base, mission, work = sys.argv[1:]
seed = open(base).read().replace("postGestureMessageenglish", "postGestureMessageEnglish")
def write(name, text):
    path = os.path.join(work, name)
    if not os.path.exists(path):
        open(path, "w").write(text)
write("ignores.dat", "# ekb: ignore[untranslated-message]\n" * 100_000 + seed)
write("paren.dat", seed + "(" * 10_000_000 + "\n")
write("eacute.dat", seed + "\u00e9" * 5_000_000 + "\n")
write("long-value.dat", re.sub(r"^(robotLocationDescription +1 ).*$", lambda m: m.group(1) + "(" * 10_000_000, seed, count=1, flags=re.M))
no_tour = "".join(l for l in seed.splitlines(True) if not l.startswith("tourSpecification"))
write("tour-1m.dat", no_tour + "tourSpecification 1000000" + " 1 2 3 4 5" * 200_000 + "\n")
many = "".join(f"robotLocationPose {i} {i % 97 / 10:.1f} {i % 89 / 10:.1f} 0\n" for i in range(1, 50_001))
write("many-50k.dat", many + "tourSpecification 20 " + " ".join(str(i) for i in range(1, 21)) + "\n")
trees = "".join(f'  <BehaviorTree ID="T{i}"><SubTree ID="T{i + 1}"/></BehaviorTree>\n' for i in range(30_000))
write("subtrees.xml", '<?xml version="1.0"?>\n<root BTCPP_format="4" main_tree_to_execute="T0">\n' + trees + '  <BehaviorTree ID="T30000"><AlwaysSuccess/></BehaviorTree>\n</root>\n')
xml = open(mission).read()
write("paren.xml", xml.replace('<SetSpeechEvent name="false"/>', '<SetSpeechEvent name="' + "(" * 10_000_000 + '"/>', 1))
write("eacute.xml", xml.replace('<SetSpeechEvent name="false"/>', '<SetSpeechEvent name="' + "\u00e9" * 5_000_000 + '"/>', 1))
if not os.path.exists(os.path.join(work, "big-100mb.dat")):
    blocks = re.split(r"\n(?=robotLocationDescription)", no_tour.strip() + "\n")
    big, size, copies = [], 0, 0
    while size < 100_000_000:
        for block in blocks:
            copies += 1
            big.append(re.sub(r"^(\S+ +)\d+", lambda m: m.group(1) + str(copies), block, flags=re.M) + "\n\n")
            size += len(big[-1])
    write("big-100mb.dat", "".join(big))
PY

# A PO file of the real file's isiZulu, every message translated, for `import --po`.
po_of() { # kb out
  "$ekb" -q export --format po --lang zu "$1" -o "$2" --isolated 2>/dev/null || true
  python3 - "$2" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
open(sys.argv[1], "w").write(re.sub(r'msgid "(.*)"\nmsgstr ""', lambda m: f'msgid "{m.group(1)}"\nmsgstr "Zu {m.group(1)}"', text))
PY
}

printf '%-16s %-34s %8s %8s\n' input command seconds MB
measure() { # input command...
  local input=$1; shift
  local size; size=$(stat -c %s "$work/$input")
  local copy="$work/copy-$input"
  cp "$work/$input" "$copy"
  local args=("${@//FILE/$copy}")
  # At most a minute each (the time is then the minute: over the goal).
  /usr/bin/time -o "$work/time" -f '%e %M' timeout 60 "$ekb" --isolated "${args[@]}" \
    >/dev/null 2>&1 || true
  local out; out=$(tail -1 "$work/time")
  local seconds=${out% *} kb=${out#* }
  local mb=$((kb / 1024)) flag=""
  if [ "$size" -le 10500000 ] && { [ "$mb" -gt 200 ] || awk -v s="$seconds" 'BEGIN { exit !(s > 1) }'; }; then
    flag=OVER
  fi
  printf '%-16s %-34s %8s %8s %s\n' "$input" "${*//FILE/F}" "$seconds" "$mb" "$flag"
  rm -f "$copy"
}

for input in ignores.dat paren.dat eacute.dat long-value.dat tour-1m.dat many-50k.dat big-100mb.dat; do
  for command in "check FILE" "fmt --check FILE" "fix --diff FILE" "locations FILE" "show 1 FILE" \
    "tour FILE" "export --allow-errors FILE" "translations FILE" "report -o $work/r.html FILE" \
    "map -o $work/m.svg FILE" "map -o $work/m.png FILE" "diff FILE FILE" \
    "set 1 preGestureMessageIsiZulu Sawubona FILE"; do
    # shellcheck disable=SC2086
    measure "$input" $command
  done
  po_of "$work/$input" "$work/zu.po"
  measure "$input" import --po "$work/zu.po" FILE
done
for input in subtrees.xml paren.xml eacute.xml; do
  measure "$input" mission check --mission FILE --kb "$corpus/data/environmentKnowledgeBaseInput.dat" \
    --culture-kb "$corpus/data/cultureKnowledgeBaseInput.dat" \
    --culture-types "$corpus/data/cultureKnowledgeValueTypesInput.dat"
  measure "$input" mission tree --mission FILE
done
