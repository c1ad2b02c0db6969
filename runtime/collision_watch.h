// Collisions during moves (docs/models.md, "Collisions"): every move of the
// robot that runs the program is checked along the way, not only at its
// ends. The move is sampled at times chosen so that, between two checks,
// no point of the robot (gripper and carried object included) moves
// farther than workcell::kSweepStep: the sampler asks the machine where
// each motor is at time t of the move (SimMachine::positionAt, whatever
// profile the motors follow) and bounds each point's travel by the
// encoder counts covered times the model's motor weights. Each motor moves
// one way during a move, so counts covered between two samples bound every
// moment in between. Deterministic: the same move gives the same samples.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/workcell/collision_model.h"
#include "runtime/sim_machine.h"
#include "vm/machine.h"

namespace rs::runtime {

class World;

/// What a collision does to a run: stop it (a runtime error), note it, or
/// nothing (no checks at all).
enum class CollisionMode : std::uint8_t { Error, Warn, Off };

/// "error", "warn", "off".
std::string_view collisionModeName(CollisionMode mode);
std::optional<CollisionMode> collisionModeByName(std::string_view name);

/// A collision found during a move: the first check of the move at which
/// two parts overlapped.
struct CollisionEvent {
  vm::Micros at = 0;                   ///< simulated time of that check
  workcell::Contact contact;
  std::vector<std::int32_t> encoders;  ///< every motor at `at`
  std::uint32_t instruction = UINT32_MAX;  ///< the move's instruction (0-based), once the run knows it
};

class CollisionWatch {
 public:
  /// The first robot of `cell` (which must outlive the watch) moves.
  explicit CollisionWatch(const workcell::Workcell& cell);

  /// Checks the move the machine just made from `before` (its positions at
  /// `start`) to its positions at `end`, with the world as it was during
  /// the move. Returns the first collision, also kept in events().
  const CollisionEvent* sweep(const SimMachine& machine, const World& world, std::span<const std::int32_t> before,
                              std::span<const std::int32_t> after, vm::Micros start, vm::Micros end);

  const workcell::CollisionModel& model() const { return model_; }
  std::span<const CollisionEvent> events() const { return events_; }
  std::vector<CollisionEvent>& mutableEvents() { return events_; }
  /// How many checks (poses) the sweeps have made so far.
  std::uint64_t checks() const { return checks_; }
  /// "link 2 (upper_arm) hits object 3 (block)".
  std::string describe(const workcell::Contact& contact) const;

 private:
  double travel(const SimMachine& machine, vm::Micros t) const;

  workcell::CollisionModel model_;
  workcell::CollisionData data_;
  std::vector<CollisionEvent> events_;
  std::vector<Eigen::Isometry3d> poses_;  // scratch: every object's resting pose
  std::vector<double> weights_;           // scratch: this move's motor weights
  std::vector<std::int32_t> at_, sample_;  // scratch: motors at the last check, at a candidate time
  std::uint64_t checks_ = 0;
};

}  // namespace rs::runtime
