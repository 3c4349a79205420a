#!/usr/bin/env bash
# End-to-end test of the pre-commit set-ups of docs/pre-commit.md with the real pre-commit
# tool (the one on the PATH, else installed from PyPI in a throwaway venv), in throwaway git
# repositories:
# - "ekb from its wheel": the snippet `wheel` as written, its `repo` pointed at a throwaway
#   clone of this repository in which the snippet's `rev` is a tag on HEAD (the real tag is
#   made by scripts/release.sh); pre-commit installs the thin package at the clone's root,
#   which finds the wheel of scripts/build-wheel.sh offline (PIP_FIND_LINKS, PIP_NO_INDEX).
#   The first hooked commit, pre-commit's environment made from nothing, is timed;
# - "pre-commit builds ekb": the snippet `rust` (`language: rust`, `cargo install`), with
#   EKB_TEST_RUST_HOOK=1 only;
# - "an ekb you installed": the snippet `system` (`language: system`), with the ekb of
#   `cargo build` on the PATH.
# With each, a commit of the seed file is refused with its diagnostics, and once fixed it
# commits. Then the ekb-fix and ekb-fmt hooks (from the wheel) repair a file in a commit.
#
# Needs network access to PyPI (unless pre-commit is installed). The rust hook runs only
# with EKB_TEST_RUST_HOOK=1 (it needs crates.io, and its build is kept in target/pre-commit
# between runs); EKB_MEASURE_HOOK_BUILD=1 builds it from nothing instead, and prints how
# long pre-commit took to install it.
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
wheel_snippet=$(snippet wheel)
rust_snippet=$(snippet rust)
system_snippet=$(snippet system)
[ -n "$wheel_snippet" ] && [ -n "$rust_snippet" ] && [ -n "$system_snippet" ] ||
  fail "$snippets_file lacks a pre-commit snippet (wheel, rust, system)"
rev=$(sed -n 's/^ *rev: *\([^ ]*\).*/\1/p' <<<"$wheel_snippet")
url=$(sed -n 's/^ *- repo: *\([^ ]*\).*/\1/p' <<<"$wheel_snippet")
[ "$(sed -n 's/^ *rev: *\([^ ]*\).*/\1/p' <<<"$rust_snippet")" = "$rev" ] ||
  fail "the wheel and rust snippets name different revs"

# This repository's HEAD, with the snippets' rev as a tag on it.
hooks="$work/ekb"
git init --quiet "$hooks"
git -C "$hooks" fetch --quiet "$root" HEAD
git -C "$hooks" tag "$rev" FETCH_HEAD

# The ekb of the system hook, and the wheel of the python hooks.
(cd "$root" && cargo build --quiet)
installed="$root/target/debug"
wheel=$(bash "$root/scripts/build-wheel.sh")
export PIP_FIND_LINKS="$(dirname "$wheel")" PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1

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

# The seed file is refused with its diagnostics; corrected, it commits.
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
  sed -i 's/^postGestureMessageenglish/postGestureMessageEnglish/' "$repo/data/environmentKnowledgeBaseInput.dat"
  git -C "$repo" add data/environmentKnowledgeBaseInput.dat
  (cd "$repo" && git commit --quiet -m "Add the fixed knowledge base") >"$work/accepted.log" 2>&1 ||
    { cat "$work/accepted.log"; fail "$style: the fixed file was refused"; }
}

# 1. ekb from its wheel: the first hooked commit installs the hook's environment.
repo=$(content_repo wheel "${wheel_snippet//$url/$hooks}")
(cd "$repo" && pre-commit install >/dev/null)
PRE_COMMIT_HOME="$work/pre-commit-home" refuses_then_accepts "$repo" "language: python"
echo "ok: language: python, rev $rev: the seed file is refused with its diagnostics; fixed, it commits"
printf 'the first hooked commit, the wheel hook installed from nothing: %.1f s\n' "$first_commit_seconds"

