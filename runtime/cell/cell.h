// The running cell: what belongs to the whole workcell rather than to one
// robot. Its one virtual clock and event queue (scheduler.h), and, on a
// workcell, its world (world.h: the objects, what each rests on, who holds
// what). A robot's machine runs on the cell's clock: its moves and delays
// advance it, and whatever else the cell schedules happens during them.
#pragma once

#include <optional>

#include "model/workcell/model.h"
#include "runtime/cell/scheduler.h"
#include "runtime/cell/world.h"

namespace rs::runtime {

class Cell {
 public:
  /// `workcell` may be null (a robot alone: a clock, no world); it must
  /// outlive the cell.
  explicit Cell(const workcell::Workcell* workcell) {
    if (workcell) world_.emplace(*workcell);
  }
  Cell(const Cell&) = delete;
  Cell& operator=(const Cell&) = delete;

  Scheduler& clock() { return clock_; }
  const Scheduler& clock() const { return clock_; }
  World* world() { return world_ ? &*world_ : nullptr; }
  const World* world() const { return world_ ? &*world_ : nullptr; }

  struct State {
    Scheduler::State clock;
    std::optional<World::State> world;
    bool operator==(const State&) const = default;
  };
  State state() const {
    State s{clock_.state(), std::nullopt};
    if (world_) s.world = world_->state();
    return s;
  }
  void restore(const State& s) {
    clock_.restore(s.clock);
    if (world_ && s.world) world_->restore(*s.world);
  }

 private:
  Scheduler clock_;
  std::optional<World> world_;
};

}  // namespace rs::runtime
