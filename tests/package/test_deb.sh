#!/usr/bin/env bash
# The Debian package in a bare Debian 12: `cpack -G DEB` builds it from this
# build tree; a copy of a cached `debootstrap --variant=minbase bookworm`
# root (scripts/debian-root.sh makes it) installs it with
# `apt-get install ./robotsim_*.deb` (dependencies from Debian's
# repositories); a user with no source tree then runs a program on a
# library cell, `robotsim test` on the examples' passing folder and a language server
# exchange (initialize, a file with an error, its diagnostics) from a folder
# of their own; `apt-get remove --purge` and `autoremove --purge` take it all
# away, which is checked by comparing the root's file list before the
# install and after the removal. Needs root (chroot) and the network
# (Debian's mirror); skipped (exit 77) when the cached root is missing.
# Prints the time of each step.
#
#   bash tests/package/test_deb.sh BUILD_DIR SOURCE_DIR WORK_DIR [DEBIAN_ROOT]
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
work=$3
cached=${4:-${ROBOTSIM_DEBIAN_ROOT:-/var/cache/robotsim/bookworm-minbase}}
if [ ! -x "$cached/usr/bin/apt-get" ]; then
  echo "SKIP: no cached Debian 12 root at $cached (bash scripts/debian-root.sh makes one)"
  exit 77
fi
[ "$(id -u)" -eq 0 ] || { echo "SKIP: chroot needs root"; exit 77; }

rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
root=$work/root
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
started=$SECONDS
step() { echo "[$((SECONDS - started)) s] $*"; }
cleanup() {
  umount "$root/proc" 2>/dev/null || true
  umount "$root/var/cache/apt/archives" 2>/dev/null || true
}
trap cleanup EXIT

step "cpack -G DEB"
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/cpack" >"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/cpack/robotsim_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
case "$depends" in
  *libcairo2*libc6* | *libc6*libcairo2*) ;;
  *) fail "dpkg-shlibdeps did not compute the dependencies: Depends: $depends" ;;
esac
# robotsim-urdf's libraries (issue 37: the URDF reader runs in that helper).
case "$depends" in
  *liburdfdom-model*) ;;
  *) fail "Depends does not name urdfdom (robotsim-urdf links it): Depends: $depends" ;;
esac
case "$depends" in
  *libassimp*) ;;
  *) fail "Depends does not name Assimp (robotsim-urdf links it): Depends: $depends" ;;
esac
[ "$(dpkg-deb -f "$deb" Recommends)" = bash-completion ] || fail "Recommends: $(dpkg-deb -f "$deb" Recommends)"

step "copy the cached root"
cp -a "$cached" "$root"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
# Debian's packages, downloaded once and kept beside the cached root.
archives=$(dirname "$cached")/apt-archives
mkdir -p "$archives/partial"
mount --bind "$archives" "$root/var/cache/apt/archives"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LC_ALL=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"; }
as_user() { chroot --userspec=student:student "$root" env -i PATH=/usr/bin:/bin HOME=/home/student LC_ALL=C.UTF-8 \
  sh -c 'cd /home/student/work && exec "$@"' _ "$@"; }
in_root useradd --create-home student
mkdir -p "$root/home/student/work" "$root/tmp/package"
chroot "$root" chown student:student /home/student/work
cp "$deb" "$root/tmp/package/"
step "apt-get update"
in_root apt-get update -qq >"$work/update.log" 2>&1 || { cat "$work/update.log"; exit 1; }

# Every path of the root but those apt and the kernel keep changing by
# themselves (lists, logs, caches), and the user's own folder.
file_list() {
  (cd "$root" && find . -xdev \( -path ./proc -o -path ./tmp -o -path ./var/cache -o -path ./var/log \
    -o -path ./var/lib/apt -o -path ./home/student/work -o -path ./var/lib/dpkg \) -prune -o -print | LC_ALL=C sort)
}
file_list >"$work/before.txt"
dpkg_before=$(in_root dpkg-query -W -f '${Package}\n' | LC_ALL=C sort)

step "apt-get install ./$(basename "$deb")"
in_root sh -c 'cd /tmp/package && apt-get install -y -q ./robotsim_*.deb' >"$work/install.log" 2>&1 ||
  { tail -20 "$work/install.log"; exit 1; }
