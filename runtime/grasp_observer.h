// Drives workcell::Grasping from a running program: after every step it
// compares the robot's motors with where they were before the step (RESET
// puts the objects back), then hands the step on to the next observer (a
// trace, a recorder), which can ask what the step did to the hold.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "runtime/workcell/grasp.h"
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

}  // namespace rs::runtime
