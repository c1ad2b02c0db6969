// A gantry whose one motor counts 0.01 of a length unit over ±100,000: a
// MOVES of 140,000 along X is cut to the planner's shortest step, 1/65,536
// of the line, each knot 2.1 long and 214 counts: 65,536 knots a line. The
// debugger's work is measured on it (bench/moves_bench.cpp) and counted
// (tests/debug/test_debug_work.cpp).
#pragma once

#include <string_view>

namespace rs::bench {

inline constexpr std::string_view kBigGantry = R"(LINK big_base
  BOX -10 10 0 -10 10 -10
END
LINK big_carriage
  BOX -20 20 40 0 20 -20
END
ROBOT big-gantry
  LINK big_base      FRAME ORIGIN 0 0 0  XAXIS 0 100 0  ZAXIS 100 0 0
  LINK big_carriage  FRAME ORIGIN 0 0 0  XAXIS 0 100 0  ZAXIS 100 0 0
  JOINT 1 PRISMATIC  LETTER X  PRECISION 0.01  RANGE -10000000 10000000  SPEED 1000000000
END
WORKCELL big-cell
  FLOOR NONE
  ROBOT big-gantry AT 0 100 0
END
)";

}  // namespace rs::bench
