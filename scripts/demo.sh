#!/usr/bin/env bash
# Installs what building needs, builds the robotsim command (only it), and
# runs the demo: a pick-and-place program on the simulated Rhino SCARA, with
# its input handshakes played by a stimuli file, then the run summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh robotsim
echo
./build/robotsim run examples/pick_and_place.rsp --stimuli examples/pick_and_place.stim
