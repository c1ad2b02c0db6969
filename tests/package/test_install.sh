#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed robotsim used
# as a user would, from folders outside the source tree:
# - the prefix holds the command, the library, the man pages, the bash
#   completion and the docs and examples;
# - the prefix moved elsewhere still works (nothing absolute is compiled in):
#   a program runs on a library cell, with the same output as the build
#   tree's robotsim; --version names the moved prefix's library;
# - the binary copied alone finds no library and says so (so it never falls
#   back to the source tree), and --lib or ROBOTSIM_PATH give it one;
# - --lib and ROBOTSIM_PATH add cells on top of the installed library;
# - the installed man page renders (man -l) and the installed completion
#   completes in a real bash.
#
#   bash tests/package/test_install.sh BUILD_DIR SOURCE_DIR PROJECT_VERSION WORK_DIR
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
version=$3
work=$4
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_file() { [ -f "$1" ] || fail "not installed: ${1#"$work"/}"; }

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" || { cat "$work/install.log"; exit 1; }
p=$work/prefix
expect_file "$p/bin/robotsim"
for f in workcells/gantry-cell.rsd robots/gantry.rsd grippers/parallel-gripper.rsd objects/block.rsd; do
  expect_file "$p/share/robotsim/stdlib/$f"
done
[ "$(find "$p/share/robotsim/stdlib" -type f ! -name '*.rsd' | wc -l)" -eq 0 ] || fail "the library holds files other than .rsd"
[ "$(find "$p/share/robotsim/stdlib" -name '*.rsd' | wc -l)" -eq "$(find "$source/stdlib" -name '*.rsd' | wc -l)" ] ||
  fail "not every .rsd of stdlib/ was installed"
expect_file "$p/share/man/man1/robotsim.1"
expect_file "$p/share/man/man1/robotsim-run.1"
expect_file "$p/share/man/man1/robotsim-version.1"
expect_file "$p/share/bash-completion/completions/robotsim"
expect_file "$p/share/doc/robotsim/README.md"
expect_file "$p/share/doc/robotsim/docs/install.md"
expect_file "$p/share/doc/robotsim/examples/gantry_pick.rsp"
# Nothing of the build tree or the source tree's tooling in the prefix.
if find "$p" -name '*.sh' -o -name 'CMakeLists.txt' -o -name node_modules | grep -q .; then
  fail "scripts or build files were installed: $(find "$p" -name '*.sh' -o -name 'CMakeLists.txt' | head -3)"
fi

