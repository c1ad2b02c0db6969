#include "bench/collision_programs.h"

#include <fmt/format.h>

namespace rs::bench {

namespace {

// 4 instructions a loop, 333,335 loops: 1,333,342 instructions with SET
// and END; two short moves a loop between two taught points near the
// arm's home pose.
constexpr const char* kLongLoop = R"(        SET N 0
loop:   MOVEP P1
        MOVEP P2
        ADD N 1
        JMPVAR N < {} loop
        END
POINTS
)";

// A block taken from where it rests, lifted off it, carried to another
// place, put down, taken again and carried back: 13 moves a loop, with a
// take and a let-go each way. The first {} is what comes before the loop,
// the second the lift; the third stays {} for the loop count.
constexpr const char* kPickAndPlace = R"(        SET N 0
{}loop:   MOVEP ABOVE
        MOVEP PICK
        MOVEP TAKE
{}        MOVEP LIFT
        MOVEP OVER
        MOVEP PLACE
        MOVEP DROP
        MOVEP RETAKE
        MOVEP OVERC
        MOVEP LIFTC
        MOVEP PICKC
        MOVEP RELEASE
        ADD N 1
        JMPVAR N < {} loop
        END
POINTS
)";

}  // namespace

std::vector<CollisionProgram> collisionPrograms() {
  std::vector<CollisionProgram> out;
  // scara-pick: the front block onto the back-left one and back (the
  // points of examples/stack_blocks.rsp).
  out.push_back({"scara-pick", "long loop", std::string(kLongLoop) + R"(P1 AT -200 850 0 GRIP 0
P2 AT -180 860 20 GRIP 0
)", 333'335});
  out.push_back({"scara-pick", "pick and place", fmt::format(kPickAndPlace, "", "        MOVEP LIFT0\n", "{}") + R"(ABOVE   AT -130 870 0          GRIP 0
PICK    AT -130 819 0          GRIP 0
TAKE    AT -130 819 0          GRIP 120
LIFT0   AT -130 824 0          GRIP 120
LIFT    AT -130 870 0          GRIP 120
OVER    AT -180 875 -45        GRIP 120
PLACE   AT -180 859 -45        GRIP 120
DROP    AT -180 859 -45        GRIP 0
RETAKE  AT -180 859 -45        GRIP 120
OVERC   AT -180 875 -45        GRIP 120
LIFTC   AT -130 870 0          GRIP 120
PICKC   AT -130 819 0          GRIP 120
RELEASE AT -130 819 0          GRIP 0
)", 20'000});
  // puma-cell: away from the table first (its forearm would sweep through
  // it), then the first block on the table 150 to the side and back; the
  // block is lifted off the table by the shoulder alone (a move of several
  // joints at their own speeds would dip it into the table on the way).
  // Taken and put back at the same height (there is no gravity: a block
  // put back 6 higher than it was taken rose 6 a loop, and the wrist went
  // 6 deeper into it each time, until it hit it in the fourth loop).
  out.push_back({"puma-cell", "long loop", std::string(kLongLoop) + R"(P1 AT 450 400 -150 APPROACH 0 -1 0 NORMAL 0 0 1 GRIP 0
P2 AT 430 420 -130 GRIP 0
)", 333'335});
  out.push_back({"puma-cell", "pick and place",
                 fmt::format(kPickAndPlace, "        MOVETO 0 0 900 0 0 0 0\n        MOVETO 0 -900 900 0 0 0 0\n        MOVEP UP\n",
                             "        MOVE 0 -20 0 0 0 0 0\n", "{}") + R"(UP      AT 400 1000 0 APPROACH 0 -1 0 NORMAL 0 0 1 GRIP 0
ABOVE   AT 620 950 0       GRIP 0
PICK    AT 620 781 0       GRIP 0
TAKE    AT 620 781 0       GRIP 100
LIFT    AT 620 950 0       GRIP 100
OVER    AT 620 950 150     GRIP 100
PLACE   AT 620 781 150     GRIP 100
DROP    AT 620 781 150     GRIP 0
RETAKE  AT 620 781 150     GRIP 100
OVERC   AT 620 950 150     GRIP 100
LIFTC   AT 620 950 0       GRIP 100
PICKC   AT 620 781 0       GRIP 100
RELEASE AT 620 781 0       GRIP 0
)", 20'000});
  // xr4-cell: the first block across the pallet and back, lifted off the
  // pallet by the shoulder alone; taken and put back at the same height, as
  // on puma-cell (a finger hit the block in the fifth loop). Put down at the
  // height it was taken (1 above its middle), not 5 higher: a part let go
  // settles onto its support (issue 35), and the block, dropped 5 and taken
  // again, went 5 into the pallet at PICKC.
  out.push_back({"xr4-cell", "long loop", std::string(kLongLoop) + R"(P1 AT 250 950 0 APPROACH 0 -1 0 GRIP 0
P2 AT 270 960 20 GRIP 0
)", 333'335});
  out.push_back({"xr4-cell", "pick and place", fmt::format(kPickAndPlace, "", "        MOVE 0 -10 0 0 0 0\n", "{}") + R"(ABOVE   AT 240 900 -40 APPROACH 0 -1 0 GRIP 0
PICK    AT 240 801 -40     GRIP 0
TAKE    AT 240 801 -40     GRIP 115
LIFT    AT 240 900 -40     GRIP 115
OVER    AT 320 900 0       GRIP 115
PLACE   AT 320 801 0       GRIP 115
DROP    AT 320 801 0       GRIP 0
RETAKE  AT 320 801 0       GRIP 115
OVERC   AT 320 900 0       GRIP 115
LIFTC   AT 240 900 -40     GRIP 115
PICKC   AT 240 801 -40     GRIP 115
RELEASE AT 240 801 -40     GRIP 0
)", 20'000});
  return out;
}

}  // namespace rs::bench
