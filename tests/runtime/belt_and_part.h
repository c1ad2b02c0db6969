// The small belt and part the device tests build their cells from: a belt
// 1000 long (x 0..1000, top y 10, z 5..45, running towards +x) and a
// 10-unit part. The cell-section, device-run and fuzz tests all place them.
#pragma once

namespace celltest {

inline constexpr const char* kBeltAndPart =
    "OBJECT belt\n"
    "  BOX 0 1000 10 0 50 0\n"
    "  BELT 0 1000 10 0 45 5 DIRECTION 1 0 0\n"
    "END\n"
    "OBJECT blk\n"
    "  PART\n"
    "  BOX 0 10 10 0 10 0\n"
    "END\n";

}  // namespace celltest
