#include "runtime/run/followed_machine.h"

#include <vector>

namespace rs::runtime {

FollowedMachine::~FollowedMachine() { (void)settle(); }

vm::Status FollowedMachine::settle() {
  if (!underway_.valid()) return vm::Status::ok();
  return underway_.get();
}

template <typename Command>
vm::Status FollowedMachine::follow(vm::Status simulated, Command&& command) {
  if (!simulated && !simulated.notYet()) return simulated;
  if (vm::Status st = settle(); !st) return st;
  underway_ = std::async(std::launch::async, std::forward<Command>(command));
  // A motion the simulation finished at once (it took no time) is waited for now.
  if (!simulated.notYet()) return settle();
  return simulated;
}

vm::Status FollowedMachine::moveTo(std::span<const std::int32_t> targets) {
  return follow(lead_.moveTo(targets),
                [this, t = std::vector<std::int32_t>(targets.begin(), targets.end())] { return follower_.moveTo(t); });
}

vm::Status FollowedMachine::moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) {
  return follow(lead_.moveLockStep(targets, lead),
                [this, lead, t = std::vector<std::int32_t>(targets.begin(), targets.end())] {
                  return follower_.moveLockStep(t, lead);
                });
}

vm::Status FollowedMachine::hardHome() {
  return follow(lead_.hardHome(), [this] { return follower_.hardHome(); });
}

vm::Status FollowedMachine::resume() {
  const vm::Status simulated = lead_.resume();
  if (simulated.notYet()) return simulated;
  if (vm::Status st = settle(); !st) return st;
  return simulated;
}

// Nothing moves while an output changes or the arm goes back: the follower
// is told at once, after the simulation agreed. An output a wire carries
// to an input at once waits (NotYet) for the cell's rounds of the instant:
// the controller is told all the same, and the wait is the simulation's.
vm::Status FollowedMachine::setOutput(int output, bool on) {
  const vm::Status simulated = lead_.setOutput(output, on);
  if (!simulated && !simulated.notYet()) return simulated;
  if (vm::Status st = settle(); !st) return st;
  if (vm::Status st = follower_.setOutput(output, on); !st) return st;
  return simulated;
}

vm::Status FollowedMachine::reset() {
  if (vm::Status st = lead_.reset(); !st) return st;
  if (vm::Status st = settle(); !st) return st;
  return follower_.reset();
}

}  // namespace rs::runtime
