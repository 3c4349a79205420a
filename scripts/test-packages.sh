#!/usr/bin/env bash
# The packages as a user gets them (SPEC §13), from one release build in target/:
# - the wheel (scripts/build-wheel.sh), installed in a fresh virtual environment (timed):
#   its `ekb check` of the seed file gives the report and exit code of the cargo build; its
#   version is the workspace's, with the commit; `import ekb` passes the tests of
#   crates/ekb-python/tests (pytest); `uv tool install` puts `ekb` on PATH too;
# - the Debian package (scripts/build-deb.sh), installed with apt-get: `ekb --version`, its
#   man page (`man -w ekb`) and the bash, zsh and fish completions in their system places, and
#   the loader library, whose CMake package a consumer finds and links; the example ROS
#   package it carries, built and run with rosrun by the steps of docs/library.md.
#
# Installs the package system-wide: run it as root, on a machine you may change (as CI).
# Needs PyPI for pytest and uv (in the throwaway environment).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "test-packages: FAILED: $*" >&2; exit 1; }
passed=0
ok() { echo "ok: $*"; passed=$((passed + 1)); }

. scripts/version.sh

# Fails unless every relative link of the Markdown files under $1 names a file there.
links_to_docs() {
  local file link target
  while IFS= read -r file; do
    while IFS= read -r link; do
      target="$(dirname "$file")/${link%%#*}"
      [ -e "$target" ] || fail "${file#"$1"/} links to $link, which is not installed"
    done < <(grep -oE '\]\([^)#:]+(#[^)]*)?\)' "$file" | sed -E 's/^\]\(//; s/\)$//')
  done < <(find "$1" -name '*.md')
}
seed=data/environmentKnowledgeBaseInput.dat

wheel=$(bash scripts/build-wheel.sh)
deb=$(bash scripts/build-deb.sh)
echo "built $wheel ($(du -h "$wheel" | cut -f1)) and $deb ($(du -h "$deb" | cut -f1))"

# Distributed executables carry no symbols and no debug information.
stripped() {
  ! readelf --section-headers "$1" | grep -q -e '\.symtab' -e '\.debug_info' -e '\.debug_line' ||
    fail "$2 is not stripped"
}

# The report of `ekb check` of the seed file: exit code, standard output, standard error.
report() {
  local status=0
  "$@" check "$seed" >"$work/out" 2>"$work/err" || status=$?
  printf 'exit %s\n' "$status"
  cat "$work/out" "$work/err"
}
cargo build --quiet --locked --bin ekb
report target/debug/ekb >"$work/cargo.report"

# 1. The wheel, in a fresh virtual environment.
python3 -m venv "$work/venv"
start=$(date +%s.%N)
"$work/venv/bin/pip" install --quiet --disable-pip-version-check --no-index "$wheel"
seconds=$(awk -v start="$start" -v end="$(date +%s.%N)" 'BEGIN { print end - start }')
ok "the wheel installs in a fresh virtual environment in $(printf '%.1f' "$seconds") s"
[ "$("$work/venv/bin/ekb" --version)" = "$expected" ] ||
  fail "the wheel's ekb --version is '$("$work/venv/bin/ekb" --version)', not '$expected'"
[ "$("$work/venv/bin/python" -c 'import ekb; print(ekb.__version__)')" = "$version" ] ||
  fail "ekb.__version__ is not $version"
ok "the wheel's ekb and import ekb are version $version"
stripped "$work/venv/bin/ekb" "the wheel's ekb"
stripped "$(ls "$work"/venv/lib/python*/site-packages/ekb/_ekb*.so)" "the wheel's module"
ok "the wheel's executable and module are stripped"
[ -s "$work/venv/share/man/man1/ekb.1" ] || fail "the wheel installs no share/man/man1/ekb.1"
grep -q '^\.SH EXAMPLES' "$work/venv/share/man/man1/ekb.1" || fail "the wheel's man page has no EXAMPLES"
links_to_docs "$work/venv/share/doc/ekb"
[ -s "$work/venv/share/doc/ekb/docs/editors.md" ] || fail "the wheel installs no docs/editors.md"
ok "the wheel installs the man page and the documentation (share/doc/ekb), its links resolving"
report "$work/venv/bin/ekb" >"$work/wheel.report"
diff -u "$work/cargo.report" "$work/wheel.report" ||
  fail "the wheel's ekb check of the seed file differs from the cargo build's"
grep -qx 'exit 1' "$work/wheel.report" || fail "the seed file's errors did not make ekb check exit 1"
ok "the wheel's ekb check of the seed file gives the cargo build's report and exit code"
"$work/venv/bin/python" - "$seed" <<'EOF' || fail "the Python API on the seed file"
import sys
import ekb

try:
    ekb.load(sys.argv[1])
except ekb.RefusedError as error:
    rules = {finding.rule for finding in error.findings}
    assert {"key-case", "missing-field"} <= rules, rules
else:
    raise AssertionError("the seed file, which has errors, was loaded")
findings = ekb.check(sys.argv[1])
assert any(f.rule == "key-case" and f.severity == "error" for f in findings)
EOF
ok "import ekb: the seed file is refused with its findings"
"$work/venv/bin/pip" install --quiet --disable-pip-version-check pytest uv
PATH="$work/venv/bin:$PATH" "$work/venv/bin/python" -m pytest -q -p no:cacheprovider \
  crates/ekb-python/tests
