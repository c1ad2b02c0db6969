#!/usr/bin/env bash
# Builds the VS Code extension into editors/vscode/robotsim-VERSION.vsix (or
# the path given), offline from the lock file's pinned packages (npm ci),
# with @vscode/vsce.
#   bash editors/vscode/package.sh [OUT.vsix]
# Install it with: code --install-extension editors/vscode/robotsim-*.vsix
set -euo pipefail
out=${1:+$(cd "$(dirname "$1")" && pwd)/$(basename "$1")}
cd "$(dirname "$0")"
[ -d node_modules/@vscode/vsce ] || npm ci --ignore-scripts --no-audit --no-fund >/dev/null
version=$(node -p "require('./package.json').version")
out=${out:-$(pwd)/robotsim-$version.vsix}
npx --no-install vsce package --allow-missing-repository --skip-license -o "$out" >/dev/null
echo "package.sh: wrote $out"
