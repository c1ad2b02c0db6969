// PoseSolver::solveAnyOrientation: a position with no orientation written
// keeps the previous point's orientation (pose_solver.cpp); when that one
// does not reach, the orientations the arm leaves free are tried, nearest
// the kept one first, and the first that reaches within the motors' ranges
// wins. What is free is the family's (docs/models.md, "Inverse
// kinematics"):
//
//   scara with a roll joint   the heading about the joints' axes
//   articulated-5             the pitch in the arm's plane (the roll does not move the tool centre point)
//   articulated-6, spherical-6  any turn of the tool
//   cartesian, numeric        nothing (the numeric method already ignores an orientation not written)
//
// The search is a fixed grid, so its answer is deterministic: one free
// angle in steps of kStepDegrees out to half a turn each way; any turn as
// kSphereAxes axes (a Fibonacci sphere) times angles in steps of
// kTurnDegrees. An orientation between the grid's steps can still be given
// with --approach/--normal, which the refusal's hint says.
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/workcell/pose_solver.h"

namespace rs::workcell {

namespace {

constexpr int kStepDegrees = 5;   // one free angle
constexpr int kTurnDegrees = 10;  // any turn
constexpr int kSphereAxes = 48;

// The turns to try, in order: nearest the kept orientation first.
std::vector<Eigen::Matrix3d> freeTurns(const kinematics::InverseKinematics& ik, std::span<const double> refQ) {
  using kinematics::IkFamily;
  std::vector<Eigen::Matrix3d> turns;
  const auto aboutOne = [&](const Eigen::Vector3d& axis) {
    for (int angle = kStepDegrees; angle <= 180; angle += kStepDegrees)
      for (const int sign : {1, -1}) {
        if (angle == 180 && sign < 0) continue;
        turns.emplace_back(Eigen::AngleAxisd(sign * angle * kinematics::kDegToRad, axis).toRotationMatrix());
      }
  };
  switch (ik.family()) {
    case IkFamily::Scara:
      if (ik.shape().run.revolutes == 3) aboutOne(Eigen::Vector3d::UnitZ());
      break;
    case IkFamily::Articulated5:
      // The approach is kept at the previous point's pitch in frame 1: turning it about that frame's z_1 (the
      // pitch joints' axis) is a new pitch.
      aboutOne(kinematics::dhTransform(ik.model().joint(1).dh, refQ[0]).linear().col(2));
      break;
    case IkFamily::Articulated6:
    case IkFamily::Spherical6: {
      std::vector<Eigen::Vector3d> axes;
      const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
      for (int i = 0; i < kSphereAxes; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / kSphereAxes, r = std::sqrt(1.0 - z * z);
        axes.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
      }
      for (int angle = kTurnDegrees; angle <= 180; angle += kTurnDegrees)
        for (const Eigen::Vector3d& axis : axes)
          turns.emplace_back(Eigen::AngleAxisd(angle * kinematics::kDegToRad, axis).toRotationMatrix());
      break;
    }
    case IkFamily::Cartesian:
    case IkFamily::Numeric: break;
  }
  return turns;
}

bool positionProblem(const PoseResult& r) {
  return r.problem && r.problem->field == PoseField::Position &&
         (r.problem->code == "pose-unreachable" || r.problem->code == "pose-singular" ||
          r.problem->code == "pose-out-of-range");
}

}  // namespace

PoseResult PoseSolver::solveAnyOrientation(const PoseRequest& request, std::span<const std::int32_t> reference) const {
  const Kept from = kept(reference, {});
  kinematics::ToolTarget target;
  PoseResult first;
  if (std::optional<PoseProblem> problem = targetOf(request, from, target)) {
    first.problem = std::move(problem);
    return first;
  }
  first = solveTarget(request, target, from, reference);
  if (first.ok() || request.configuration || !positionProblem(first)) return first;
  const bool sixAxes =
      ik_.family() == kinematics::IkFamily::Articulated6 || ik_.family() == kinematics::IkFamily::Spherical6;
  if (request.approach || request.normal) {
    // One axis written: a six-axis arm kept the other from the previous point, and giving it may help.
    if (sixAxes && !(request.approach && request.normal))
      first.problem->hint += fmt::format("; the {} was kept from the previous point: give {} too",
                                         request.approach ? "normal" : "approach",
                                         request.optionWords ? (request.approach ? "--normal" : "--approach")
                                                             : (request.approach ? "NORMAL" : "APPROACH"));
    return first;
  }
  const std::vector<Eigen::Matrix3d> turns = freeTurns(ik_, from.refQ);
  if (turns.empty()) return first;  // nothing is free: the first answer stands
  bool reachedSome = first.problem->code != "pose-unreachable";
  for (std::size_t i = 0; i < turns.size(); ++i) {
    kinematics::ToolTarget turned = target;
    turned.rotation = turns[i] * target.rotation;
    PoseResult r = solveTarget(request, turned, from, reference);
    if (r.ok()) {
      r.orientationsTried = static_cast<int>(i + 1);
      r.turned = Eigen::AngleAxisd(turns[i]).angle() * kinematics::kRadToDeg;
      return r;
    }
    if (r.problem->code != "pose-unreachable") reachedSome = true;
  }
  PoseResult refused = first;
  refused.orientationsTried = static_cast<int>(turns.size());
  const std::string tried = fmt::format("{} other orientation{} the arm leaves free {} tried", turns.size(),
                                        turns.size() == 1 ? "" : "s", turns.size() == 1 ? "was" : "were");
  if (!reachedSome)
    refused.problem->hint = fmt::format("{}, and none reaches the point: move it nearer the robot", tried);
  else
    refused.problem->hint = fmt::format(
        "{} (in steps of {} degrees), and none reaches it with every motor in range: {} try one between those "
        "steps, or move the point",
        tried, sixAxes ? kTurnDegrees : kStepDegrees,
        request.optionWords ? "--approach and --normal" : "APPROACH and NORMAL");
  return refused;
}

}  // namespace rs::workcell
