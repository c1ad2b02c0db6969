// The parts of collision_bench (bench/collision_main.cpp says what each
// measures); figures in docs/performance.md, "Collisions".
#pragma once

#include <string>

namespace rs::bench {

struct CollisionBenchOptions {
  int reps = 5;
  std::string robotsim;                     ///< the binary, for the test part
  std::string workDir = "collision-bench";  ///< the test part's copies of the examples
  bool smoke = false;                       ///< tiny sizes, one repetition
};

void benchGjk(const CollisionBenchOptions& options);
void benchSweep(const CollisionBenchOptions& options);
void benchWorkcellRuns(const CollisionBenchOptions& options);
void benchTestExamples(const CollisionBenchOptions& options);

}  // namespace rs::bench
