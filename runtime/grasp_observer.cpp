#include "runtime/grasp_observer.h"

namespace rs::runtime {

void GraspObserver::afterStep(const vm::Interpreter& vm, std::uint32_t index) {
  const auto after = vm.machine().positions();
  change_.reset();
  if (vm.image().code[index].op == vm::Op::Reset) {
    if (const auto held = grasping_.held()) change_ = workcell::GraspChange{*held, false};
    grasping_.reset();
  } else {
    change_ = grasping_.step(before_, after, !takeUntil_ || vm.machine().now() <= *takeUntil_);
  }
  before_.assign(after.begin(), after.end());
  if (next_) next_->afterStep(vm, index);
}

ObjectsInGripper::ObjectsInGripper(const workcell::Workcell* cell, std::span<const std::int32_t> start) {
  if (!cell) return;
  grasping_.emplace(*cell);
  observer_.emplace(*grasping_, start);
}

vm::StepObserver* ObjectsInGripper::chain(vm::StepObserver* next) {
  if (!observer_) return next;
  observer_->setNext(next);
  return &*observer_;
}

}  // namespace rs::runtime
