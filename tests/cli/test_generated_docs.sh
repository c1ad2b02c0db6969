#!/usr/bin/env bash
# The man pages the build wrote (the robotsim_docs target: DOCS/man1),
# checked against the built robotsim itself: one page for robotsim and one
# for each command its --help lists, no other; each renders in man-db with
# groff's warnings on and nothing on standard error; lexgrog (what mandb
# and apropos index) reads its NAME line as "robotsim-COMMAND - HELP"; and
# every option that `robotsim COMMAND --help` prints is in the rendered
# page. The completions are there too.
# Usage: test_generated_docs.sh ROBOTSIM_BINARY DOCS_DIR
set -euo pipefail
binary=$1 docs=$2
fail() { echo "test_generated_docs: FAILED: $*" >&2; exit 1; }
command -v man >/dev/null && command -v lexgrog >/dev/null || { echo "man-db is not installed: skipped" >&2; exit 77; }
export LC_ALL=C.UTF-8 MANWIDTH=80
for f in robotsim.bash _robotsim robotsim.fish man1/robotsim.1; do
  [ -s "$docs/$f" ] || fail "$docs/$f is missing: is robotsim_docs built?"
done

# The commands, from --help's Subcommands list (two spaces, a name, spaces, the help).
mapfile -t commands < <("$binary" --help | awk '/^Subcommands:/ { on = 1; next } on && /^$/ { exit } on && /^  [a-z]/ { print $1 }')
[ "${#commands[@]}" -ge 10 ] || fail "robotsim --help lists ${#commands[@]} commands"
expected=$(printf 'robotsim.1\n'; printf 'robotsim-%s.1\n' "${commands[@]}")
actual=$(cd "$docs/man1" && ls)
[ "$(sort <<< "$expected")" = "$(sort <<< "$actual")" ] || fail "pages: $actual; expected: $expected"

check_page() {
  local page=$1 name=$2
  local warnings
  warnings=$(man --warnings -E UTF-8 -l "$page" 2>&1 >/dev/null) || fail "man -l $page failed: $warnings"
  [ -z "$warnings" ] || fail "man -l $page warns: $warnings"
  local whatis
  whatis=$(lexgrog "$page") || fail "lexgrog cannot read $page"
  grep -qF ": \"$name - " <<< "$whatis" || fail "lexgrog $page: $whatis"
}
check_page "$docs/man1/robotsim.1" robotsim
for c in "${commands[@]}"; do
  page=$docs/man1/robotsim-$c.1
  check_page "$page" "robotsim-$c"
  help_line=$("$binary" --help | awk -v c="$c" '$1 == c { $1 = ""; sub(/^ +/, ""); print; exit }')
  lexgrog "$page" | grep -F -- "- ${help_line:0:40}" >/dev/null || fail "$c: the NAME line is not --help's: $help_line"
  text=$(man -E UTF-8 -l "$page" 2>/dev/null | col -b)
  # Every option --help shows ("  -o,--output TEXT ..." at a line's start).
  mapfile -t options < <("$binary" "$c" --help | grep -oE '^  +(-[a-zA-Z],)?--?[a-z][a-z-]*' | tr ',' '\n' | tr -d ' ')
  [ "${#options[@]}" -ge 2 ] || fail "$c --help shows ${#options[@]} options"
  for o in "${options[@]}"; do
    grep -qE -- "(^|[ ,])$o([ ,=]|$)" <<< "$text" || fail "robotsim-$c.1 does not name $o"
  done
done
echo "test_generated_docs: ok (${#commands[@]} commands)"
