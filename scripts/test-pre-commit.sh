#!/usr/bin/env bash
# End-to-end test of .pre-commit-hooks.yaml with the real pre-commit tool (from PyPI), in a
# throwaway git repository: a commit of the seed file is refused with the diagnostics shown;
# once fixed, it commits. Then the ekb-fix and ekb-fmt hooks repair a file in the commit. Needs network access to PyPI and crates.io (pre-commit builds ekb
# with `cargo install`). The hooks are taken from this repository's HEAD commit.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 -m venv "$work/venv"
"$work/venv/bin/pip" install --quiet --disable-pip-version-check pre-commit
export PATH="$work/venv/bin:$PATH"
# pre-commit builds ekb with `cargo install`; keep its build between runs.
export CARGO_TARGET_DIR="$root/target/pre-commit"
export PRE_COMMIT_HOME="$root/target/pre-commit-home"

repo="$work/content"
mkdir -p "$repo/data"
cd "$repo"
git init --quiet
git config user.email editor@example.org
git config user.name "Content Editor"
# Writes .pre-commit-config.yaml using this repository's hooks with the given ids.
use_hooks() {
  {
    echo "repos:"
    echo "  - repo: $root"
    echo "    rev: $(git -C "$root" rev-parse HEAD)"
    echo "    hooks:"
    for id in "$@"; do echo "      - id: $id"; done
  } > .pre-commit-config.yaml
}
use_hooks ekb-check
pre-commit install --install-hooks >/dev/null

fail() { echo "test-pre-commit: FAILED: $*" >&2; exit 1; }

cp "$root/data/environmentKnowledgeBaseInput.dat" data/
git add .pre-commit-config.yaml data/environmentKnowledgeBaseInput.dat
if git commit --quiet -m "Add the seed knowledge base" >"$work/refused.log" 2>&1; then
  cat "$work/refused.log"; fail "the seed file was committed despite its errors"
fi
grep -q "key-case" "$work/refused.log" || { cat "$work/refused.log"; fail "the refusal did not show key-case"; }
grep -q "missing-field" "$work/refused.log" || { cat "$work/refused.log"; fail "the refusal did not show missing-field"; }
echo "ok: the seed file is refused, with its diagnostics"

sed -i 's/^postGestureMessageenglish/postGestureMessageEnglish/' data/environmentKnowledgeBaseInput.dat
git add data/environmentKnowledgeBaseInput.dat
git commit --quiet -m "Add the fixed knowledge base" >"$work/accepted.log" 2>&1 ||
  { cat "$work/accepted.log"; fail "the fixed file was refused"; }
echo "ok: the fixed file commits"

use_hooks ekb-fix ekb-fmt ekb-check
mkdir -p lab2/data
# A wrong-case key, trailing blanks, CRLF endings and a misaligned line.
sed -e 's/^postGestureMessageEnglish     5/PostGestureMessageEnglish     5/' \
    -e 's/^robotLocation  *3 /robotLocation\t3 /' \
    -e 's/$/  \r/' data/environmentKnowledgeBaseInput.dat > lab2/data/environmentKnowledgeBaseInput.dat
git add .pre-commit-config.yaml lab2
if git commit --quiet -m "Add a second lab" >"$work/modified.log" 2>&1; then
  cat "$work/modified.log"; fail "a file the hooks had to repair was committed as it was"
fi
grep -q "files were modified by this hook" "$work/modified.log" || { cat "$work/modified.log"; fail "ekb-fix/ekb-fmt did not repair the file"; }
kb=lab2/data/environmentKnowledgeBaseInput.dat
grep -q "^postGestureMessageEnglish     5 See you again soon$" "$kb" || fail "ekb-fix did not fix the key"
grep -q $'\r' "$kb" && fail "ekb-fix left CRLF line endings"
grep -q "^robotLocation                 3 2.0 6.3 -45$" "$kb" || fail "ekb-fmt did not realign the pose"
git add lab2
git commit --quiet -m "Add a second lab" >"$work/repaired.log" 2>&1 ||
  { cat "$work/repaired.log"; fail "the repaired file was refused"; }
echo "ok: ekb-fix and ekb-fmt repair a file, which then commits"
echo "pre-commit hooks: 3 passed, 0 failed"
