#!/usr/bin/env bash
# End-to-end test of the pre-commit set-ups of docs/pre-commit.md with the real pre-commit
# tool (the one on the PATH, else installed from PyPI in a throwaway venv), in throwaway git
# repositories. Every snippet runs as the page writes it; only paths are put in:
# - `system` ("an ekb you installed", `language: system`), the ekb of `cargo build` on the
#   PATH: the seed file is refused with its findings, the key-case error first; fixed, it
#   commits;
# - `repair` (ekb-fix, ekb-fmt, ekb-check, `language: system`): a file is fixed and
#   realigned in a commit, which then goes through;
# - `wheel-file` (`language: python`, `additional_dependencies` a wheel file): the wheel of
#   scripts/build-wheel.sh put in for the page's /opt/ekb/ one (same name but for the
#   platform tag), refused then accepted as with `system`; the first hooked commit, the
#   environment made from nothing, is timed;
# - `clone` (the repository's own hooks, `repo:` a clone, `rev:` a commit id): with
#   EKB_TEST_RUST_HOOK=1 only (a whole release build, kept in target/pre-commit between
#   runs; EKB_MEASURE_HOOK_BUILD=1 builds it from nothing and prints how long it took). The
#   same clone's wheel hook (`ekb-check`, which the page says pip finds with
#   PIP_FIND_LINKS) runs every time.
#
# Needs network access to PyPI (unless pre-commit is installed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The file with the snippets, each a YAML block after a line `<!-- pre-commit:NAME -->`.
snippets_file=${EKB_PRE_COMMIT_SNIPPETS:-$root/docs/pre-commit.md}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "test-pre-commit: FAILED: $*" >&2; exit 1; }

if ! command -v pre-commit >/dev/null; then
  python3 -m venv "$work/venv"
  "$work/venv/bin/pip" install --quiet --disable-pip-version-check pre-commit
  export PATH="$work/venv/bin:$PATH"
fi
if [ -n "${EKB_MEASURE_HOOK_BUILD:-}" ]; then
  rust_target="$work/cargo-target" rust_home="$work/pre-commit-home"
else
  rust_target="$root/target/pre-commit" rust_home="$root/target/pre-commit-home"
fi

# The YAML block after `<!-- pre-commit:$1 -->` in the snippets file.
snippet() {
  awk -v marker="<!-- pre-commit:$1 -->" '
    $0 == marker { found = 1; next }
    found && /^```yaml/ { inside = 1; next }
    inside && /^```/ { exit }
    inside { print }' "$snippets_file"
}
system_snippet=$(snippet system)
repair_snippet=$(snippet repair)
wheel_file_snippet=$(snippet wheel-file)
clone_snippet=$(snippet clone)
[ -n "$system_snippet" ] && [ -n "$repair_snippet" ] && [ -n "$wheel_file_snippet" ] &&
  [ -n "$clone_snippet" ] ||
  fail "$snippets_file lacks a pre-commit snippet (system, repair, wheel-file, clone)"
url=$(sed -n 's/^ *- repo: *\([^ ]*\).*/\1/p' <<<"$clone_snippet")
rev=$(sed -n 's/^ *rev: *\([^ ]*\).*/\1/p' <<<"$clone_snippet")

# A clone of this repository's HEAD, for the clone snippet's repo and rev.
hooks="$work/ekb"
git init --quiet "$hooks"
git -C "$hooks" fetch --quiet "$root" HEAD
git -C "$hooks" checkout --quiet FETCH_HEAD
commit=$(git -C "$hooks" rev-parse HEAD)
clone_config=$(sed -e "s|$url|$hooks|" -e "s|$rev|$commit|" <<<"$clone_snippet")

# The ekb of the system hook, and the wheel of the python hooks.
(cd "$root" && cargo build --quiet)
installed="$root/target/debug"
wheel=$(bash "$root/scripts/build-wheel.sh")
# Offline: the wheel-file snippet must need nothing but its file (PIP_FIND_LINKS only where
# the page says so).
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1

# A new content repository using `config`; prints its path.
content_repo() {
  local repo="$work/content-$1"
  mkdir -p "$repo/data"
  git -C "$repo" init --quiet
  git -C "$repo" config user.email editor@example.org
  git -C "$repo" config user.name "Content Editor"
  printf '%s\n' "$2" > "$repo/.pre-commit-config.yaml"
  echo "$repo"
}

# The seed file is refused with its findings, the key-case error before anything else;
# corrected, it commits.
refuses_then_accepts() {
  local repo=$1 style=$2
  cp "$root/data/environmentKnowledgeBaseInput.dat" "$repo/data/"
  git -C "$repo" add .pre-commit-config.yaml data/environmentKnowledgeBaseInput.dat
  local start=$(date +%s.%N)
  if (cd "$repo" && git commit --quiet -m "Add the seed knowledge base") >"$work/refused.log" 2>&1; then
    cat "$work/refused.log"; fail "$style: the seed file was committed despite its errors"
  fi
  first_commit_seconds=$(awk -v start="$start" -v end="$(date +%s.%N)" 'BEGIN { print end - start }')
  for rule in key-case missing-field; do
    grep -q "$rule" "$work/refused.log" || { cat "$work/refused.log"; fail "$style: the refusal did not show $rule"; }
  done
  first=$(grep -m1 -oE '(error|warning)\[[a-z-]+\]' "$work/refused.log")
  [ "$first" = "error[key-case]" ] || { cat "$work/refused.log"; fail "$style: the refusal showed $first first, not error[key-case]"; }
  sed -i 's/^postGestureMessageenglish/postGestureMessageEnglish/' "$repo/data/environmentKnowledgeBaseInput.dat"
  git -C "$repo" add data/environmentKnowledgeBaseInput.dat
  (cd "$repo" && git commit --quiet -m "Add the fixed knowledge base") >"$work/accepted.log" 2>&1 ||
    { cat "$work/accepted.log"; fail "$style: the fixed file was refused"; }
}
export PRE_COMMIT_HOME="$work/pre-commit-home"

