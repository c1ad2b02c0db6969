#!/usr/bin/env bash
# The Debian package's control file as `cpack -G DEB` writes it from the
# build's CPackConfig.cmake (the project's own packaging), without the
# install and dpkg-shlibdeps (which only add the files and Depends, and
# take a minute): the fields a user's apt-get reads. Recommends must name
# bash-completion, without which the completion it installs does nothing.
#
#   bash tests/package/test_control.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$(realpath "$1")
work=$2
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
(cd "$work" && cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/cpack" \
  -D CPACK_INSTALL_CMAKE_PROJECTS= -D CPACK_DEBIAN_PACKAGE_SHLIBDEPS=OFF >"$work/cpack.log" 2>&1) ||
  { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/cpack/robotsim_*.deb)
failures=0
field() {
  local got
  got=$(dpkg-deb -f "$deb" "$1")
  if [ "$got" != "$2" ]; then
    echo "FAIL: $1: '$got', expected '$2'"
    failures=$((failures + 1))
  fi
}
field Package robotsim
field Recommends bash-completion
field Section devel
rm -rf "$work"
[ "$failures" -eq 0 ] || exit 1
echo "ok: the control file says Package: robotsim, Recommends: bash-completion, Section: devel"
