#!/usr/bin/env bash
# Makes the bare Debian 12 root the package test installs robotsim into
# (tests/package/test_deb.sh, CTest label `package`): debootstrap's minimal
# variant of bookworm from Debian's repositories, kept at DIR (default
# /var/cache/robotsim/bookworm-minbase) for every later run, which copies it.
# Runs as root; installs debootstrap if it is missing. About 2.5 minutes.
#
#   bash scripts/debian-root.sh [DIR]
set -euo pipefail
dir=${1:-/var/cache/robotsim/bookworm-minbase}
[ "$(id -u)" -eq 0 ] || { echo "debian-root: run as root (debootstrap and chroot need it)" >&2; exit 2; }
if [ -x "$dir/usr/bin/apt-get" ]; then
  echo "debian-root: $dir exists; remove it to make a fresh one"
  exit 0
fi
command -v debootstrap >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y debootstrap
mkdir -p "$(dirname "$dir")"
rm -rf "$dir.partial"
debootstrap --variant=minbase bookworm "$dir.partial" http://deb.debian.org/debian
mv "$dir.partial" "$dir"
echo "debian-root: made $dir"
