// A machine in a workcell: passes every call on to the machine that moves
// the motors (the simulation, or a real Rhino) and lets the world react to
// what it did — the gripper closing or opening, RESET. The run puts it in
// front of its machine when the program runs on a workcell.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "model/workcell/line_path.h"
#include "model/workcell/line_plan_cache.h"

#include "runtime/sim/collision_watch.h"
#include "runtime/sim/sim_machine.h"
#include "runtime/cell/world.h"
#include "vm/machine.h"

namespace rs::runtime {

class CellMachine final : public vm::Machine {
 public:
  /// Both must outlive this. `robot` is the robot of the world's cell
  /// that `motion` moves (its hand in the world).
  CellMachine(vm::Machine& motion, World& world, std::size_t robot = 0)
      : motion_(motion), world_(world), robot_(robot), before_(motion.positions().size(), 0) {}

  /// Checks every move on the simulated machine `timeline` (the machine
  /// this one stands in front of) for collisions; with CollisionMode::Error
  /// a move that collides fails with the collision's message. Both must
  /// outlive this.
  void watchCollisions(const SimMachine& timeline, CollisionWatch& watch, CollisionMode mode) {
    timeline_ = &timeline, watch_ = &watch, mode_ = mode;
  }

  vm::Status moveTo(std::span<const std::int32_t> targets) override;
  vm::Status moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) override;
  /// The line planned (model/workcell/line_path.h) and run knot by knot,
  /// each knot a lock-step move swept and reacted to like any move. Fault:
  /// a robot without a chain, or the planner's problem in its words.
  vm::Status moveLine(std::span<const std::int32_t> targets) override;
  vm::Status moveAlongTool(std::int32_t distance) override;
  std::span<const std::int32_t> positions() const override { return motion_.positions(); }
  vm::Status setOutput(int output, bool on) override { return motion_.setOutput(output, on); }
  bool input(int input) override { return motion_.input(input); }
  vm::Status waitFor(int input, bool on) override { return motion_.waitFor(input, on); }
  vm::Status delay(vm::Micros duration) override { return motion_.delay(duration); }
  vm::Status hardHome() override;
  vm::Status reset() override;
  /// On a machine waiting on the scheduler: the move's end reached, the
  /// world reacts (and a straight line goes on with its next knot).
  vm::Status resume() override;
  void window(std::int32_t x, std::int32_t y, std::int32_t z) override { motion_.window(x, y, z); }
  void view(std::int32_t x, std::int32_t y, std::int32_t z) override { motion_.view(x, y, z); }
  vm::Micros now() const override { return motion_.now(); }
  std::uint64_t knots() const override { return motion_.knots(); }
  std::string stillReason() const override { return motion_.stillReason(); }
  vm::IoMask outputs() const override { return motion_.outputs(); }
  vm::IoMask inputs() const override { return motion_.inputs(); }

 private:
  template <typename Move>
  vm::Status moveAndReact(Move&& move);
  /// The move from before_ at start_ to now is done: the sweep, the world.
  vm::Status react();
  /// The line's knots from `from` on (NotYet at one that waits).
  vm::Status runKnots(std::size_t from);
  /// The planner, its cache and its path, made at the first straight
  /// line; false when the robot has no chain. The cache lives as long as
  /// the machine: a loop plans each of its lines once, and a debugger's
  /// replay after a restore plans none.
  bool planner();
  vm::Status runPath(const std::optional<workcell::LineProblem>& problem);

  vm::Machine& motion_;
  World& world_;
  std::size_t robot_ = 0;
  const SimMachine* timeline_ = nullptr;
  CollisionWatch* watch_ = nullptr;
  CollisionMode mode_ = CollisionMode::Off;
  std::vector<std::int32_t> before_;  // where the move under way began, sized once
  vm::Micros start_ = 0;              // when it began
  bool pendingMove_ = false;          // it answered NotYet: the world reacts on resume
  std::size_t lineKnot_ = 0;          // the knot of the line under way
  std::unique_ptr<workcell::LinePlanCache> plans_;
  std::unique_ptr<workcell::LinePlanner> planner_;
  std::unique_ptr<workcell::LinePath> path_;
  // The line being run, while its knots are: their sweeps take the
  // gripper's exemptions from its ends (CollisionWatch::sweep).
  bool inLine_ = false;
  std::vector<std::int32_t> lineFrom_, lineTo_;
};

}  // namespace rs::runtime
