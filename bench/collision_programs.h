// The programs of the collision benchmark's targets (issue 23): on each of
// scara-pick, puma-cell and xr4-cell a long loop of short moves and a long
// pick-and-place (a block taken, carried, put down and taken back, every
// loop), both free of collisions, so that a run with --collisions=error
// goes to the end and checks every move. `{}` is the number of loops.
#pragma once

#include <string>
#include <vector>

namespace rs::bench {

struct CollisionProgram {
  std::string cell;
  std::string kind;  ///< "long loop" or "pick and place"
  std::string text;  ///< with one {} for the loop count
  long loops = 0;    ///< the benchmark's count (--smoke: a few)
};

/// The six programs, scara-pick first.
std::vector<CollisionProgram> collisionPrograms();

}  // namespace rs::bench
