// The parts that run off a belt's open end (devices.h, CellDevices::runOff),
// and the piles the belts' plan and the run-off move as one (gatherPile).
#include <algorithm>
#include <cmath>

#include "runtime/cell/devices.h"

namespace rs::runtime {

bool CellDevices::onBelt(const Eigen::AlignedBox3d& b, const Geometry& g) {
  return std::abs(b.min().y() - g.belt.max().y()) <= kRestTolerance;
}

// A part rests on another when its bottom is within the tolerance of the
// other's top and their footprints overlap by more than a sliver.
void CellDevices::gatherPile(std::vector<std::size_t>& pile, std::size_t from) {
  constexpr double kSliver = 1e-6;
  for (std::size_t k = from; k < pile.size(); ++k) {
    const Eigen::AlignedBox3d& under = partBox(parts_[pile[k]]);
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const std::size_t o = parts_[i];
      if (takenScratch_[o] || world_.holder(o)) continue;
      const Eigen::AlignedBox3d& b = partBox(o);
      if (std::abs(b.min().y() - under.max().y()) > kRestTolerance) continue;
      if (std::min(b.max().x(), under.max().x()) - std::max(b.min().x(), under.min().x()) <= kSliver ||
          std::min(b.max().z(), under.max().z()) - std::max(b.min().z(), under.min().z()) <= kSliver)
        continue;
      takenScratch_[o] = true;
      pile.push_back(i);
    }
  }
}

// A part on a belt whose centre passed its open end runs off, with the
// parts piled on it: each settles straight down as a let-go does
// (workcell::settle, never onto that belt's object), the lowest first (then
// by object), so a pile lands in order and a part lands on one that ran off
// below it at the same instant.
void CellDevices::runOff(vm::Micros now) {
  const workcell::Devices& d = cell_.devices;
  runOff_.clear();
  for (const std::size_t o : parts_) takenScratch_[o] = false;
  for (const std::size_t o : parts_) {
    if (state_.ridden[o] == 0 || world_.holder(o)) continue;
    const std::size_t c = state_.ridden[o] - 1;
    if (!belts_[c] || !cell_.objects[d.conveyors[c].object].belt->endOpen) continue;
    const Geometry& g = *belts_[c];
    const Eigen::AlignedBox3d& b = partBox(o);
    // A part piled on another goes with the one under it.
    if (!onBelt(b, g) || g.dir.dot(b.center()) < g.end - 1e-9) continue;
    pile_.clear();
    pile_.push_back(static_cast<std::size_t>(std::lower_bound(parts_.begin(), parts_.end(), o) - parts_.begin()));
    takenScratch_[o] = true;
    gatherPile(pile_, 0);
    for (const std::size_t i : pile_) runOff_.emplace_back(parts_[i], c);
  }
  std::sort(runOff_.begin(), runOff_.end(), [this](const auto& a, const auto& b) {
    const double ya = partBox(a.first).min().y(), yb = partBox(b.first).min().y();
    return ya != yb ? ya < yb : a.first < b.first;
  });
  for (const auto& [o, c] : runOff_) {
    const workcell::Settled s = world_.settleRunOff(o, d.conveyors[c].object);
    worldBox(o);
    state_.ridden[o] = 0, state_.velocity[o].setZero(), state_.travel[o] = 0;
    DeviceEvent e{DeviceEvent::Kind::RunsOff, now, c, o, state_.number[o]};
    e.on = s.on, e.support = s.support, e.drop = s.drop;
    const bool onObject = s.on == workcell::Settled::On::Object || s.on == workcell::Settled::On::Belt;
    e.supportNumber = onObject ? state_.number[s.support] : 0;
    events_.push_back(e);
  }
}

}  // namespace rs::runtime
