#!/usr/bin/env bash
# Builds a release's artifacts and checks that every one reports the version of the root
# Cargo.toml (`[workspace.package] version`, its one place) and the same commit:
# - the wheel (scripts/build-wheel.sh): its file name, its metadata, `ekb --version` of the
#   executable it installs and `ekb.__version__`;
# - the Debian package (scripts/build-deb.sh): its Version and the `ekb --version` it carries;
# - the thin package the pre-commit hooks install (pyproject.toml): its version and the
#   wheel version it requires;
# - the release build: `target/release/ekb --version`.
#
#   scripts/release.sh          # build and check; prints the artifacts
#   scripts/release.sh --tag    # then tag HEAD `vVERSION`, the `rev:` of the pre-commit
#                               # snippets (the tree must be clean, and CHANGELOG.md must
#                               # have a `## [VERSION]` section)
#
# Works offline once maturin and cargo-deb are installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "release: FAILED: $*" >&2; exit 1; }
same() { [ "$2" = "$3" ] || fail "$1 reports '$2', not '$3'"; echo "ok: $1: $2"; }

. scripts/version.sh
[ -n "$version" ] || fail "Cargo.toml has no [workspace.package] version"
[ -n "$commit" ] || fail "not a git checkout: a release is made of a commit"

wheel=$(bash scripts/build-wheel.sh)
deb=$(bash scripts/build-deb.sh)

same "target/release/ekb --version" "$(target/release/ekb --version)" "$expected"

case "$(basename "$wheel")" in
  "ekb-$version-"*) echo "ok: wheel file $(basename "$wheel")" ;;
  *) fail "the wheel $wheel is not version $version" ;;
esac
python3 -m venv "$work/venv"
"$work/venv/bin/pip" install --quiet --disable-pip-version-check --no-index "$wheel"
same "the wheel's ekb --version" "$("$work/venv/bin/ekb" --version)" "$expected"
same "the wheel's metadata" \
  "$("$work/venv/bin/python" -c 'import importlib.metadata as m; print(m.version("ekb"))')" "$version"
same "ekb.__version__" "$("$work/venv/bin/python" -c 'import ekb; print(ekb.__version__)')" "$version"

same "the Debian package's Version" "$(dpkg-deb --field "$deb" Version)" "$version-1"
dpkg-deb --extract "$deb" "$work/deb"
same "the Debian package's ekb --version" "$("$work/deb/usr/bin/ekb" --version)" "$expected"

"$work/venv/bin/pip" wheel --quiet --disable-pip-version-check --no-index --no-deps \
  --wheel-dir "$work/hooks" . 2>/dev/null
hooks=$(ls "$work"/hooks/ekb_pre_commit-*.whl)
same "the pre-commit package" "$(basename "$hooks")" "ekb_pre_commit-$version-py3-none-any.whl"
same "the pre-commit package's requirement" \
  "$(unzip -p "$hooks" '*/METADATA' | sed -n 's/^Requires-Dist: //p')" "ekb==$version"

echo "release $version ($commit): $wheel $deb"
if [ "${1:-}" = "--tag" ]; then
  git diff --quiet HEAD || fail "the tree has uncommitted changes: commit them first"
  grep -q "^## \[$version\]" CHANGELOG.md ||
    fail "CHANGELOG.md has no '## [$version]' section: move the Unreleased entries under it"
  git tag --annotate "v$version" --message "ekb $version"
  echo "tagged v$version: push it with the wheel and the package"
fi
