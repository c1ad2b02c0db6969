// The swept check as it was before conservative advancement, kept as the
// slow reference of the differential test (test_sweep_differential.cpp):
// a move is checked at its start and then at times chosen so that no point
// of the robot (or of what it carries) moves farther than kSweepStep
// between checks, whatever the distance to the nearest obstacle: the
// latest such time by bisection, or the first time it moves when one count
// already goes farther. Every point bounded by the model's global motor
// weights (CollisionModel::motorWeights[Carrying]).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "model/workcell/collision_model.h"
#include "runtime/sim/sim_machine.h"
#include "runtime/cell/world.h"

namespace collisiontest {

struct SampledHit {
  rs::vm::Micros at = 0;
  rs::workcell::Contact contact;
};

/// The first check of the move (machine's latest segments, from `before`
/// at `start` to `end`) that sees an overlap, with the world as it was
/// during the move; `checks` counts the poses checked. `step` is the
/// travel bound between checks (the product's was kSweepStep).
std::optional<SampledHit> samplingSweep(const rs::workcell::CollisionModel& model, rs::workcell::CollisionData& data,
                                        const rs::runtime::SimMachine& machine, const rs::runtime::World& world,
                                        std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                        rs::vm::Micros start, rs::vm::Micros end, std::uint64_t& checks,
                                        double step = rs::workcell::kSweepStep);

}  // namespace collisiontest
