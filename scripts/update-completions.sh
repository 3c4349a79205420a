#!/usr/bin/env bash
# Regenerates the shell completion scripts in completions/ from the CLI definition.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --quiet
for shell in bash zsh fish elvish powershell; do
  case "$shell" in
    zsh) file=_ekb ;;
    powershell) file=_ekb.ps1 ;;
    elvish) file=ekb.elv ;;
    *) file="ekb.$shell" ;;
  esac
  target/debug/ekb completions "$shell" > "completions/$file"
done
