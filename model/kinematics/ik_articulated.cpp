// Arms whose joint 1 turns the plane the rest of the arm works in
// (α_1 = ±90): joint 1 from the target's offset across that plane
// (baseAngles: facing the target, or turned back over the top), then, in
// the plane, the shoulder and elbow as a two-link problem (ik_planar.h).
//
//   Articulated5: the tool point itself, after taking off the last pitch
//     link at the pitch the approach asks for; joint 5 rolls the normal.
//   Articulated6: the wrist centre, p - R Rx(-α6) (a6, 0, d6); the wrist
//     (ik_wrist.cpp) then sets the orientation.
//   Spherical6: the wrist centre again, reached by joint 2 and the
//     prismatic joint 3 in polar form.
//
// Each form walks its branches (shoulder front or back, elbow + or -,
// wrist flipped or not) as Branches says: all of them, or one path.
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/kinematics/ik_solvers.h"

namespace rs::kinematics::ik {

namespace {

// A branch's error is kept unless one already is; a singular pose wins
// over an unreachable one (the branch that misses may not be the one that
// was meant).
void note(IkError& kept, const IkError& error) {
  if (kept.message.empty() || (error.kind == IkErrorKind::Singular && kept.kind != IkErrorKind::Singular)) kept = error;
}

double deg(double radians) { return wrapDegrees(radians * kRadToDeg); }

// q of the run's revolute joints from the planar angles Φ_g.
void setRun(const PlanarRun& run, const double* phi, IkSolution& s) {
  double previous = 0;
  for (int g = 0; g < run.revolutes; ++g) {
    const std::size_t gi = static_cast<std::size_t>(g);
    s.q[static_cast<std::size_t>(run.revolute[gi] - 1)] = deg((phi[g] - previous) / run.sign[gi]);
    previous = phi[g];
  }
}

void outOfReach(const FamilyShape& f, double miss, IkSolutions& out) {
  fail(out, IkErrorKind::Unreachable, miss,
       fmt::format("the point is {:.4g} out of the arm's reach (joints {} and {} reach {:.4g} to {:.4g} from joint {})",
                   miss, f.run.revolute[0], f.run.revolute[1],
                   innerReach(f.run.link[0].norm(), f.run.link[1].norm()), f.run.link[0].norm() + f.run.link[1].norm(),
                   f.run.revolute[0]),
       "move the point nearer the shoulder");
}

bool bentEnough(const FamilyShape& f, double sinElbow, IkSolutions& out) {
  if (sinElbow >= std::sin(kSingularDegrees * kDegToRad)) return true;
  fail(out, IkErrorKind::Singular, std::asin(sinElbow) * kRadToDeg,
       fmt::format("near-singular pose: joint {} would be {:.3g} degrees from stretched or folded straight",
                   f.run.revolute[1], std::asin(sinElbow) * kRadToDeg),
       fmt::format("bring the point nearer the shoulder, so that joint {} bends at least {} degree",
                   f.run.revolute[1], kSingularDegrees));
  return false;
}

Eigen::Vector3d wristCentre(const ChainModel& m, const ToolTarget& t) {
  const Joint& j6 = m.joint(6);
  // R Rx(-α6) (a6, 0, d6): Rx(-α6) keeps x, turns (0, 0, d6) to (0, d6 sin α6, d6 cos α6).
  const Eigen::Vector3d local(j6.dh.a, j6.dh.d * j6.sinAlpha, j6.dh.d * j6.cosAlpha);
  return t.position - t.rotation * local;
}

// Adds the wrist solutions wanted (both, or the flipped one or the other)
// for arm joints q[0..2] already set in `arm`. The flipped wrist is
// derived from the other (ik_wrist.cpp), so either costs the same.
void addWrist(const ChainModel& m, const ToolTarget& t, IkSolution arm, const Branches& want, IkSolutions& out,
              IkError& firstError) {
  IkSolution a = arm, b = arm;
  const Eigen::Matrix3d R_0_3 = frameOf(m, arm.q.data(), 3).linear();
  IkError error;
  if (!solveWrist(m, R_0_3.transpose() * t.rotation, a, b, error)) {
    note(firstError, error);
    return;
  }
  if (want.takes(kWristFlip, false)) out.solutions[static_cast<std::size_t>(out.count++)] = a;
  if (want.takes(kWristFlip, true)) out.solutions[static_cast<std::size_t>(out.count++)] = b;
}

void finish(IkSolutions& out, const IkError& firstError) {
  if (out.count == 0) out.error = firstError;
}

}  // namespace

void solveArticulated5(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, std::span<const double> ref,
                       const Branches& want, IkSolutions& out) {
  const PlanarRun& run = f.run;
  double th1[2];
  if (!baseAngles(f, t.position, run.along, th1, out)) return;
  const Joint &j1 = m.joint(1), &j4 = m.joint(4), &j5 = m.joint(5);
  // The approach in frame 1: written, or kept at the previous point's pitch.
  const Eigen::Matrix3d R_0_1ref = dhTransform(j1.dh, ref[0]).linear();
  // z_5 = cos α5 · z_4, and z_4 in frame 1 is Rz(ψ4) (0, -σ4 sin α4).
  const Eigen::Vector2d g(0.0, -run.sign[2] * j4.sinAlpha * j5.cosAlpha);
  // What the arm reaches is checked here, not by forward kinematics: a
  // written approach must lie in the arm's plane (no component along z_1),
  // a written normal at right angles to the approach reached (none along z_4).
  constexpr double kInPlane = 1e-7;
  IkError firstError;
  for (int b = 0; b < 2; ++b) {
    if (!want.takes(kShoulderBack, b == 1)) continue;
    const Eigen::Isometry3d A1 = dhTransform(j1.dh, deg(th1[b]));
    const Eigen::Vector3d T1 = A1.inverse() * t.position;
    const Eigen::Vector3d a1 = (t.approachGiven ? A1.linear() : R_0_1ref).transpose() * t.rotation.col(2);
    IkSolutions scratch;
    if (t.approachGiven && std::abs(a1.z()) > kInPlane) {
      fail(scratch, IkErrorKind::OrientationFixed, std::asin(std::min(1.0, std::abs(a1.z()))) * kRadToDeg,
           fmt::format("the tool cannot take that orientation: {}", familyOrientation(IkFamily::Articulated5)), "");
      note(firstError, scratch.error);
      continue;
    }
    const double psi = std::atan2(a1.y(), a1.x()) - std::atan2(g.y(), g.x());
    const double phiLast = psi - run.fixedHeading;
    const Eigen::Vector2d W = T1.head<2>() - run.offset - rotate2(phiLast, run.link[2]);
    std::array<Eigen::Vector2d, 2> phis;
    double miss = 0, sinElbow = 0;
    if (!solveTwoLink(W, run.link[0], run.link[1], phis, miss, sinElbow, want.elbow())) {
      outOfReach(f, miss, scratch);
    } else if (bentEnough(f, sinElbow, scratch)) {
      for (std::size_t e = 0; e < 2; ++e) {
        if (!want.takes(kElbowDown, e == 1)) continue;
        IkSolution s;
        s.q[0] = deg(th1[b]);
        const double phi[3] = {phis[e].x(), phis[e].y(), phiLast};
        setRun(run, phi, s);
        s.config = static_cast<std::uint8_t>((b ? kShoulderBack : 0) | (e ? kElbowDown : 0));
        if (t.normalGiven) {
          const Eigen::Vector3d n4 = frameOf(m, s.q.data(), 4).linear().transpose() * t.rotation.col(0);
          if (std::abs(n4.z()) > kInPlane) {
            fail(scratch, IkErrorKind::OrientationFixed, 0,
                 fmt::format("the tool cannot take that orientation: {}", familyOrientation(IkFamily::Articulated5)),
                 "");
            note(firstError, scratch.error);
            continue;
          }
          s.q[4] = deg(std::atan2(n4.y(), n4.x()));
        } else {
          s.q[4] = ref[4];
        }
        out.solutions[static_cast<std::size_t>(out.count++)] = s;
      }
      continue;
    }
    note(firstError, scratch.error);
  }
  finish(out, firstError);
}

void solveArticulated6(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want,
                       IkSolutions& out) {
  const PlanarRun& run = f.run;
  const Eigen::Vector3d c = wristCentre(m, t);
  double th1[2];
  if (!baseAngles(f, c, run.along, th1, out)) return;
  IkError firstError;
  for (int b = 0; b < 2; ++b) {
    if (!want.takes(kShoulderBack, b == 1)) continue;
    const Eigen::Vector3d T1 = dhTransform(m.joint(1).dh, deg(th1[b])).inverse() * c;
    std::array<Eigen::Vector2d, 2> phis;
    double miss = 0, sinElbow = 0;
    IkSolutions scratch;
    if (!solveTwoLink(T1.head<2>() - run.offset, run.link[0], run.link[1], phis, miss, sinElbow, want.elbow())) {
      outOfReach(f, miss, scratch);
    } else if (bentEnough(f, sinElbow, scratch)) {
      for (std::size_t e = 0; e < 2; ++e) {
        if (!want.takes(kElbowDown, e == 1)) continue;
        IkSolution arm;
        arm.q[0] = deg(th1[b]);
        const double phi[2] = {phis[e].x(), phis[e].y()};
        setRun(run, phi, arm);
        arm.config = static_cast<std::uint8_t>((b ? kShoulderBack : 0) | (e ? kElbowDown : 0));
        addWrist(m, t, arm, want, out, firstError);
      }
      continue;
    }
    note(firstError, scratch.error);
  }
  finish(out, firstError);
}

void solveSpherical6(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const Branches& want,
                     IkSolutions& out) {
  const Joint &j2 = m.joint(2), &j3 = m.joint(3), &j4 = m.joint(4);
  const Eigen::Vector3d c = wristCentre(m, t);
  double th1[2];
  if (!baseAngles(f, c, j2.dh.d, th1, out)) return;
  IkError firstError;
  for (int b = 0; b < 2; ++b) {
    if (!want.takes(kShoulderBack, b == 1)) continue;
    // In frame 1 the wrist centre is Rz(θ2) (a2, -sin α2 · L, d2), L = d3 + cos α3 · d4.
    const Eigen::Vector3d T1 = dhTransform(m.joint(1).dh, deg(th1[b])).inverse() * c;
    const double r = std::hypot(T1.x(), T1.y()), a2 = j2.dh.a;
    IkSolutions scratch;
    if (r < std::abs(a2)) {
      fail(scratch, IkErrorKind::Unreachable, std::abs(a2) - r,
           fmt::format("the wrist centre would be {:.4g} too near joint 2's axis", std::abs(a2) - r), "");
    } else {
      const double reach = std::sqrt(r * r - a2 * a2);
      if (reach < f.reach * std::sin(kSingularDegrees * kDegToRad)) {
        fail(scratch, IkErrorKind::Singular, reach,
             fmt::format("near-singular pose: the wrist centre would be {:.4g} from joint 2's axis", reach),
             "move the point away from the shoulder");
      } else {
        for (int e = 0; e < 2; ++e) {
          if (!want.takes(kElbowDown, e == 1)) continue;
          const double L = e == 0 ? reach : -reach;
          IkSolution arm;
          arm.q[0] = deg(th1[b]);
          arm.q[1] = deg(std::atan2(T1.y(), T1.x()) - std::atan2(-j2.sinAlpha * L, a2));
          arm.q[2] = L - j3.cosAlpha * j4.dh.d;
          arm.config = static_cast<std::uint8_t>((b ? kShoulderBack : 0) | (e ? kElbowDown : 0));
          addWrist(m, t, arm, want, out, firstError);
        }
        continue;
      }
    }
    note(firstError, scratch.error);
  }
  finish(out, firstError);
}

}  // namespace rs::kinematics::ik
