#include "runtime/sim/cell_machine.h"

#include <algorithm>
#include <fmt/format.h>

#include "base/seconds.h"
#include "vm/interpreter.h"

namespace rs::runtime {

template <typename Move>
vm::Status CellMachine::moveAndReact(Move&& move) {
  const auto positions = motion_.positions();
  std::copy(positions.begin(), positions.end(), before_.begin());
  const vm::Micros start = motion_.now();
  vm::Status status = move();
  if (!status) return status;
  if (watch_ && mode_ != CollisionMode::Off) {
    const CollisionEvent* hit = watch_->sweep(*timeline_, world_, before_, motion_.positions(), start, motion_.now());
    if (hit && mode_ == CollisionMode::Error)
      return vm::Status::fault(
          fmt::format("collision at {} s: {}", base::formatSeconds(hit->at), watch_->describe(hit->contact)));
  }
  world_.moved(before_, motion_.positions(), start, motion_.now());
  return status;
}

vm::Status CellMachine::moveTo(std::span<const std::int32_t> targets) {
  return moveAndReact([&] { return motion_.moveTo(targets); });
}

vm::Status CellMachine::hardHome() {
  return moveAndReact([&] { return motion_.hardHome(); });
}

vm::Status CellMachine::reset() {
  vm::Status status = motion_.reset();
  if (status) world_.reset(motion_.now());
  return status;
}

}  // namespace rs::runtime
