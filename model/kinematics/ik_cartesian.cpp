// Cartesian arms (three prismatic joints): p = origin + axes · d, a linear
// system solved with the inverse worked out once. One solution; the
// orientation never changes (InverseKinematics::solve checks what was
// written against it).
#include "model/kinematics/ik_solvers.h"

namespace rs::kinematics::ik {

void solveCartesian(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, IkSolutions& out) {
  const Eigen::Vector3d d = f.axesInverse * (t.position - f.origin);
  IkSolution& s = out.solutions[0];
  for (int i = 0; i < 3; ++i) s.q[static_cast<std::size_t>(i)] = d[i];
  (void)m;
  out.count = 1;
}

}  // namespace rs::kinematics::ik
