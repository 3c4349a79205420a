#!/usr/bin/env bash
# The loader for C and C++ end to end (SPEC §12), as CI runs it after `cargo test`:
# - the CMake project (crates/ekb-capi) builds from the source tree, and its CTest passes,
#   plain and under AddressSanitizer;
# - a consumer project finds it with find_package(ekb CONFIG) from that build tree and
#   from an install prefix, and its programs (one written only against the document's
#   appendix A) print the tour of the fixed seed file;
# - the drop-in compiles under its three include spellings (<> and ""), and not below C++17;
# - the document's example (§6), built as it is and with -DSTRING_LENGTH=600, ends on a
#   refused file with the findings, errors first, one fatal line naming the file and
#   `ekb check`, and exit status 1; it finds the configuration in every layout (the
#   document's, the robot's, the 2026-02 example's, EKB_CONFIG) and lists the paths tried
#   when there is none; the 600 build loads a 335-byte message whole, the default refuses it;
# - every C, C++ and CMake snippet of docs/library.md builds against the install prefix;
# - a catkin workspace builds the example node, which refuses the seed file as it is
#   (the key-case finding at line 34) and logs the tour 1, 4, 3, 2, 5 after `ekb fix`, and
#   the package cssr_system (tests/cssr_system: the robot's layout, a global object, no
#   catch), which exits 1 on the seed file, its key-case error before any warning and its
#   last line naming the file and `ekb check`, logs the tour after `ekb fix`, and finds the
#   configuration in each layout of its package.
# Cargo builds into the repository's target/ (or CARGO_TARGET_DIR) with the dev profile,
# so ekb is built once for `cargo test` and this.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
target=${CARGO_TARGET_DIR:-$root/target}
ekb=$target/debug/ekb
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=${EKB_JOBS:-2}

fail() {
  echo "test-loader: $*" >&2
  exit 1
}

step() { echo "== $*"; }

# How a program written for the document's class ended on the seed file ($1: its name, $2:
# its log, $3: its exit status): exit 1, the key-case error at line 34 first (before the
# missing field it causes, and any warning), and a last line that names the file and
# `ekb check`.
expect_refused_seed() {
  local name=$1 log=$2 status=$3
  [ "$status" = 1 ] || { cat "$log"; fail "$name: exit status $status on the seed file, not 1"; }
  ! grep -q 'terminate called' "$log" || { cat "$log"; fail "$name: terminate"; }
  local key_case first_error first_warning last_error
  # (awk, not grep | head: no SIGPIPE under pipefail)
  key_case=$(awk '/environmentKnowledgeBaseInput\.dat:34:1: error\[key-case\]/ { print NR; exit }' "$log")
  first_error=$(awk '/: error\[/ { print NR; exit }' "$log")
  first_warning=$(awk '/: warning\[/ { print NR; exit }' "$log")
  last_error=$(awk '/: error\[/ { line = NR } END { print line }' "$log")
  [ -n "$key_case" ] || { cat "$log"; fail "$name: no key-case error at line 34"; }
  [ "$key_case" = "$first_error" ] || { cat "$log"; fail "$name: the key-case error, the cause, is not the first"; }
  [ -n "$first_warning" ] && [ "$key_case" -lt "$first_warning" ] && [ "$last_error" -lt "$first_warning" ] \
    || { cat "$log"; fail "$name: an error after a warning"; }
  tail -1 "$log" | grep -q 'the environment knowledge base .*environmentKnowledgeBaseInput\.dat was refused (2 errors, [0-9]* warnings): `ekb check .*environmentKnowledgeBaseInput\.dat` shows them, `ekb fix .*environmentKnowledgeBaseInput\.dat` fixes what it can$' \
    || { cat "$log"; fail "$name: the last line: $(tail -1 "$log")"; }
}

# $1 exits 1 with no configuration: its last line lists the three paths it tried under $2.
expect_no_configuration() {
  local name=$1 root=$2 log=$3 status=$4
  [ "$status" = 1 ] || { cat "$log"; fail "$name: exit status $status with no configuration"; }
  local last
  last=$(tail -1 "$log")
  for layout in config behaviorController/config behaviorController/include/utilities/config; do
    case $last in
      *"$root/$layout/environmentKnowledgeBaseConfiguration.ini"*) ;;
      *) cat "$log"; fail "$name: the message does not list $root/$layout: $last" ;;
    esac
  done
  case $last in
    *"no FILE given"* | *"--config"*) fail "$name: the command line's words: $last" ;;
  esac
}

