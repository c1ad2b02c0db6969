// Drives workcell::Grasping from a running program: after every step it
// compares the robot's motors with where they were before the step (RESET
// puts the objects back), then hands the step on to the next observer (a
// trace, a recorder), which can ask what the step did to the hold.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/grasp.h"
#include "vm/interpreter.h"

namespace rs::runtime {

class GraspObserver final : public vm::StepObserver {
 public:
  /// `grasping` must outlive the observer; the motors start at `start`.
  GraspObserver(workcell::Grasping& grasping, std::span<const std::int32_t> start, vm::StepObserver* next = nullptr)
      : grasping_(grasping), before_(start.begin(), start.end()), next_(next) {}

  void afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  /// The observer called after this one (it may ask lastChange()).
  void setNext(vm::StepObserver* next) { next_ = next; }
  /// A step that ends after `t` takes nothing (a still at `t` shows a
  /// closing move that has not ended; letting go happens at a move's start).
  void takeNothingEndingAfter(vm::Micros t) { takeUntil_ = t; }

  /// What the latest step did to the hold, if anything.
  const std::optional<workcell::GraspChange>& lastChange() const { return change_; }
  workcell::Grasping& grasping() const { return grasping_; }

 private:
  workcell::Grasping& grasping_;
  std::vector<std::int32_t> before_;
  vm::StepObserver* next_;
  std::optional<workcell::GraspChange> change_;
  std::optional<vm::Micros> takeUntil_;
};

/// The objects a workcell's first robot carries in its gripper during a run:
/// owns the workcell::Grasping and the GraspObserver that drives it, the
/// setup every runner of a program on a workcell needs. Without a cell it
/// holds nothing: chain() hands back `next` and the accessors answer null.
/// A robot without a gripper holds nothing either (Grasping never takes).
///
///   ObjectsInGripper objects(cell, machine.positions());
///   RunRecorder recorder(machine, objects.observer());
///   interpreter.run(limits, objects.chain(&recorder));
class ObjectsInGripper {
 public:
  /// `cell` (may be null) must outlive this; the motors start at `start`.
  ObjectsInGripper(const workcell::Workcell* cell, std::span<const std::int32_t> start);
  ObjectsInGripper(const ObjectsInGripper&) = delete;  // the observer refers to the Grasping
  ObjectsInGripper& operator=(const ObjectsInGripper&) = delete;

  /// The observer to run with: the grasp observer, which then calls `next`
  /// (may be null) after every step; `next` itself when there is no cell.
  vm::StepObserver* chain(vm::StepObserver* next);
  /// The hold and the objects' poses; null without a cell.
  workcell::Grasping* grasping() { return grasping_ ? &*grasping_ : nullptr; }
  /// What each step did to the hold (for a trace or a recorder); null without a cell.
  GraspObserver* observer() { return observer_ ? &*observer_ : nullptr; }

 private:
  std::optional<workcell::Grasping> grasping_;
  std::optional<GraspObserver> observer_;
};

}  // namespace rs::runtime
