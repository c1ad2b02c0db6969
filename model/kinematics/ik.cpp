#include "model/kinematics/ik.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/kinematics/ik_solvers.h"
#include "model/kinematics/trig.h"

namespace rs::kinematics {

namespace ik {

Eigen::Isometry3d frameOf(const ChainModel& m, const double* q, int j) {
  // F_0_j = A_1···A_j with A_i's structure used (as forward_kinematics.cpp
  // does): with X, Y, Z, o the columns so far and v = cosθ Y − sinθ X,
  // x' = cosθ X + sinθ Y, y' = cosα v + sinα Z, z' = cosα Z − sinα v,
  // o' = o + a x' + d Z.
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d o = Eigen::Vector3d::Zero();
  for (int i = 1; i <= j; ++i) {
    const Joint& joint = m.joint(i);
    double ct = joint.cosTheta, st = joint.sinTheta, d = q[i - 1];
    if (joint.type() == JointType::Revolute) {
      sinCosDegrees(q[i - 1], st, ct);
      d = joint.dh.d;
    }
    const Eigen::Vector3d X = R.col(0), Y = R.col(1), Z = R.col(2);
    const Eigen::Vector3d v = ct * Y - st * X;
    R.col(0) = ct * X + st * Y;
    R.col(1) = joint.cosAlpha * v + joint.sinAlpha * Z;
    R.col(2) = joint.cosAlpha * Z - joint.sinAlpha * v;
    o += joint.dh.a * R.col(0) + d * Z;
  }
  Eigen::Isometry3d F = Eigen::Isometry3d::Identity();
  F.linear() = R;
  F.translation() = o;
  return F;
}

void fail(IkSolutions& out, IkErrorKind kind, double distance, std::string message, std::string hint) {
  out.count = 0;
  out.error = IkError{kind, std::move(message), std::move(hint), distance};
}

bool baseAngles(const FamilyShape& f, const Eigen::Vector3d& T, double lateral, double angles[2], IkSolutions& out) {
  // z_1 · T = lateral with z_1 = k (-sin θ1, cos θ1, 0):  ρ sin(φ - θ1) = lateral / k.
  const double rho = std::hypot(T.x(), T.y());
  const double offset = lateral / f.lateralSign;
  const double clearance = std::sqrt(std::max(0.0, rho * rho - offset * offset));
  if (rho < std::abs(offset) - 1e-9 * f.reach) {
    fail(out, IkErrorKind::Unreachable, std::abs(offset) - rho,
         fmt::format("the point is {:.4g} from joint 1's axis, inside the {:.4g} the arm's side offset keeps clear",
                     rho, std::abs(offset)),
         "move the point further from the robot's base axis");
    return false;
  }
  if (clearance < kSingularAxisFraction * f.reach) {
    fail(out, IkErrorKind::Singular, clearance,
         fmt::format("near-singular pose: the point is {:.4g} from joint 1's axis (the line it turns about), where "
                     "joint 1's angle is not defined",
                     std::abs(rho - std::abs(offset))),
         fmt::format("keep the point at least {:.4g} away from that axis",
                     kSingularAxisFraction * f.reach + std::abs(offset)));
    return false;
  }
  const double phi = std::atan2(T.y(), T.x());
  const double s = std::asin(std::clamp(offset / rho, -1.0, 1.0));
  angles[0] = phi - s;
  angles[1] = phi - (std::numbers::pi - s);
  return true;
}

}  // namespace ik

namespace {

// Does q put the tool where the target says (the position, and each axis
// the user wrote)? Tolerances scale with the arm's size.
bool meets(const ChainModel& m, const FamilyShape& f, const ToolTarget& t, const IkSolution& s) {
  const Eigen::Isometry3d F = ik::frameOf(m, s.q.data(), m.size());
  if ((F.translation() - t.position).norm() > 1e-7 * f.reach) return false;
  constexpr double kAxis = 1e-7;
  if (t.approachGiven && (F.linear().col(2) - t.rotation.col(2)).norm() > kAxis) return false;
  if (t.normalGiven && (F.linear().col(0) - t.rotation.col(0)).norm() > kAxis) return false;
  return true;
}

// The orientation the arm reaches nearest the one asked for: what the
// message quotes.
std::string nearestOrientation(const ChainModel& m, const IkSolution& s, const ToolTarget& t) {
  const Eigen::Matrix3d R = ik::frameOf(m, s.q.data(), m.size()).linear();
  std::string what;
  if (t.approachGiven) what += fmt::format("approach ({:.4g}, {:.4g}, {:.4g})", R(0, 2), R(1, 2), R(2, 2));
  if (t.normalGiven)
    what += fmt::format("{}normal ({:.4g}, {:.4g}, {:.4g})", what.empty() ? "" : ", ", R(0, 0), R(1, 0), R(2, 0));
  return what;
}

// The target of frame n for a chain with a tool frame: F_0_n = F_0_tool ·
// F_n_tool⁻¹. A tool frame that only moves along the approach keeps what
// the user wrote; any other needs the target's whole rotation (the caller
// filled in the rest from the previous point), so then both axes count.
ToolTarget frameNTarget(const ChainModel& m, const ToolTarget& t) {
  const Eigen::Isometry3d& tool = m.F_n_tool();
  ToolTarget out = t;
  out.rotation = t.rotation * tool.linear().transpose();
  out.position = t.position - out.rotation * tool.translation();
  const bool alongApproach = tool.linear().isIdentity(0.0) && tool.translation().head<2>().isZero(0.0);
  if (!alongApproach) out.approachGiven = out.normalGiven = true;
  return out;
}

}  // namespace

InverseKinematics::InverseKinematics(const ChainModel& model) : model_(model), family_(detectFamily(model)) {}

IkSolutions InverseKinematics::solve(const ToolTarget& target, std::span<const double> reference) const {
  return solveBranches(target, reference, ik::Branches{});
}

std::span<const std::uint8_t> InverseKinematics::configurations() const {
  // In the order the forms list them: shoulder outermost, then elbow, then wrist.
  static constexpr std::uint8_t kOne[] = {0};
  static constexpr std::uint8_t kElbow[] = {0, kElbowDown};
  static constexpr std::uint8_t kArm[] = {0, kElbowDown, kShoulderBack, kShoulderBack | kElbowDown};
  static constexpr std::uint8_t kSix[] = {0,
                                          kWristFlip,
                                          kElbowDown,
                                          kElbowDown | kWristFlip,
                                          kShoulderBack,
                                          kShoulderBack | kWristFlip,
                                          kShoulderBack | kElbowDown,
                                          kShoulderBack | kElbowDown | kWristFlip};
  switch (family_.kind) {
    case IkFamily::Cartesian:
    case IkFamily::Numeric: return kOne;
    case IkFamily::Scara: return kElbow;
    case IkFamily::Articulated5: return kArm;
    case IkFamily::Articulated6:
    case IkFamily::Spherical6: return kSix;
  }
  return kOne;
}

IkSolutions InverseKinematics::solveConfig(const ToolTarget& target, std::span<const double> reference,
                                           std::uint8_t config) const {
  const std::span<const std::uint8_t> all = configurations();
  if (std::find(all.begin(), all.end(), config) == all.end()) {
    IkSolutions out;
    ik::fail(out, IkErrorKind::NoSuchConfiguration, 0,
             fmt::format("the {} family has no configuration {} (it has {})", familyName(family_.kind), config,
                         all.size()),
             "");
    return out;
  }
  return solveBranches(target, reference, ik::Branches{false, config});
}

IkSolutions InverseKinematics::solveBranches(const ToolTarget& toolTarget, std::span<const double> reference,
                                             const ik::Branches& want) const {
  const ToolTarget target = model_.hasTool() ? frameNTarget(model_, toolTarget) : toolTarget;
  IkSolutions out;
  const int n = model_.size();
  if (n == 0 || n > kMaxIkJoints || reference.size() != static_cast<std::size_t>(n)) {
    ik::fail(out, IkErrorKind::NoChain, 0,
             n > kMaxIkJoints ? fmt::format("inverse kinematics handles at most {} joints; this chain has {}",
                                            kMaxIkJoints, n)
                              : std::string("inverse kinematics needs a chain with joints"),
             "");
    return out;
  }
  switch (family_.kind) {
    case IkFamily::Cartesian: ik::solveCartesian(model_, family_, target, out); break;
    case IkFamily::Scara: ik::solveScara(model_, family_, target, want, out); break;
    case IkFamily::Articulated5: ik::solveArticulated5(model_, family_, target, reference, want, out); break;
    case IkFamily::Articulated6: ik::solveArticulated6(model_, family_, target, want, out); break;
    case IkFamily::Spherical6: ik::solveSpherical6(model_, family_, target, want, out); break;
    case IkFamily::Numeric: ik::solveNumeric(model_, family_, target, reference, out); return out;
  }
  // The 6-axis forms meet any orientation, and the five-axis form checks
  // its own; for the others keep the solutions that meet what was written.
  if (out.count == 0 || family_.kind == IkFamily::Articulated6 || family_.kind == IkFamily::Spherical6 ||
      family_.kind == IkFamily::Articulated5)
    return out;
  const IkSolution first = out.solutions[0];
  int kept = 0;
  for (int i = 0; i < out.count; ++i)
    if (meets(model_, family_, target, out.solutions[static_cast<std::size_t>(i)]))
      out.solutions[static_cast<std::size_t>(kept++)] = out.solutions[static_cast<std::size_t>(i)];
  out.count = kept;
  if (kept == 0)
    ik::fail(out, IkErrorKind::OrientationFixed, 0,
             fmt::format("the tool cannot take that orientation: {}", familyOrientation(family_.kind)),
             fmt::format("the nearest it reaches here: {}", nearestOrientation(model_, first, target)));
  return out;
}

}  // namespace rs::kinematics
