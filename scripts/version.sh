# Sourced, from the repository's root, by the scripts that check what a build reports:
# sets `version` (the root Cargo.toml's `[workspace.package] version`, its one place),
# `commit` (HEAD's short id; empty outside a git checkout) and `expected` (what
# `ekb --version` prints for them, as build.rs writes it).
version=$(sed -n '/^\[workspace.package\]/,/^\[/ s/^version = "\(.*\)"/\1/p' Cargo.toml)
commit=$(git rev-parse --short HEAD 2>/dev/null || true)
expected="ekb $version${commit:+ ($commit)}"