step "CMake project from the source tree, and its tests"
cmake -S crates/ekb-capi -B "$work/build" -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$work/build" -j"$jobs"
ctest --test-dir "$work/build" --output-on-failure

step "the same tests under AddressSanitizer"
cmake -S crates/ekb-capi -B "$work/asan" -DCMAKE_BUILD_TYPE=Debug -DEKB_SANITIZE=ON >/dev/null
cmake --build "$work/asan" -j"$jobs"
ctest --test-dir "$work/asan" --output-on-failure
rm -rf "$work/asan" # a debug build of ekb is large: keep the disk free as we go

step "a consumer, from the build tree and from an install prefix"
cmake --install "$work/build" --prefix "$work/prefix" >/dev/null
cmake -S crates/ekb-capi/tests/consumer -B "$work/consumer-tree" -Dekb_DIR="$work/build" >/dev/null
cmake --build "$work/consumer-tree" -j"$jobs" >/dev/null
cmake -S crates/ekb-capi/tests/consumer -B "$work/consumer-prefix" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer-prefix" -j"$jobs" >/dev/null
grep -q "$work/prefix" "$work/consumer-prefix/CMakeCache.txt" || fail "the consumer did not find the installed package"

step "the drop-in's include spellings, and C++17"
for consumer in consumer-tree consumer-prefix; do
  for spelling in 1 2 3 4 5 6; do
    "$work/$consumer/include_spelling_$spelling" || fail "$consumer: include spelling $spelling"
  done
done
for header in environmentKnowledgeBaseInterface.h ekb.hpp; do
  printf '#include <%s>\nint main() { return 0; }\n' "$header" >"$work/old.cpp"
  if c++ -std=c++14 -fsyntax-only -I"$work/prefix/include" "$work/old.cpp" 2>"$work/err"; then
    fail "$header compiles as C++14"
  fi
  grep -q 'error: #error .*needs C++17 or later' "$work/err" || { cat "$work/err"; fail "$header: no clear #error below C++17"; }
done

mkdir -p "$work/robot/config" "$work/robot/data"
cp data/environmentKnowledgeBaseInput.dat "$work/robot/data/"
printf 'verboseMode   false\nknowledgeBase environmentKnowledgeBaseInput.dat\n' \
  >"$work/robot/config/environmentKnowledgeBaseConfiguration.ini"
seed=$work/robot/data/environmentKnowledgeBaseInput.dat
for consumer in consumer-tree consumer-prefix; do
  bin=$work/$consumer
  # The seed file as it is has two errors: every face refuses it.
  if (cd "$work/robot" && "$bin/appendix_a" >"$work/out" 2>"$work/err"); then
    fail "$consumer: appendix_a loaded the seed file as it is"
  fi
  grep -q ':34:1: error\[key-case\]' "$work/err" || fail "$consumer: no key-case finding at line 34"
  "$bin/cpp_api" "$seed" >"$work/out" && fail "$consumer: cpp_api loaded the seed file as it is"
  grep -q ':34:1: error\[key-case\]' "$work/out" || fail "$consumer: cpp_api: no key-case finding"
  "$bin/c_api" "$seed" >"$work/out" && fail "$consumer: c_api loaded the seed file as it is"
done
"$ekb" fix --isolated "$seed" >/dev/null
expected_tour=$("$ekb" export --isolated "$seed" | python3 -c 'import json,sys; print(" ".join(map(str, json.load(sys.stdin)["tour"])))')
[ "$expected_tour" = "1 4 3 2 5" ] || fail "ekb export's tour is $expected_tour"
for consumer in consumer-tree consumer-prefix; do
  bin=$work/$consumer
  (cd "$work/robot" && "$bin/appendix_a" >"$work/out") || fail "$consumer: appendix_a refused the fixed file"
  head -1 "$work/out" | grep -qx "5 stops: $expected_tour" || fail "$consumer: appendix_a: $(head -1 "$work/out")"
  grep -q "^4 Roomba (5.0, 3.9, 110.0) \[6.80 4.80 0.82\] This is the Roomba / We use it for teaching mobile robotics$" \
    "$work/out" || fail "$consumer: appendix_a: location 4"
  grep -q "^Location 5: Pepper's starting location$" "$work/out" || fail "$consumer: printToScreen"
  [ "$(grep -c '^Location ' "$work/out")" = 5 ] || fail "$consumer: printToScreen prints every location"
  # EKB_CONFIG names the configuration from anywhere.
  (cd / && EKB_CONFIG=$work/robot/config/environmentKnowledgeBaseConfiguration.ini "$bin/appendix_a" >/dev/null) \
    || fail "$consumer: EKB_CONFIG"
  [ "$("$bin/cpp_api" "$seed" | cut -d' ' -f1 | tr '\n' ' ')" = "$expected_tour " ] || fail "$consumer: cpp_api"
  [ "$("$bin/c_api" "$seed" | cut -d' ' -f1 | tr '\n' ' ')" = "$expected_tour " ] || fail "$consumer: c_api"
