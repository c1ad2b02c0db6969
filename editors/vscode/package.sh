#!/usr/bin/env bash
# Builds the VS Code extension into editors/vscode/robotsim-VERSION.vsix,
# offline from the lock file's pinned packages (npm ci), with @vscode/vsce.
# Install it with: code --install-extension editors/vscode/robotsim-*.vsix
set -euo pipefail
cd "$(dirname "$0")"
[ -d node_modules/@vscode/vsce ] || npm ci --no-audit --no-fund >/dev/null
version=$(node -p "require('./package.json').version")
npx --no-install vsce package --allow-missing-repository --skip-license -o "robotsim-$version.vsix" >/dev/null
echo "package.sh: wrote $(pwd)/robotsim-$version.vsix"