grep -E "^(Need to get|After this operation)" "$work/install.log" || true
[ -x "$root/usr/bin/robotsim" ] || fail "no /usr/bin/robotsim after the install"
[ -f "$root/usr/share/robotsim/stdlib/workcells/gantry-cell.rsd" ] || fail "no library under /usr/share/robotsim"
[ -f "$root/usr/share/man/man1/robotsim.1" ] || fail "no man page"
[ -f "$root/usr/share/bash-completion/completions/robotsim" ] || fail "no bash completion"
# apt-get installs what a package recommends: the completion's loader too.
[ -f "$root/usr/share/bash-completion/bash_completion" ] || fail "bash-completion (recommended) not installed"
[ ! -e "$root$source" ] || fail "the source tree is visible in the root"
[ -x "$root/usr/libexec/robotsim/robotsim-urdf" ] || fail "no /usr/libexec/robotsim/robotsim-urdf (the URDF reader)"

step "as a user: a program on a library cell, robotsim test, --version"
cp "$root/usr/share/doc/robotsim/examples/gantry_pick.rsp" "$root/home/student/work/"
cp -r "$root/usr/share/doc/robotsim/examples" "$root/home/student/work/examples"
chroot "$root" chown -R student:student /home/student/work
if as_user robotsim run gantry_pick.rsp --cell gantry-cell >"$work/run.out" 2>&1; then
  (cd "$work" && cp "$source/examples/gantry_pick.rsp" . && "$build/robotsim" run gantry_pick.rsp --cell gantry-cell >"$work/run-build-tree.out" 2>&1)
  cmp -s "$work/run.out" "$work/run-build-tree.out" ||
    fail "the packaged run differs from the build tree's: $(diff "$work/run.out" "$work/run-build-tree.out" | head -5)"
else
  fail "robotsim run on gantry-cell failed in the root: $(head -3 "$work/run.out")"
fi
as_user robotsim test examples/tests/passing >"$work/test.out" 2>&1 ||
  fail "robotsim test examples/tests/passing failed: $(tail -3 "$work/test.out")"
grep -Eq "^[1-9][0-9]* passed, 0 failed, 0 errors" "$work/test.out" || fail "robotsim test's summary: $(tail -1 "$work/test.out")"
# A URDF file written and read back by the installed robotsim: the helper
# robotsim-urdf found from /usr/bin and its libraries installed by apt.
as_user robotsim export abb-irb120 --urdf -o irb120.urdf >"$work/urdf.out" 2>&1 &&
  as_user robotsim table irb120.urdf --tip tool0 >>"$work/urdf.out" 2>&1 ||
  fail "a URDF export read back in the root: $(tail -3 "$work/urdf.out")"
version_json=$(as_user robotsim --version --format=json)
case "$version_json" in
  *'"library":"/usr/share/robotsim/stdlib"'*) ;;
  *) fail "--version does not name /usr/share/robotsim/stdlib: $version_json" ;;
esac

step "as a user: the language server (initialize, didOpen, diagnostics)"
bash "$(dirname "$0")/lsp_exchange.sh" "$work/lsp.log" chroot --userspec=student:student "$root" \
  env -i PATH=/usr/bin:/bin HOME=/home/student LC_ALL=C.UTF-8 sh -c 'cd /home/student/work && exec robotsim lsp' ||
  fail "the language server exchange: $(tail -3 "$work/lsp.log")"

step "apt-get remove --purge robotsim; apt-get autoremove --purge"
in_root apt-get remove --purge -y -q robotsim >"$work/remove.log" 2>&1 || { tail -20 "$work/remove.log"; exit 1; }
in_root apt-get autoremove --purge -y -q >>"$work/remove.log" 2>&1 || { tail -20 "$work/remove.log"; exit 1; }
rm -rf "$root/home/student/work"
mkdir -p "$root/home/student/work"
file_list >"$work/after.txt"
if ! cmp -s "$work/before.txt" "$work/after.txt"; then
  fail "files left behind or lost: $(diff "$work/before.txt" "$work/after.txt" | head -10)"
fi
dpkg_after=$(in_root dpkg-query -W -f '${Package}\n' | LC_ALL=C sort)
[ "$dpkg_before" = "$dpkg_after" ] || fail "packages differ after the removal: $(diff <(echo "$dpkg_before") <(echo "$dpkg_after") | head -5)"

cleanup
step "done"
rm -rf "$root"
if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok: the package installs in a bare Debian 12, runs, tests, serves LSP, and leaves nothing behind"