done

step "the document's example: a refused file, the layouts, the sizes"
for consumer in consumer-tree consumer-prefix; do
  bin=$work/$consumer
  cp data/environmentKnowledgeBaseInput.dat "$seed" # as it is again
  for example in document_example document_example_600; do
    status=0
    (cd "$work/robot" && "$bin/$example" >"$work/out" 2>"$work/err") || status=$?
    expect_refused_seed "$consumer/$example" "$work/err" "$status"
    ! grep -q '^main:' "$work/out" || fail "$consumer/$example: went on with a refused file"
  done
done
cp "$work/err" "$work/document-example.log"
"$ekb" fix --isolated "$seed" >/dev/null
example=$work/consumer-prefix/document_example
# Each layout, from the folder that holds it (the knowledge base beside the config folder).
layouts=$work/layouts
for layout in config behaviorController/config behaviorController/include/utilities/config; do
  rm -rf "$layouts" && mkdir -p "$layouts/$layout" "$layouts/$(dirname "$layout")/data"
  cp "$work/robot/config/environmentKnowledgeBaseConfiguration.ini" "$layouts/$layout/"
  cp "$seed" "$layouts/$(dirname "$layout")/data/"
  (cd "$layouts" && "$example" >"$work/out" 2>"$work/err") || { cat "$work/err"; fail "the layout $layout"; }
  grep -q '^Key  *4 *$' "$work/out" && grep -q '^Pre-Gesture Message English  *This is the Roomba *$' "$work/out" \
    || { cat "$work/out"; fail "the layout $layout: the document's example did not print location 4"; }
done
(cd / && EKB_CONFIG=$work/robot/config/environmentKnowledgeBaseConfiguration.ini "$example" >/dev/null) \
  || fail "the document's example with EKB_CONFIG"