# 2. pre-commit builds ekb: a whole release build, since `cargo install` (as pre-commit runs
# it) resolves the dependencies anew instead of reusing target/: only when asked.
if [ -n "${EKB_TEST_RUST_HOOK:-}${EKB_MEASURE_HOOK_BUILD:-}" ]; then
  repo=$(content_repo rust "${rust_snippet//$url/$hooks}")
  start=$(date +%s)
  (cd "$repo" && CARGO_TARGET_DIR="$rust_target" PRE_COMMIT_HOME="$rust_home" \
    pre-commit install --install-hooks >/dev/null)
  built=$(( $(date +%s) - start ))
  if [ -n "${EKB_MEASURE_HOOK_BUILD:-}" ]; then
    echo "pre-commit install --install-hooks (builds ekb in release mode): ${built} s"
  fi
  PRE_COMMIT_HOME="$rust_home" refuses_then_accepts "$repo" "language: rust"
  echo "ok: language: rust, rev $rev: the seed file is refused with its diagnostics; fixed, it commits"
  passed=4 skipped=0
else
  echo "skipped: language: rust (a whole release build; EKB_TEST_RUST_HOOK=1 runs it)"
  passed=3 skipped=1
fi

# 3. An ekb you installed: the local hook, ekb on the PATH.
repo=$(content_repo system "$system_snippet")
(cd "$repo" && pre-commit install >/dev/null)
PRE_COMMIT_HOME="$work/pre-commit-home" PATH="$installed:$PATH" refuses_then_accepts "$repo" "language: system"
echo "ok: language: system: the seed file is refused with its diagnostics; fixed, it commits"

# 4. ekb-fix and ekb-fmt (from the wheel) repair a file in the commit.
repo=$(content_repo fixes "repos:
  - repo: $hooks
    rev: $rev
    hooks:
      - id: ekb-fix
      - id: ekb-fmt
      - id: ekb-check")
export PRE_COMMIT_HOME="$work/pre-commit-home"
(cd "$repo" && pre-commit install --install-hooks >/dev/null)
mkdir -p "$repo/lab2/data"
# A wrong-case key, trailing blanks, CRLF endings and a misaligned line.
sed -e 's/^postGestureMessageEnglish     5/PostGestureMessageEnglish     5/' \
    -e 's/^robotLocation  *3 /robotLocation\t3 /' \
    -e 's/$/  \r/' "$root/data/environmentKnowledgeBaseInput.dat" |
  sed -e 's/^postGestureMessageenglish/postGestureMessageEnglish/' > "$repo/lab2/data/environmentKnowledgeBaseInput.dat"
git -C "$repo" add .pre-commit-config.yaml lab2
if (cd "$repo" && git commit --quiet -m "Add a second lab") >"$work/modified.log" 2>&1; then
  cat "$work/modified.log"; fail "a file the hooks had to repair was committed as it was"
fi
grep -q "files were modified by this hook" "$work/modified.log" || { cat "$work/modified.log"; fail "ekb-fix/ekb-fmt did not repair the file"; }
kb="$repo/lab2/data/environmentKnowledgeBaseInput.dat"
grep -q "^postGestureMessageEnglish     5 See you again soon$" "$kb" || fail "ekb-fix did not fix the key"
grep -q $'\r' "$kb" && fail "ekb-fix left CRLF line endings"
grep -q "^robotLocation                 3 2.0 6.3 -45$" "$kb" || fail "ekb-fmt did not realign the pose"
git -C "$repo" add lab2
(cd "$repo" && git commit --quiet -m "Add a second lab") >"$work/repaired.log" 2>&1 ||
  { cat "$work/repaired.log"; fail "the repaired file was refused"; }
echo "ok: ekb-fix and ekb-fmt repair a file, which then commits"
echo "pre-commit hooks: $passed passed, 0 failed, $skipped skipped"
