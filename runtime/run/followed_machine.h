// A simulated robot of a cell run that a real controller follows (run
// --cell CELL --device LABEL=DEV): the simulation stays the machine the
// program and the cell see (its clock, its positions, its inputs), and
// every move, HRDHOME, RESET and output is also given to the follower. A
// move is sent when it begins and runs on the controller while the cell's
// clock goes on with the other robots; the robot's wait ends (resume) only
// once the controller has reported the move done, so the cell's clock does
// not pass the move's end before the real arm got there. docs/serial.md,
// "Several robots on their controllers".
#pragma once

#include <future>
#include <span>
#include <string>

#include "vm/machine.h"

namespace rs::runtime {

class FollowedMachine final : public vm::Machine {
 public:
  /// Both must outlive this; `follower` is used only from this object
  /// (a move under way runs on a thread of its own).
  FollowedMachine(vm::Machine& lead, vm::Machine& follower) : lead_(lead), follower_(follower) {}
  ~FollowedMachine() override;
  FollowedMachine(const FollowedMachine&) = delete;
  FollowedMachine& operator=(const FollowedMachine&) = delete;

  vm::Status moveTo(std::span<const std::int32_t> targets) override;
  vm::Status moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) override;
  void beginPath() override { lead_.beginPath(); }
  std::span<const std::int32_t> positions() const override { return lead_.positions(); }
  vm::Status setOutput(int output, bool on) override;
  bool input(int input) override { return lead_.input(input); }
  vm::Status waitFor(int input, bool on) override { return lead_.waitFor(input, on); }
  vm::Status delay(vm::Micros duration) override { return lead_.delay(duration); }
  vm::Status hardHome() override;
  vm::Status reset() override;
  void window(std::int32_t x, std::int32_t y, std::int32_t z) override { lead_.window(x, y, z); }
  void view(std::int32_t x, std::int32_t y, std::int32_t z) override { lead_.view(x, y, z); }
  /// The simulation's wait ended: the controller's move is waited for too.
  vm::Status resume() override;
  vm::Micros now() const override { return lead_.now(); }
  std::uint64_t knots() const override { return lead_.knots(); }
  std::string stillReason() const override { return lead_.stillReason(); }
  vm::IoMask outputs() const override { return lead_.outputs(); }
  vm::IoMask inputs() const override { return lead_.inputs(); }

 private:
  /// The simulation's call `simulated` began a motion: `command` gives it
  /// to the follower, on a thread, unless the simulation refused it.
  template <typename Command>
  vm::Status follow(vm::Status simulated, Command&& command);
  /// The follower's motion under way is done (its failure, if it failed).
  vm::Status settle();

  vm::Machine& lead_;
  vm::Machine& follower_;
  std::future<vm::Status> underway_;
};

}  // namespace rs::runtime
