#!/bin/sh
# Regenerates the pictures in docs/images with `robotsim render`: one PNG of
# each library robot (stdlib/robots/*.rsd) at its home pose, and one of each
# library workcell (stdlib/workcells/*.rsd). Run it after a robot or the
# renderer changes, and commit the result:
#
#   docs/images/regenerate.sh BUILD/robotsim
#
# (the build's `docs-images` target runs it). Deterministic: the same robotsim
# and the same descriptions give the same files.
set -eu
robotsim=${1:?usage: regenerate.sh PATH/TO/robotsim}
here=$(cd "$(dirname "$0")" && pwd)
stdlib=$(cd "$here/../../stdlib" && pwd)
for file in "$stdlib"/robots/*.rsd; do
  name=$(basename "$file" .rsd)
  "$robotsim" render "$name" --size 800x600 -o "$here/robot-$name.png"
  echo "docs/images/robot-$name.png"
done
for file in "$stdlib"/workcells/*.rsd; do
  name=$(basename "$file" .rsd)
  "$robotsim" render "$name" --size 800x600 -o "$here/cell-$name.png"
  echo "docs/images/cell-$name.png"
done
# The chart of a run (docs/render.md, "Charts of a run").
"$robotsim" plot "$here/../../examples/gantry_pick.rsp" --cell gantry-cell -o "$here/plot-gantry-pick.png"
echo "docs/images/plot-gantry-pick.png"
# The tool's path (docs/render.md, "The tool's path"): a MOVES line beside a MOVEP curve.
"$robotsim" render xr4-cell --program "$here/path-moves-movep.rsp" --path --zoom 2.5 --center 100,900,100 \
  --view 60,-20,0 --size 800x600 -o "$here/path-moves-movep.png"
echo "docs/images/path-moves-movep.png"
