#!/usr/bin/env bash
# Installs what robotsim needs to build and test, from Debian's packages.
# Idempotent: asks apt only for what is missing. Runs as root (or via sudo).
set -euo pipefail

packages=(
  build-essential cmake make git pkg-config
  antlr4 libantlr4-runtime-dev default-jre-headless
  libeigen3-dev libfmt-dev catch2 libcli11-dev nlohmann-json3-dev
  libmimalloc-dev lua5.4 xxd
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
