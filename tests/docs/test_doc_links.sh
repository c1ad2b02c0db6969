#!/usr/bin/env bash
# The documentation link check (scripts/check-doc-links.sh) passes on the
# tree, and fails on copies of README.md and docs/ with a bad link planted:
# one out of the repository, one to a file that does not exist, an absolute
# path, a mention of ../shared, a reference-style link out of the tree;
# a link inside a code block or a code span is not a link.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check="$root/scripts/check-doc-links.sh"
bash "$check" "$root"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One copy of the whole source tree (docs may link to any of it), without
# builds; each case plants its text in one file and puts the file back.
mkdir -p "$work/tree"
(cd "$root" && tar cf - --exclude=./build --exclude='./build-*' --exclude=./.git --exclude=node_modules --exclude='*.vsix' .) |
  tar xf - -C "$work/tree"
planted=""
plant() {  # FILE TEXT: the last case's file as it was, then this one's text
  [ -n "$planted" ] && cp "$root/$planted" "$work/tree/$planted"
  planted=$1
  printf '%s\n' "$2" >> "$work/tree/$1"
}
expect_failure() {  # FILE TEXT-TO-PLANT EXPECTED-MESSAGE
  plant "$1" "$2"
  if out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check passed with '$2' planted in $1" >&2; exit 1
  fi
  if ! grep -qF "$3" <<<"$out"; then
    echo "FAIL: expected '$3' in:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: '$2' in $1 is refused"
}
expect_pass() {  # FILE TEXT-TO-PLANT
  plant "$1" "$2"
  if ! out=$(bash "$check" "$work/tree" 2>&1); then
    echo "FAIL: the check refused '$2' in $1:" >&2; echo "$out" >&2; exit 1
  fi
  echo "ok: '$2' in $1 passes"
}
lines() { wc -l < "$root/$1" | tr -d ' '; }

expect_failure docs/serial.md 'See [the notes](../../shared/rhino-protocol.md).' \
  "docs/serial.md:$(( $(lines docs/serial.md) + 1 )): error: link '../../shared/rhino-protocol.md' points outside the repository"
expect_failure docs/cli.md 'See [x](../../../etc/passwd).' "points outside the repository"
expect_failure README.md 'See [x](docs/nowhere.md#top).' "README.md:$(( $(lines README.md) + 1 )): error: link 'docs/nowhere.md#top' names no file"
expect_failure docs/models.md '![a picture](images/missing.png)' "link 'images/missing.png' names no file"
expect_failure docs/language.md 'See [x](/etc/passwd).' "is an absolute path"
expect_failure docs/serial.md 'The notes are in `../shared/rhino-protocol.md`.' "mentions '../shared'"
expect_failure docs/render.md '[notes]: ../../shared/x.md' "link '../../shared/x.md' points outside the repository"
expect_failure docs/testing.md $'A link [over\ntwo lines](nowhere.md).' \
  "docs/testing.md:$(( $(lines docs/testing.md) + 2 )): error: link 'nowhere.md' names no file"
expect_pass docs/cli.md 'Online: [site](https://example.org/x) and [here](#exit-codes).'
expect_pass docs/cli.md 'Code: `[a](nowhere.md)` is not a link.'
expect_pass docs/cli.md $'```\n[a](nowhere.md)\n```'
