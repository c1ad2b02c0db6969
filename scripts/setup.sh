#!/usr/bin/env bash
# Installs what robotsim needs to build and test, from Debian's packages.
# Idempotent: asks apt only for what is missing. Runs as root (or via sudo).
set -euo pipefail

packages=(
  build-essential cmake make git pkg-config
  antlr4 libantlr4-runtime-dev default-jre-headless
  libeigen3-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev
  libmimalloc-dev lua5.4 xxd
  libcairo2-dev chromium fonts-liberation
)

# The browser test's driver (playwright-core, pinned in package-lock.json).
install_node_modules() {
  if [ ! -d tests/browser/node_modules/playwright-core ]; then
    echo "setup: npm ci in tests/browser" >&2
    npm ci --prefix tests/browser --no-audit --no-fund >/dev/null
  fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js may come from elsewhere than Debian's packages (with its own npm,
# which Debian's npm package conflicts with): ask apt only when a command is missing.
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
cd "$(dirname "$0")/.."
if [ ${#missing[@]} -eq 0 ]; then
  install_node_modules
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_node_modules