# No path of the source tree in the shipped binary (a Release build has no
# debug information; a sanitizer build's reports name source files).
if grep -q "^CMAKE_BUILD_TYPE:STRING=Release$" "$build/CMakeCache.txt" &&
  grep -q "^ROBOTSIM_SANITIZE:BOOL=OFF$" "$build/CMakeCache.txt"; then
  # As a path into the tree ("SOURCE/stdlib/..."): a short source path such as
  # /src is also a piece of the ANTLR runtime's own file names
  # ("./runtime/src/atn/...") that the static binary carries.
  into_tree=()
  for d in "$source"/*/; do into_tree+=(-e "$d"); done
  ! grep -q -F "${into_tree[@]}" "$p/bin/robotsim" || fail "the installed binary holds the source tree's path $source"
fi

# Relocated: the whole prefix moved, used from a folder outside both trees.
mv "$p" "$work/moved"
m=$work/moved
mkdir -p "$work/user"
cp "$source/examples/gantry_pick.rsp" "$work/user/"
cd "$work/user"
if "$m/bin/robotsim" run gantry_pick.rsp --cell gantry-cell >"$work/installed.out" 2>&1; then
  "$build/robotsim" run gantry_pick.rsp --cell gantry-cell >"$work/build-tree.out" 2>&1 || fail "the build tree's robotsim failed"
  cmp -s "$work/installed.out" "$work/build-tree.out" || fail "the installed run differs from the build tree's: $(diff "$work/installed.out" "$work/build-tree.out" | head -5)"
  grep -q . "$work/installed.out" || fail "the installed run printed nothing"
else
  fail "the moved prefix's robotsim cannot run a program on a library cell: $(head -3 "$work/installed.out")"
fi
json=$("$m/bin/robotsim" --version --format=json)
case "$json" in
  *"\"version\":\"$version\""*) ;;
  *) fail "--version --format=json does not give version $version: $json" ;;
esac
case "$json" in
  *"\"library\":\"$m/share/robotsim/stdlib\""*) ;;
  *) fail "--version --format=json does not name the moved prefix's library: $json" ;;
esac
"$m/bin/robotsim" --version | head -1 | grep -qx "robotsim $version" || fail "--version's first line is not 'robotsim $version'"

# Copied alone: no library beside it, and no path back to the source tree.
mkdir -p "$work/alone"
cp "$m/bin/robotsim" "$work/alone/robotsim"
a=$work/alone/robotsim
case "$("$a" --version --format=json)" in
  *'"library":null'*) ;;
  *) fail "a lone copy still finds a library: $("$a" --version --format=json)" ;;
esac
"$a" --version | grep -q "^library: not found (looked in $work/share/robotsim/stdlib, $work/alone/share/robotsim/stdlib)" ||
  fail "a lone copy does not say where it looked: $("$a" --version | tail -1)"
set +e
"$a" run gantry_pick.rsp --cell gantry-cell >"$work/alone.out" 2>&1
code=$?
set -e
[ "$code" -eq 2 ] || fail "a lone copy ran a library cell it cannot have (exit $code)"
grep -q "gantry-cell.*no workcell or robot of that name on the library path" "$work/alone.out" ||
  fail "a lone copy's error does not say the cell is not on the library path: $(head -2 "$work/alone.out")"
# ... and --lib or ROBOTSIM_PATH give it one.
"$a" run gantry_pick.rsp --cell gantry-cell --lib "$m/share/robotsim/stdlib" >"$work/alone-lib.out" 2>&1 ||
  fail "--lib did not give a lone copy its library: $(head -2 "$work/alone-lib.out")"
cmp -s "$work/alone-lib.out" "$work/installed.out" || fail "the lone copy with --lib ran differently"
ROBOTSIM_PATH="$m/share/robotsim/stdlib" "$a" run gantry_pick.rsp --cell gantry-cell >"$work/alone-env.out" 2>&1 ||
  fail "ROBOTSIM_PATH did not give a lone copy its library"

# --lib and ROBOTSIM_PATH on top of the installed library: a cell of the
# user's own that places the library's gantry robot.
mkdir -p "$work/mine/workcells"
sed 's/^WORKCELL gantry-cell/WORKCELL my-gantry-cell/' "$m/share/robotsim/stdlib/workcells/gantry-cell.rsd" \
  >"$work/mine/workcells/my-gantry-cell.rsd"
grep -q "^WORKCELL my-gantry-cell" "$work/mine/workcells/my-gantry-cell.rsd" || fail "the test's own cell was not made"
set +e
"$m/bin/robotsim" run gantry_pick.rsp --cell my-gantry-cell >/dev/null 2>&1
code=$?
set -e
[ "$code" -eq 2 ] || fail "a cell that is on no path was found (exit $code)"
"$m/bin/robotsim" run gantry_pick.rsp --cell my-gantry-cell --lib "$work/mine" >"$work/mine-lib.out" 2>&1 ||
  fail "--lib on top of the installed library: $(head -2 "$work/mine-lib.out")"
ROBOTSIM_PATH="$work/mine" "$m/bin/robotsim" run gantry_pick.rsp --cell my-gantry-cell >"$work/mine-env.out" 2>&1 ||
  fail "ROBOTSIM_PATH on top of the installed library: $(head -2 "$work/mine-env.out")"

# The installed man page and completion, as man and bash use them.
if command -v man >/dev/null; then
  MANWIDTH=80 man -l "$m/share/man/man1/robotsim-version.1" 2>"$work/man.err" | grep -q -- "--format" ||
    fail "man -l robotsim-version.1 does not show --format"
  [ ! -s "$work/man.err" ] || fail "man -l warned: $(head -2 "$work/man.err")"
fi
completions=$(bash -c 'source "$1"; COMP_WORDS=(robotsim vers); COMP_CWORD=1; COMP_LINE="robotsim vers"; COMP_POINT=${#COMP_LINE}
  fn=$(complete -p robotsim | sed -E "s/.*-F ([^ ]+).*/\1/"); "$fn" robotsim vers robotsim; printf "%s\n" "${COMPREPLY[@]}"' _ \
  "$m/share/bash-completion/completions/robotsim")
[ "$completions" = version ] || fail "the installed completion gives '$completions' for 'robotsim vers', not 'version'"

# The source tarball (package_source): the tree under robotsim-VERSION/,
# without build trees, node_modules or .git.
(cd "$work" && cpack --config "$build/CPackSourceConfig.cmake" -B "$work/source-package" >"$work/source-package.log" 2>&1) ||
  fail "cpack of the source tarball failed: $(tail -3 "$work/source-package.log")"
tarball=$work/source-package/robotsim-$version.tar.gz
if [ -f "$tarball" ]; then
  tar tzf "$tarball" | LC_ALL=C sort >"$work/source-package.txt"
  for f in CMakeLists.txt stdlib/workcells/gantry-cell.rsd tools/cli/main.cpp docs/install.md editors/vscode/package.json \
    scripts/build_info.cmake; do
    grep -qx "robotsim-$version/$f" "$work/source-package.txt" || fail "the source tarball lacks $f"
  done
  grep -v "^robotsim-$version/" "$work/source-package.txt" | head -3 | grep . && fail "the source tarball has files outside robotsim-$version/"
  grep -E "/node_modules/|^robotsim-$version/build[^/]*/|/\.git(/|\$)|\.vsix\$" "$work/source-package.txt" | head -3 | grep . &&
    fail "the source tarball holds build trees, node_modules, .git or packages"
else
  fail "no $tarball"
fi

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok: installed to a prefix, moved, copied alone; library, --lib, ROBOTSIM_PATH, --version, man page, completion"
