// compiler::kinematicsDiagnostic, the one place a kinematics problem becomes
// a Diagnostic: every kind of problem lands at the place the reader gave
// for what it is about, with the subject before its words; a place that
// has no line falls back as the header says. The positions are made up
// (each thing at its own line), so a wrong choice shows as a wrong line.
#include <catch2/catch.hpp>
#include <string>

#include "compiler/program/kinematics_diagnostic.h"
#include "model/kinematics/gripper.h"

namespace {

using rs::compiler::KinematicsPlaces;
using rs::compiler::kinematicsDiagnostic;
using rs::diag::Pos;
using rs::kinematics::ErrorKind;
using rs::kinematics::KinematicsError;
using rs::workcell::PoseField;
using rs::workcell::PoseProblem;

// A chain's places: the robot at line 1, joint N at line 10 + N (joints 1..3
// only), frame N at line 20 + N (frames 0..3 only; -1, the whole chain, at 30).
KinematicsPlaces chainPlaces() {
  KinematicsPlaces places{"arm.rsd", "robot 'arm'", {1, 7}};
  places.joint = [](int j) { return j >= 1 && j <= 3 ? Pos{static_cast<std::uint32_t>(10 + j), 3} : Pos{}; };
  places.frame = [](int f) { return f >= 0 && f <= 3 ? Pos{static_cast<std::uint32_t>(20 + f), 5} : Pos{30, 1}; };
  return places;
}

}  // namespace

TEST_CASE("kinematics diagnostic: a chain's joint errors point at the joint, the others at the frame",
          "[compiler][kinematics]") {
  const KinematicsPlaces places = chainPlaces();
  for (const ErrorKind kind : {ErrorKind::BadPrecision, ErrorKind::BadCoupling}) {
    const auto d = kinematicsDiagnostic(KinematicsError{kind, 2, "joint 2 has a bad drive"}, places);
    CHECK(d.file == "arm.rsd");
    CHECK(d.pos == Pos{12, 3});
    CHECK(d.severity == rs::diag::Severity::Error);
    CHECK(d.message == "robot 'arm': joint 2 has a bad drive");
    CHECK(d.hint.empty());
    CHECK(d.code.empty());
  }
  // A joint the reader has no line for: the frame of the same index.
  CHECK(kinematicsDiagnostic(KinematicsError{ErrorKind::BadPrecision, 3, "m"}, places).pos == Pos{13, 3});
  CHECK(kinematicsDiagnostic(KinematicsError{ErrorKind::BadPrecision, 0, "m"}, places).pos == Pos{20, 5});
  for (const ErrorKind kind :
       {ErrorKind::NotFinite, ErrorKind::DegenerateAxis, ErrorKind::AxesNotPerpendicular,
        ErrorKind::XNotPerpendicularToPreviousZ, ErrorKind::XMissesPreviousZ, ErrorKind::TcpMismatch}) {
    const auto d = kinematicsDiagnostic(KinematicsError{kind, 1, "frame 1 is bent"}, places);
    CHECK(d.pos == Pos{21, 5});
    CHECK(d.message == "robot 'arm': frame 1 is bent");
  }
  CHECK(kinematicsDiagnostic(KinematicsError{ErrorKind::CountMismatch, -1, "m"}, places).pos == Pos{30, 1});
}

TEST_CASE("kinematics diagnostic: without a place for the frame or joint, the whole construct",
          "[compiler][kinematics]") {
  const KinematicsPlaces link{"cell.rsd", "link 'base'", {4, 9}};
  for (const ErrorKind kind : {ErrorKind::AxesNotPerpendicular, ErrorKind::BadPrecision, ErrorKind::CountMismatch}) {
    const auto d = kinematicsDiagnostic(KinematicsError{kind, 2, "its axes are not at right angles"}, link);
    CHECK(d.pos == Pos{4, 9});
    CHECK(d.message == "link 'base': its axes are not at right angles");
  }
  KinematicsPlaces noLine = chainPlaces();
  noLine.frame = [](int) { return Pos{}; };
  CHECK(kinematicsDiagnostic(KinematicsError{ErrorKind::DegenerateAxis, 1, "m"}, noLine).pos == Pos{1, 7});
}

TEST_CASE("kinematics diagnostic: a gripper's errors point at the vector they are about", "[compiler][kinematics]") {
  KinematicsPlaces places{"g.rsd", "gripper 'claw'", {2, 1}};
  places.frame = [](int) { return Pos{99, 1}; };  // a gripper's index is a vector, never a frame
  places.gripperPart = [](int part) {
    switch (part) {
      case rs::kinematics::kGripperNormal: return Pos{5, 2};
      case rs::kinematics::kGripperApproach: return Pos{6, 2};
      case rs::kinematics::kGripperAxis2: return Pos{7, 2};
      case rs::kinematics::kGripperAxis3: return Pos{8, 2};
      default: return Pos{};
    }
  };
  const std::pair<int, Pos> expected[] = {{rs::kinematics::kGripperNormal, {5, 2}},
                                          {rs::kinematics::kGripperApproach, {6, 2}},
                                          {rs::kinematics::kGripperAxis2, {7, 2}},
                                          {rs::kinematics::kGripperAxis3, {8, 2}},
                                          {rs::kinematics::kGripperWhole, {2, 1}}};
  for (const auto& [part, pos] : expected) {
    const auto d = kinematicsDiagnostic(KinematicsError{ErrorKind::DegenerateAxis, part, "the axis has no length"},
                                        places);
    CHECK(d.pos == pos);
    CHECK(d.message == "gripper 'claw': the axis has no length");
  }
  // A precision error is about the whole gripper, not a joint.
  CHECK(kinematicsDiagnostic(KinematicsError{ErrorKind::BadPrecision, rs::kinematics::kGripperWhole, "m"}, places)
            .pos == Pos{2, 1});
}

TEST_CASE("kinematics diagnostic: a pose problem points at the part of the pose, with its hint and code",
          "[compiler][kinematics]") {
  KinematicsPlaces places{"p.rsp", "point P1", {40, 5}};
  places.poseField = [](PoseField f) {
    switch (f) {
      case PoseField::Approach: return Pos{40, 20};
      case PoseField::Normal: return Pos{40, 30};
      case PoseField::Grip: return Pos{};  // GRIP not written: the AT
      case PoseField::Position: break;
    }
    return Pos{40, 5};
  };
  const std::pair<PoseField, Pos> expected[] = {{PoseField::Position, {40, 5}},
                                                {PoseField::Approach, {40, 20}},
                                                {PoseField::Normal, {40, 30}},
                                                {PoseField::Grip, {40, 5}}};
  for (const auto& [field, pos] : expected) {
    const auto d = kinematicsDiagnostic(
        PoseProblem{field, "the pose is out of reach", "move it closer", "pose-unreachable"}, places);
    CHECK(d.file == "p.rsp");
    CHECK(d.pos == pos);
    CHECK(d.message == "point P1: the pose is out of reach");
    CHECK(d.hint == "move it closer");
    CHECK(d.code == "pose-unreachable");
  }
  // A caller with no places at all (robotsim ik): the command as a whole.
  const auto ik = kinematicsDiagnostic(PoseProblem{PoseField::Normal, "singular", "", "pose-singular"},
                                       {"robotsim", "scara", {}});
  CHECK(rs::diag::render(ik, nullptr) == "robotsim: error: scara: singular\n");
}