# 1. An ekb you installed: the local hook, ekb on the PATH.
repo=$(content_repo system "$system_snippet")
(cd "$repo" && pre-commit install >/dev/null)
PATH="$installed:$PATH" refuses_then_accepts "$repo" "system"
echo "ok: system: the seed file is refused, the key-case error first; fixed, it commits"

# 2. ekb-fix and ekb-fmt repair a file in the commit, then ekb-check lets it through.
repo=$(content_repo repair "$repair_snippet")
(cd "$repo" && pre-commit install >/dev/null)
mkdir -p "$repo/lab2/data"
# A wrong-case key, trailing blanks, CRLF endings and a misaligned line.
sed -e 's/^postGestureMessageEnglish     5/PostGestureMessageEnglish     5/' \
    -e 's/^robotLocation  *3 /robotLocation\t3 /' \
    -e 's/$/  \r/' "$root/data/environmentKnowledgeBaseInput.dat" |
  sed -e 's/^postGestureMessageenglish/postGestureMessageEnglish/' > "$repo/lab2/data/environmentKnowledgeBaseInput.dat"
git -C "$repo" add .pre-commit-config.yaml lab2
if (cd "$repo" && PATH="$installed:$PATH" git commit --quiet -m "Add a second lab") >"$work/modified.log" 2>&1; then
  cat "$work/modified.log"; fail "repair: a file the hooks had to repair was committed as it was"
fi
grep -q "files were modified by this hook" "$work/modified.log" || { cat "$work/modified.log"; fail "repair: ekb-fix/ekb-fmt did not repair the file"; }
kb="$repo/lab2/data/environmentKnowledgeBaseInput.dat"
grep -q "^postGestureMessageEnglish     5 See you again soon$" "$kb" || fail "repair: ekb-fix did not fix the key"
grep -q $'\r' "$kb" && fail "repair: ekb-fix left CRLF line endings"
grep -q "^robotLocation                 3 2.0 6.3 -45$" "$kb" || fail "repair: ekb-fmt did not realign the pose"
git -C "$repo" add lab2
(cd "$repo" && PATH="$installed:$PATH" git commit --quiet -m "Add a second lab") >"$work/repaired.log" 2>&1 ||
  { cat "$work/repaired.log"; fail "repair: the repaired file was refused"; }
echo "ok: repair: ekb-fix and ekb-fmt repair a file, which then commits"

# 3. One wheel file: pre-commit installs it into an environment of its own.
named=$(grep -o 'file:///opt/ekb/[^"]*' <<<"$wheel_file_snippet") ||
  fail "the wheel-file snippet names no wheel under /opt/ekb/"
version=$(cd "$root" && cargo metadata --no-deps --format-version 1 |
  python3 -c 'import json,sys; print(next(p["version"] for p in json.load(sys.stdin)["packages"] if p["name"] == "ekb"))')
case "$(basename "$named")" in
  "ekb-$version-cp39-abi3-"*.whl) ;;
  *) fail "the wheel-file snippet names $(basename "$named"), not a wheel of ekb $version" ;;
esac
repo=$(content_repo wheel-file "${wheel_file_snippet//$named/file://$wheel}")
(cd "$repo" && pre-commit install >/dev/null)
refuses_then_accepts "$repo" "wheel-file"
echo "ok: wheel-file: the seed file is refused, the key-case error first; fixed, it commits"
printf 'the first hooked commit, the wheel installed from nothing: %.1f s\n' "$first_commit_seconds"
passed=3

# 4. From a clone: the repository's wheel hook, pip pointed at the wheel as the page says.
repo=$(content_repo clone-wheel "${clone_config//ekb-check-rust/ekb-check}")
(cd "$repo" && pre-commit install >/dev/null)
PIP_FIND_LINKS="$(dirname "$wheel")" PIP_NO_INDEX=1 refuses_then_accepts "$repo" "clone (ekb-check)"
echo "ok: clone, ekb-check with PIP_FIND_LINKS: the seed file is refused; fixed, it commits"
passed=4

# 5. From a clone, built by pre-commit: a whole release build, since `cargo install` (as
# pre-commit runs it) resolves the dependencies anew instead of reusing target/: only when
# asked.
if [ -n "${EKB_TEST_RUST_HOOK:-}${EKB_MEASURE_HOOK_BUILD:-}" ]; then
  repo=$(content_repo clone "$clone_config")
  start=$(date +%s)
  (cd "$repo" && CARGO_TARGET_DIR="$rust_target" PRE_COMMIT_HOME="$rust_home" \
    pre-commit install --install-hooks >/dev/null)
  built=$(( $(date +%s) - start ))
  if [ -n "${EKB_MEASURE_HOOK_BUILD:-}" ]; then
    echo "pre-commit install --install-hooks (builds ekb in release mode): ${built} s"
  fi
  PRE_COMMIT_HOME="$rust_home" refuses_then_accepts "$repo" "clone (ekb-check-rust)"
  echo "ok: clone, ekb-check-rust: the seed file is refused; fixed, it commits"
  passed=5 skipped=0
else
  echo "skipped: clone, ekb-check-rust (a whole release build; EKB_TEST_RUST_HOOK=1 runs it)"
  skipped=1
fi
echo "pre-commit hooks: $passed passed, 0 failed, $skipped skipped"
