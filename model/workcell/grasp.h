// Objects in the gripper (DESIGN.md, "Objects"): a closed gripper whose
// tool centre point lies inside an object holds it; the object moves with
// the gripper until it opens; RESET puts every object back where the
// workcell placed it.
//
// When is a gripper closed? Its motor's RANGE runs from open (min) to
// closed (max). A move that turns the gripper motor towards max closes the
// gripper; one that turns it towards min opens it. So:
//  - at the end of a closing move, the gripper takes the part (ObjectKind
//    Part) whose box (the bounds of its lines) holds the tool centre point,
//    the smallest such box when boxes nest (a block on a table, not the
//    table); a fixture is never taken;
//  - at the start of an opening move, it lets go: the part settles
//    straight down onto what is under it (model/workcell/settle.h);
//  - in between, the object keeps its pose relative to the end-effector
//    frame: F_world_object = F_world_E(q) · F_E_object.
// A closing move with nothing at the tool centre point holds nothing, and a
// closed gripper moved into an object does not take it (it was not closing
// there). Decided here; documented in docs/models.md.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/model.h"
#include "model/workcell/settle.h"
#include "model/workcell/tool_tracker.h"

namespace rs::workcell {

/// What a step did to the gripper's hold.
struct GraspChange {
  std::size_t object = 0;  ///< index in Workcell::objects
  bool held = false;       ///< true: taken; false: let go
  Settled settled;         ///< a let-go: where it came to rest, on what, how far it dropped
};

class Grasping {
 public:
  /// Tracks robot `robot` of `cell` (both must outlive this). A robot
  /// without a gripper never holds anything.
  Grasping(const Workcell& cell, std::size_t robot);
  /// Tracks the robot the cell's run drives (Workcell::drivenRobot).
  explicit Grasping(const Workcell& cell) : Grasping(cell, cell.drivenRobotIndex()) {}

  /// One step of the program moved the robot's motors (arm joints, then
  /// the gripper, as a program sees them) from `before` to `after`. With
  /// `mayTake` false a closing move takes nothing: a still of a moment
  /// during a closing move, which has not ended yet.
  std::optional<GraspChange> step(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                  bool mayTake = true);
  /// RESET: nothing held, every object back at its placement.
  void reset();

  std::optional<std::size_t> held() const { return held_; }
  /// F_E_object of the held object (meaningful while something is held).
  const Eigen::Isometry3d& heldOffset() const { return offset_; }
  /// Object `o`'s placement (F_world_design of its drawing) with the
  /// robot's motors at `encoders`: where it rests, or where the gripper
  /// carries it.
  Eigen::Isometry3d objectPose(std::size_t o, std::span<const std::int32_t> encoders);
  /// The same for an object that is not held (where it rests now).
  const Eigen::Isometry3d& restingPose(std::size_t o) const { return resting_[o]; }
  /// Object `o` (not held) rests at `pose` from now on: a belt moved it, a
  /// feeder put it, a sink took it (runtime/cell/devices.h).
  void setResting(std::size_t o, const Eigen::Isometry3d& pose) {
    resting_[o] = pose;
    letGo_[o].reset();
  }
  /// The end-effector frame in the world for the robot's motors (identity
  /// for a robot without a gripper).
  Eigen::Isometry3d toolFrame(std::span<const std::int32_t> encoders);
  /// The object whose box holds `point`: the smallest such box (objects
  /// where they rest), of any kind.
  std::optional<std::size_t> objectAt(const Eigen::Vector3d& point) const { return smallestAt(point, false); }
  /// The part a closing gripper would take with its tool centre point at
  /// `point`: the smallest part's box that holds it. Fixtures are never taken.
  std::optional<std::size_t> partAt(const Eigen::Vector3d& point) const { return smallestAt(point, true); }
  /// Where the held part would settle if it were let go with the robot's
  /// motors at `encoders` (meaningful while one is held).
  Settled settleHeld(std::span<const std::int32_t> encoders);
  /// Whether a move from `before` to `after` turns the gripper towards open.
  bool opens(std::span<const std::int32_t> before, std::span<const std::int32_t> after) const {
    return tool_ && gripperMotor_ < before.size() && gripperMotor_ < after.size() &&
           after[gripperMotor_] < before[gripperMotor_];
  }
  /// Whether it turns the gripper towards closed.
  bool closes(std::span<const std::int32_t> before, std::span<const std::int32_t> after) const {
    return tool_ && gripperMotor_ < before.size() && gripperMotor_ < after.size() &&
           after[gripperMotor_] > before[gripperMotor_];
  }
  /// The nearest object's box to `point` and the distance to it (0 inside),
  /// for messages about a grasp that took nothing.
  std::optional<std::pair<std::size_t, double>> nearestObject(const Eigen::Vector3d& point) const;
  /// The centre of object `o`'s box in the world, where it rests now.
  Eigen::Vector3d boxCentre(std::size_t o) const { return resting_[o] * boxes_[o].center(); }
  bool hasGripper() const { return tool_.has_value(); }

  /// How an object was let go where it rests: the end-effector frame then
  /// and its F_E_object. A take with the end-effector at that very frame
  /// holds it by that offset again, the exact value of
  /// frame⁻¹·(frame·offset), which rounding would otherwise drift by an ulp
  /// or two a take: a loop that puts a block down and takes it again then
  /// leaves the world bit for bit as it was, so the swept check's memory of
  /// moves (runtime/sim/sweep_memo.h) answers its moves again.
  struct LetGo {
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    bool operator==(const LetGo& o) const {
      return frame.matrix() == o.frame.matrix() && offset.matrix() == o.offset.matrix();
    }
  };
  /// What a grasp changes, for snapshots of a run.
  struct State {
    std::optional<std::size_t> held;
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    std::vector<Eigen::Isometry3d> resting;
    std::vector<std::optional<LetGo>> letGo;  ///< per object: how it was let go where it rests (none: placed there)
    bool operator==(const State& o) const {  // exact: a restored run must be bit for bit the same
      if (held != o.held || offset.matrix() != o.offset.matrix() || resting.size() != o.resting.size() ||
          letGo != o.letGo)
        return false;
      for (std::size_t i = 0; i < resting.size(); ++i)
        if (resting[i].matrix() != o.resting[i].matrix()) return false;
      return true;
    }
  };
  State state() const { return {held_, offset_, resting_, letGo_}; }
  void restore(const State& s) { held_ = s.held, offset_ = s.offset, resting_ = s.resting, letGo_ = s.letGo; }

 private:
  std::optional<std::size_t> smallestAt(const Eigen::Vector3d& point, bool partsOnly) const;

  const Workcell* cell_;
  std::optional<ToolTracker> tool_;  // empty: the robot has no gripper
  std::size_t gripperMotor_ = 0;
  std::vector<Eigen::Isometry3d> resting_;
  std::vector<std::optional<LetGo>> letGo_;  // per object, as State::letGo
  std::vector<Eigen::AlignedBox3d> boxes_;  // in each object's design coordinates
  std::optional<std::size_t> held_;
  Eigen::Isometry3d offset_ = Eigen::Isometry3d::Identity();
};

}  // namespace rs::workcell
