// SCARA arms: every joint axis parallel (ik_planar.h with the run 1..n).
// The prismatic joint sets the height along the axes; the revolute joints
// are a two-link planar problem, after taking off the last link at the
// wanted heading when there is a third (roll) joint. Two solutions: the
// elbow to one side or the other (or the one Branches asks for).
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/ik_solvers.h"

namespace rs::kinematics::ik {

void solveScara(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want,
                IkSolutions& out) {
  const PlanarRun& run = f.run;
  const Eigen::Vector3d& p = t.position;
  double d = 0;  // the prismatic joint's value
  if (run.prismatic != 0) {
    d = (p.z() - run.along) / run.prismaticSign;
  } else if (std::abs(p.z() - run.along) > 1e-7 * f.reach) {
    return fail(out, IkErrorKind::Unreachable, std::abs(p.z() - run.along),
                fmt::format("the point is {:.4g} along the joint axes from the only height the arm reaches",
                            std::abs(p.z() - run.along)),
                "this arm has no joint that moves along its axes");
  }
  // The heading of the tool's x axis about the axes is ψ_n = Φ_last + c_n.
  const double heading = std::atan2(t.rotation(1, 0), t.rotation(0, 0));
  Eigen::Vector2d W = p.head<2>() - run.offset;
  double phiLast = 0;
  if (run.revolutes == 3) {
    phiLast = heading - run.fixedHeading;
    W -= rotate2(phiLast, run.link[2]);
  }
  std::array<Eigen::Vector2d, 2> phis;
  double miss = 0, sinElbow = 0;
  if (!solveTwoLink(W, run.link[0], run.link[1], phis, miss, sinElbow, want.elbow()))
    return fail(out, IkErrorKind::Unreachable, miss,
                fmt::format("the point is {:.4g} out of the arm's reach (its links reach {:.4g} to {:.4g} from joint "
                            "{}'s axis)",
                            miss, innerReach(run.link[0].norm(), run.link[1].norm()),
                            run.link[0].norm() + run.link[1].norm(), run.revolute[0]),
                "move the point within the ring the arm sweeps");
  if (sinElbow < std::sin(kSingularDegrees * kDegToRad))
    return fail(out, IkErrorKind::Singular, std::asin(sinElbow) * kRadToDeg,
                fmt::format("near-singular pose: joint {} would be {:.3g} degrees from stretched or folded straight",
                            run.revolute[1], std::asin(sinElbow) * kRadToDeg),
                fmt::format("keep the point so that joint {} bends at least {} degree", run.revolute[1],
                            kSingularDegrees));
  for (std::size_t k = 0; k < 2; ++k) {
    if (!want.takes(kElbowDown, k == 1)) continue;
    IkSolution& s = out.solutions[static_cast<std::size_t>(out.count++)];
    for (int i = 1; i <= m.size(); ++i) s.q[static_cast<std::size_t>(i - 1)] = m.joint(i).home;
    const double phi[3] = {phis[k].x(), phis[k].y(), phiLast};
    double previous = 0;
    for (int g = 0; g < run.revolutes; ++g) {
      const std::size_t gi = static_cast<std::size_t>(g);
      s.q[static_cast<std::size_t>(run.revolute[gi] - 1)] = wrapDegrees((phi[g] - previous) / run.sign[gi] * kRadToDeg);
      previous = phi[g];
    }
    if (run.prismatic != 0) s.q[static_cast<std::size_t>(run.prismatic - 1)] = d;
    s.config = k == 0 ? 0 : kElbowDown;
  }
}

}  // namespace rs::kinematics::ik
