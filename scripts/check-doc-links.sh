#!/usr/bin/env bash
# Checks the product documentation's links: every relative markdown link in
# README.md and docs/ (inline `[text](target)`, images `![alt](target)` and
# reference definitions `[name]: target`, outside fenced code blocks) must
# name a file or folder that exists inside the repository, and no document
# may mention `../shared` (notes outside the repository, which a reader of
# the product does not have).
#
#   scripts/check-doc-links.sh [ROOT]     (ROOT defaults to this checkout)
#
# Links to http(s)://, mailto: and anchors in the same page (#...) are not
# files and are skipped. Prints one `file:line: error:` per bad link and
# exits 1 if there is any; prints a one-line summary and exits 0 otherwise.
set -euo pipefail
root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
root=$(cd "$root" && pwd -P)
cd "$root"

docs=(README.md)
while IFS= read -r f; do docs+=("$f"); done < <(find docs -name '*.md' -type f | LC_ALL=C sort)

bad=0
links=0
for doc in "${docs[@]}"; do
  [ -f "$doc" ] || continue
  dir=$(dirname "$doc")
  # file<TAB>line<TAB>target, one per link, fences skipped.
  while IFS=$'\t' read -r line target; do
    links=$((links + 1))
    case "$target" in
      http://* | https://* | mailto:* | '#'*) continue ;;
    esac
    path=${target%%#*}
    path=${path%%\?*}
    if [ -z "$path" ]; then continue; fi
    if [ "${path#/}" != "$path" ]; then
      echo "$doc:$line: error: link '$target' is an absolute path: link relative to the file" >&2
      bad=$((bad + 1))
      continue
    fi
    resolved=$(realpath -m -- "$dir/$path")
    case "$resolved/" in
      "$root"/*) ;;
      *)
        echo "$doc:$line: error: link '$target' points outside the repository" >&2
        bad=$((bad + 1))
        continue
        ;;
    esac
    if [ ! -e "$resolved" ]; then
      echo "$doc:$line: error: link '$target' names no file (${resolved#"$root"/})" >&2
      bad=$((bad + 1))
    fi
  done < <(perl -0777 -ne '
      # Fenced code blocks and code spans are not links: blank them out,
      # keeping the newlines so that line numbers stay right.
      s{^[ \t]*(```|~~~).*?^[ \t]*\1[^\n]*$}{ $& =~ s/[^\n]//gr }gmse;
      s{`(?:[^`\n]|\n(?![ \t]*\n))*`}{ $& =~ s/[^\n]/ /gr }ge;   # may run over a line, not a paragraph
      # Inline links and images; the text may run over a line break.
      while (/!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g) {
        my ($target, $end) = ($1, $-[1]);
        my $line = 1 + (substr($_, 0, $end) =~ tr/\n//);
        print "$line\t$target\n";
      }
      # Reference definitions: "[name]: target" at the start of a line.
      while (/^ {0,3}\[[^\]]+\]:[ \t]*<?(\S+?)>?(?:[ \t]|$)/gm) {
        my $line = 1 + (substr($_, 0, $-[1]) =~ tr/\n//);
        print "$line\t$1\n";
      }
    ' "$doc")
  # Notes outside the repository must not be referred to at all.
  while IFS=: read -r line _; do
    echo "$doc:$line: error: mentions '../shared' (outside the repository): put what the reader needs in docs/" >&2
    bad=$((bad + 1))
  done < <(grep -n -F '../shared' "$doc" || true)
done

if [ "$bad" -ne 0 ]; then
  echo "check-doc-links: $bad bad link(s)" >&2
  exit 1
fi
echo "check-doc-links: ${#docs[@]} files, $links links, all inside the repository"
