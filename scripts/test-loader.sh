#!/usr/bin/env bash
# The loader for C and C++ end to end (SPEC §12), as CI runs it after `cargo test`:
# - the CMake project (crates/ekb-capi) builds from the source tree, and its CTest passes,
#   plain and under AddressSanitizer;
# - a consumer project finds it with find_package(ekb CONFIG) from that build tree and
#   from an install prefix, and its programs (one written only against the document's
#   appendix A) print the tour of the fixed seed file;
# - a catkin workspace builds the example node, which refuses the seed file as it is
#   (the key-case finding at line 34) and logs the tour 1, 4, 3, 2, 5 after `ekb fix`.
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
rm -rf "$work/prefix"

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

step "a catkin workspace with the example node"
ws=$work/catkin_ws
mkdir -p "$ws/src"
ln -s "$root/crates/ekb-capi" "$ws/src/ekb"
cp -rL integrations/ros "$ws/src/ekb_ros_example"
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
echo "test-loader: all passed"
