#include "compiler/program/kinematics_diagnostic.h"

#include <fmt/format.h>

namespace rs::compiler {

namespace {

// The first place that has a line, `whole` when none has.
template <class Key>
diag::Pos placeOf(const std::function<diag::Pos(Key)>& place, Key key, diag::Pos fallback) {
  if (!place) return fallback;
  const diag::Pos pos = place(key);
  return pos.line ? pos : fallback;
}

bool isJointError(kinematics::ErrorKind kind) {
  return kind == kinematics::ErrorKind::BadCoupling || kind == kinematics::ErrorKind::BadPrecision;
}

}  // namespace

diag::Diagnostic kinematicsDiagnostic(const KinematicsProblem& problem, const KinematicsPlaces& places) {
  diag::Diagnostic d{places.file, places.whole, diag::Severity::Error, {}};
  if (const auto* e = std::get_if<kinematics::KinematicsError>(&problem)) {
    // A gripper names its vectors; a chain its joints (for their drives) and frames.
    diag::Pos pos = placeOf(places.frame, e->index, places.whole);
    if (places.gripperPart) pos = placeOf(places.gripperPart, e->index, places.whole);
    else if (isJointError(e->kind)) pos = placeOf(places.joint, e->index, pos);
    d.pos = pos;
    d.message = fmt::format("{}: {}", places.subject, e->message);
    return d;
  }
  const auto& pose = std::get<workcell::PoseProblem>(problem);
  d.pos = placeOf(places.poseField, pose.field, places.whole);
  d.message = fmt::format("{}: {}", places.subject, pose.message);
  d.hint = pose.hint;
  d.code = pose.code;
  return d;
}

}  // namespace rs::compiler