rm -rf "$layouts" && mkdir -p "$layouts"
status=0
(cd "$layouts" && env -u EKB_CONFIG "$example" >"$work/out" 2>"$work/err") || status=$?
expect_no_configuration "the document's example" "$(cd "$layouts" && pwd -P)" "$work/err" "$status"
# A 335-byte message, read by the 2026-04 robot (a 600-byte line buffer): whole under
# -DSTRING_LENGTH=600, refused naming the limit under the document's 200.
long=$(printf 'The robotics lab at Carnegie Mellon University Africa %.0s' 1 2 3 4 5 6 7)
long=${long:0:335}
[ ${#long} = 335 ] || fail "the long message is ${#long} bytes"
mkdir -p "$work/long/config" "$work/long/data"
printf 'verboseMode false\nknowledgeBase environmentKnowledgeBaseInput.dat\nreader 2026-04\n' \
  >"$work/long/config/environmentKnowledgeBaseConfiguration.ini"
# (in the 2026-04 robot's dialect: robotLocationPose)
sed -e "s/^\(preGestureMessageEnglish[[:space:]]*1[[:space:]]\).*/\1$long/" -e 's/^robotLocation\([[:space:]]\)/robotLocationPose\1/' \
  "$seed" >"$work/long/data/environmentKnowledgeBaseInput.dat"
grep -q "$long" "$work/long/data/environmentKnowledgeBaseInput.dat" || fail "the long message is not in the file"
(cd "$work/long" && "$work/consumer-prefix/document_example_600" >"$work/out" 2>"$work/err") \
  || { cat "$work/err"; fail "the STRING_LENGTH 600 build refused a 335-byte message"; }
grep -qx "Pre-Gesture Message English      $long " "$work/out" \
  || fail "the STRING_LENGTH 600 build did not load the 335-byte message whole"
status=0
(cd "$work/long" && "$example" >"$work/out" 2>"$work/err") || status=$?
[ "$status" = 1 ] || { cat "$work/err"; fail "the default build: exit status $status on a 335-byte message"; }
grep -q 'error\[drop-in-string-length\]: this text is 335 bytes, .* (STRING_LENGTH 200, with its NUL)' "$work/err" \
  || { cat "$work/err"; fail "the default build did not refuse the 335-byte message naming STRING_LENGTH 200"; }

step "every C, C++ and CMake snippet of docs/library.md builds"
snippets=$work/snippets
mkdir -p "$snippets"
python3 - docs/library.md "$snippets" <<'PY'
import pathlib, re, sys
text = pathlib.Path(sys.argv[1]).read_text()
out = pathlib.Path(sys.argv[2])
blocks = re.findall(r"^```(c|cpp|cmake)\n(.*?)^```$", text, re.M | re.S)
lists = {"c": [], "cpp": [], "cmake": []}
for index, (language, body) in enumerate(blocks):
    name = f"snippet_{index}"
    if language == "cmake":
        project = out / name
        project.mkdir()
        (project / "main.cpp").write_text('#include "environmentKnowledgeBaseInterface.h"\nint main() { return sizeof(KeyValueType) ? 0 : 1; }\n')
        (project / "CMakeLists.txt").write_text(f"cmake_minimum_required(VERSION 3.16)\nproject({name} C CXX)\nadd_executable(my_node main.cpp)\n{body}")
    else:
        (out / f"{name}.{language}").write_text(body)
    lists[language].append(name)
for language in ("c", "cpp"):
    if not lists[language]:
        sys.exit(f"docs/library.md has no {language} snippet")
root = ["cmake_minimum_required(VERSION 3.16)", "project(snippets C CXX)", "find_package(ekb CONFIG REQUIRED)"]
for language in ("c", "cpp"):
    for name in lists[language]:
        root.append(f"add_executable({name} {name}.{language})")
        root.append(f"target_link_libraries({name} PRIVATE ekb::ekb)")
(out / "CMakeLists.txt").write_text("\n".join(root) + "\n")
(out / "cmake.list").write_text("\n".join(lists["cmake"]) + "\n")
print(f"{len(lists['c'])} C, {len(lists['cpp'])} C++ and {len(lists['cmake'])} CMake snippets")
PY
cmake -S "$snippets" -B "$snippets/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$snippets/build" -j"$jobs" >"$work/snippets.log" 2>&1 || { cat "$work/snippets.log"; fail "a C or C++ snippet of docs/library.md does not build"; }
while read -r name; do
  [ -n "$name" ] || continue
  { cmake -S "$snippets/$name" -B "$snippets/$name/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
    && cmake --build "$snippets/$name/build"; } >"$work/snippets.log" 2>&1 \
    || { cat "$snippets/$name/CMakeLists.txt" "$work/snippets.log"; fail "a CMake snippet of docs/library.md does not build"; }
done <"$snippets/cmake.list"
rm -rf "$snippets"

step "a catkin workspace with the example node"
ws=$work/catkin_ws
mkdir -p "$ws/src"
ln -s "$root/crates/ekb-capi" "$ws/src/ekb"
cp -rL integrations/ros "$ws/src/ekb_ros_example"
cp -rL crates/ekb-capi/tests/cssr_system "$ws/src/cssr_system"
(cd "$ws" && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DEKB_CARGO_PROFILE=dev >"$work/catkin.log" 2>&1) \
  || { tail -40 "$work/catkin.log"; fail "catkin_make failed"; }
run_node() {
  (
    set +u
    # shellcheck disable=SC1091
    source "$ws/devel/setup.bash"
    cd "$work" && rosrun_node=$ws/devel/lib/ekb_ros_example/tour_node && "$rosrun_node"
  ) >"$work/node.out" 2>&1
}
if run_node; then
  cat "$work/node.out"
  fail "the node loaded the seed file as it is"
fi
grep -q 'ERROR.*environmentKnowledgeBaseInput.dat:34:1: error\[key-case\]' "$work/node.out" \
  || { cat "$work/node.out"; fail "the node did not log the key-case finding at line 34"; }
"$ekb" fix --isolated "$ws/src/ekb_ros_example/data/environmentKnowledgeBaseInput.dat" >/dev/null
run_node || { cat "$work/node.out"; fail "the node refused the fixed file"; }
stops=$(sed -n 's/.*Stop [0-9]*: location \([0-9]*\),.*/\1/p' "$work/node.out" | tr '\n' ' ')
[ "$stops" = "1 4 3 2 5 " ] || { cat "$work/node.out"; fail "the node logged the tour $stops"; }
grep -q 'Stop 2: location 4, Roomba, .*"This is the Roomba" ... "We use it for teaching mobile robotics"' "$work/node.out" \
  || { cat "$work/node.out"; fail "the node's English messages"; }

step "the package cssr_system: the robot's layout, a global object, nothing caught"
cssr=$ws/src/cssr_system
run_cssr() { # [the workspace, else $ws]
  local status=0 space=${1:-$ws}
  (
    set +u
    # shellcheck disable=SC1091
    source "$space/devel/setup.bash"
    cd "$work" && "$space/devel/lib/cssr_system/behaviorController"
  ) >"$work/cssr.raw" 2>&1 || status=$?
  sed 's/\x1b\[[0-9;]*m//g' "$work/cssr.raw" >"$work/cssr.out" # rosconsole's colours
  return "$status"
}
status=0
run_cssr || status=$?
expect_refused_seed "cssr_system" "$work/cssr.out" "$status"
grep -q '^\[ERROR\] .*environmentKnowledgeBaseInput.dat:34:1: error\[key-case\]' "$work/cssr.out" \
  || { cat "$work/cssr.out"; fail "cssr_system: the key-case error is not through ROS_ERROR"; }
tail -1 "$work/cssr.out" | grep -q '^\[FATAL\] ' || fail "cssr_system: the last line is not ROS_FATAL"
cp "$work/cssr.out" "$work/cssr-seed.log"
"$ekb" fix --isolated "$cssr/behaviorController/data/environmentKnowledgeBaseInput.dat" >/dev/null
run_cssr || { cat "$work/cssr.out"; fail "cssr_system refused the fixed file"; }
stops=$(sed -n 's/.*stop [0-9]*: location \([0-9]*\),.*/\1/p' "$work/cssr.out" | tr '\n' ' ')
[ "$stops" = "1 4 3 2 5 " ] || { cat "$work/cssr.out"; fail "cssr_system logged the tour $stops"; }
# The other layouts of the package: the 2026-02 example's, the document's; then none.
mkdir -p "$cssr/behaviorController/include/utilities"
mv "$cssr/behaviorController/config" "$cssr/behaviorController/data" "$cssr/behaviorController/include/utilities/"
run_cssr || { cat "$work/cssr.out"; fail "cssr_system: the layout behaviorController/include/utilities/config"; }
grep -q 'stop 5: location 5' "$work/cssr.out" || fail "cssr_system: the 2026-02 layout's tour"
mv "$cssr/behaviorController/include/utilities/config" "$cssr/behaviorController/include/utilities/data" "$cssr/"
run_cssr || { cat "$work/cssr.out"; fail "cssr_system: the layout config/ and data/"; }
grep -q 'stop 5: location 5' "$work/cssr.out" || fail "cssr_system: the document's layout's tour"
rm -rf "$cssr/config"
status=0
run_cssr || status=$?
expect_no_configuration "cssr_system" "$(cd "$cssr" && pwd -P)" "$work/cssr.out" "$status"
grep -q 'in the ROS package cssr_system' "$work/cssr.out" || { cat "$work/cssr.out"; fail "cssr_system: the package not named"; }

step "the package cssr_system alone in a workspace, on the installed CMake package"
rws=$work/robot_ws
mkdir -p "$rws/src"
cp -rL crates/ekb-capi/tests/cssr_system "$rws/src/cssr_system"
(cd "$rws" && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -Dekb_DIR="$work/prefix/lib/cmake/ekb" \
  >"$work/robot_ws.log" 2>&1) || { tail -40 "$work/robot_ws.log"; fail "catkin_make of cssr_system alone failed"; }
grep -rqF "$work/prefix/lib/libekb_capi.a" "$rws/build/cssr_system/CMakeFiles/behaviorController.dir/link.txt" \
  || fail "cssr_system was not linked with the installed library"
status=0
run_cssr "$rws" || status=$?
expect_refused_seed "cssr_system on the installed package" "$work/cssr.out" "$status"
rm -rf "$work/prefix" "$rws"

if [ -n "${EKB_LOADER_LOGS:-}" ]; then # where to keep the logs of the seed file, to read
  mkdir -p "$EKB_LOADER_LOGS"
  cp "$work/cssr-seed.log" "$work/document-example.log" "$EKB_LOADER_LOGS/"
fi
echo "test-loader: all passed"