UV_TOOL_DIR="$work/uv-tools" UV_TOOL_BIN_DIR="$work/uv-bin" UV_NO_CACHE=1 \
  "$work/venv/bin/uv" tool install --quiet --offline --no-index --find-links "$(dirname "$wheel")" \
  "ekb==$version"
[ "$("$work/uv-bin/ekb" --version)" = "$expected" ] || fail "uv tool install gave no working ekb"
ok "uv tool install puts ekb on PATH"

# 2. The Debian package.
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --reinstall "$deb" >/dev/null
[ "$(/usr/bin/ekb --version)" = "$expected" ] ||
  fail "the package's ekb --version is '$(/usr/bin/ekb --version)', not '$expected'"
stripped /usr/bin/ekb "the package's ekb"
ok "the package installs /usr/bin/ekb, version $version, stripped"
[ "$(man -w ekb)" = /usr/share/man/man1/ekb.1.gz ] || fail "man -w ekb: $(man -w ekb 2>&1)"
for section in 'EXIT STATUS' EXAMPLES; do
  zcat /usr/share/man/man1/ekb.1.gz | grep -q "^\.SH \"\?$section" || fail "the man page has no $section"
done
ok "the package installs the man page, with its EXAMPLES and EXIT STATUS"
# The documentation, every link between its files resolving where it is installed.
docs_dir=/usr/share/doc/ekb
for file in README.md docs/library.md docs/editors.md docs/pre-commit.md docs/translators.md \
  editors/README.md; do
  [ -s "$docs_dir/$file" ] || fail "the package has no $docs_dir/$file"
done
links_to_docs "$docs_dir"
ok "the package installs the documentation in $docs_dir, its links resolving"
for completion in /usr/share/bash-completion/completions/ekb \
  /usr/share/zsh/vendor-completions/_ekb /usr/share/fish/vendor_completions.d/ekb.fish; do
  [ -s "$completion" ] || fail "the package has no $completion"
done
bash -c 'source /usr/share/bash-completion/completions/ekb && complete -p ekb' >/dev/null ||
  fail "the bash completion does not register for ekb"
ok "the package installs the bash, zsh and fish completions"
for file in /usr/include/ekb.h /usr/include/ekb.hpp /usr/include/environmentKnowledgeBaseInterface.h \
  /usr/include/utilities/environmentKnowledgeBaseInterface.h \
  /usr/include/behaviorController/environmentKnowledgeBaseInterface.h \
  /usr/lib/libekb_capi.a /usr/lib/cmake/ekb/ekbConfig.cmake /usr/lib/cmake/ekb/ekbConfigVersion.cmake; do
  [ -s "$file" ] || fail "the package has no $file"
done
# A consumer of the loader (SPEC §12) finds the installed package with find_package(ekb), and
# compiles the drop-in under its three include spellings.
cmake -S crates/ekb-capi/tests/consumer -B "$work/consumer" >/dev/null
grep -q 'ekb_DIR:PATH=/usr/lib/cmake/ekb' "$work/consumer/CMakeCache.txt" ||
  fail "the consumer did not find the installed CMake package"
cmake --build "$work/consumer" -j2 >/dev/null
"$work/consumer/cpp_api" "$seed" >"$work/out" && fail "the installed loader loaded the seed file as it is"
grep -q ':34:1: error\[key-case\]' "$work/out" || fail "the installed loader gave no key-case finding at line 34"
ok "the package installs the loader library, its headers and CMake package: a consumer builds and refuses the seed file"
# The example ROS node on the package, by the steps of docs/library.md as written (their
# apt-get lines left out: .ci/run installs those packages), in a home of its own.
steps=$(awk '/^\*\*On the Debian package\*\*/ { found = 1 }
  found && /^```sh/ { inside = 1; next }
  inside && /^```/ { exit }
  inside { print }' docs/library.md)
[ -n "$steps" ] || fail "docs/library.md has no steps for the Debian package"
steps=$(grep -v '^sudo apt-get install' <<<"$steps")
ros_home="$work/ros-home"
mkdir -p "$ros_home"
# The seed file: refused, the node exits 1 with the key-case finding.
if (export HOME="$ros_home"; set +u; eval "$steps") >"$work/ros.log" 2>&1; then
  cat "$work/ros.log"; fail "the example node on the package loaded the seed file as it is"
fi
grep -q 'ERROR.*environmentKnowledgeBaseInput.dat:34:1: error\[key-case\]' "$work/ros.log" ||
  { tail -40 "$work/ros.log"; fail "the example node on the package did not refuse the seed file"; }
/usr/bin/ekb fix --isolated "$ros_home/catkin_ws/src/ekb_ros_example/data/environmentKnowledgeBaseInput.dat" >/dev/null 2>&1
(export HOME="$ros_home"; set +u; cd "$ros_home/catkin_ws" && source devel/setup.bash &&
  rosrun ekb_ros_example tour_node) >"$work/ros.log" 2>&1 || { cat "$work/ros.log"; fail "rosrun of the fixed file"; }
stops=$(sed -n 's/.*Stop [0-9]*: location \([0-9]*\),.*/\1/p' "$work/ros.log" | tr '\n' ' ')
[ "$stops" = "1 4 3 2 5 " ] || { cat "$work/ros.log"; fail "the example node on the package logged the tour $stops"; }
ok "docs/library.md's catkin steps on the package: rosrun refuses the seed file, and runs the fixed tour"
echo "packages: $passed passed, 0 failed"
