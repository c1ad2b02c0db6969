// The cell the pendant's and the terminal pendant's device tests jog a
// block in: the library's gantry (Cartesian, 0.1 mm per count, the tool
// centre point at (500 + X/10, 200 - Y/10, 400 + Z/10)) over a block
// centred at (220, 50, 680) on a pallet, and a beam across x = 400 at
// y = 200, wired to input 1.
#pragma once

namespace teachtest {

inline constexpr const char* kCarryCell =
    "WORKCELL carry\n"
    "  ROBOT gantry    AT 0 1000 0\n"
    "  OBJECT pallet   AT 150 0 760\n"
    "  OBJECT block    AT 200 30 700\n"
    "  SENSOR eye BEAM 400 200 600  400 200 760\n"
    "  WIRE eye TO IN 1\n"
    "END\n";

}  // namespace teachtest
