#!/usr/bin/env bash
# Builds the VS Code extension (editors/vscode/): installs its locked dependencies from the
# npm registry (`npm ci`), compiles it, tests its TextMate grammar, and packages it as
# editors/vscode/ekb.vsix. Needs Node.js and npm.
set -euo pipefail
cd "$(dirname "$0")/../editors/vscode"
npm ci --no-audit --no-fund
npm run compile
npm test
npm run package
ls -l ekb.vsix
