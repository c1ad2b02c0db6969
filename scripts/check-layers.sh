#!/usr/bin/env bash
# Checks that every `#include "..."` in the tree points down or sideways,
# never up: the allowed edges are those of scripts/layers.txt.
#
#   scripts/check-layers.sh [ROOT]     (ROOT defaults to this checkout)
#
# A file's layer is the longest layer folder that contains it; an include's
# layer is found the same way from its path. An include without a folder is
# either a file beside the includer or a generated grammar header
# (RobotProgramParser.h, ...). Prints one `file:line: error:` per bad
# include and exits 1 if there is any; exits 0 and prints a one-line
# summary otherwise. Also fails when the list itself names an unknown or a
# later layer, when a source file belongs to no layer, and when the list
# allows an edge no include uses (the list is the code's edges exactly).
set -euo pipefail
root=${1:-"$(cd "$(dirname "$0")/.." && pwd)"}
layers="$(dirname "$0")/layers.txt"
[ -f "$root/scripts/layers.txt" ] && layers="$root/scripts/layers.txt"

cd "$root"
find base diag model vm stdlib compiler runtime launch tools bench tests \
  -path tests/browser/node_modules -prune -o \
  \( -name '*.h' -o -name '*.cpp' \) -type f -print 2>/dev/null | LC_ALL=C sort |
awk -v layersFile="$layers" '
  function layerOf(path,    best, l) {
    best = ""
    for (l in allowed)
      if (index(path, l "/") == 1 && length(l) > length(best)) best = l
    return best
  }
  function normalize(path,    n, i, k, seg, out) {
    n = split(path, seg, "/"); k = 0
    for (i = 1; i <= n; i++) {
      if (seg[i] == "." || seg[i] == "") continue
      if (seg[i] == "..") { if (k > 0) k--; continue }
      out[++k] = seg[i]
    }
    path = out[1]
    for (i = 2; i <= k; i++) path = path "/" out[i]
    return path
  }
  BEGIN {
    bad = 0; n = 0
    while ((getline line < layersFile) > 0) {
      sub(/#.*/, "", line)
      if (line ~ /^[ \t]*$/) continue
      split(line, parts, ":")
      name = parts[1]; gsub(/[ \t]/, "", name)
      if (name in allowed) { printf "%s: error: layer %s is listed twice\n", layersFile, name; bad = 1 }
      allowed[name] = " "; order[name] = ++n
      m = split(parts[2], deps, /[ \t]+/)
      for (i = 1; i <= m; i++) {
        if (deps[i] == "") continue
        if (!(deps[i] in order)) {
          printf "%s: error: layer %s may include %s, which is not listed before it\n", layersFile, name, deps[i]
          bad = 1
        }
        allowed[name] = allowed[name] deps[i] " "
      }
    }
    close(layersFile)
  }
  {
    file = $0; files++
    from = layerOf(file)
    if (from == "") { printf "%s: error: this file belongs to no layer of %s\n", file, layersFile; bad = 1; next }
    dir = file; sub(/\/[^\/]*$/, "", dir)
    lineNo = 0
    while ((getline text < file) > 0) {
      lineNo++
      if (text !~ /^[ \t]*#[ \t]*include[ \t]*"/) continue
      inc = text; sub(/^[^"]*"/, "", inc); sub(/".*$/, "", inc)
      includes++
      if (inc ~ /^\.\.?\//) inc = normalize(dir "/" inc)  # relative to the includer
      if (inc !~ /\//) {
        if ((getline probe < (dir "/" inc)) >= 0) { close(dir "/" inc); continue }  # beside the includer
        if (inc ~ /^Robot(Program|Model)(Lexer|Parser)\.h$/) to = "grammar"
        else { printf "%s:%d: error: include \"%s\" names no file of the tree\n", file, lineNo, inc; bad = 1; continue }
      } else {
        to = layerOf(inc)
        if (to == "") { printf "%s:%d: error: include \"%s\" is in no layer\n", file, lineNo, inc; bad = 1; continue }
      }
      if (to == from) continue
      if (index(allowed[from], " " to " ") > 0) { used[from " " to] = 1; continue }
      printf "%s:%d: error: %s includes \"%s\" of layer %s, which %s may not include (%s)\n",
             file, lineNo, from, inc, to, from, layersFile
      bad = 1
    }
    close(file)
  }
  END {
    for (l in allowed) {
      m = split(allowed[l], deps, " ")
      for (i = 1; i <= m; i++)
        if (deps[i] != "" && !((l " " deps[i]) in used)) {
          printf "%s: error: layer %s may include %s, but no file of it does: drop the edge\n", layersFile, l, deps[i]
          bad = 1
        }
    }
    if (bad) exit 1
    printf "layers: %d files, %d includes, every one points down, every allowed edge used (%s)\n", files, includes, layersFile
  }'
