// Collisions during moves (docs/models.md, "Collisions"): every move of the
// robot that runs the program is checked along the way, not only at its
// ends, by conservative advancement. At each check the pose's clearance
// says, for every moving part, how far it can go before it could touch
// anything (CollisionData::findContactOrClearance); the next check is the
// latest time at which no part has gone farther than its clearance, or
// than workcell::kSweepStep where its clearance is less, or than the
// look-ahead (MotionBounds::kLookAhead: a check counts nothing farther):
// free space costs a check per look-ahead of travel, and only near contact
// are checks as close as the bound.
// How far a part has gone from time t to t' is bounded by the encoder
// counts each motor covered times the part's weight for that motor
// (CollisionModel::bodyWeights); each motor moves one way during a move,
// so the counts covered between two checks bound every moment in between.
// The machine says where each motor is at time t (SimMachine::positionAt,
// whatever profile it follows); a microsecond in which a motor covers more
// than a count (faster than 1,000,000 counts a second) is stepped through
// by counts when it goes farther than the limits, so the bound holds at
// every speed an image allows. Deterministic: the same move is checked at
// the same times. A move made before in the same world is answered from
// memory (runtime/sim/sweep_memo.h), with the same verdict; so is one made
// before among the same shapes at the same places near its way
// (reachKeyOf), whatever stands farther off.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/workcell/collision_model.h"
#include "runtime/sim/moving_parts.h"
#include "runtime/sim/sim_machine.h"
#include "runtime/sim/sweep_memo.h"
#include "runtime/sim/sweep_motion.h"
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
  std::uint32_t instruction = 0;       ///< the move's instruction (0-based)
  double depth = 0;                    ///< how deep the parts are in each other at `at` (length units, as drawn)
  /// The move ends with the same two parts in each other by a little (at
  /// most CollisionWatch::kEndsInBy): a block set down a fraction too low.
  std::optional<workcell::Overlap> endsIn = {};
  bool operator==(const CollisionEvent&) const = default;
};

class CollisionWatch {
 public:
  /// Robot `robot` of `cell` (which must outlive the watch) moves; its
  /// hand in the world is the same index.
  explicit CollisionWatch(const workcell::Workcell& cell, std::size_t robot = 0);

  /// Checks the move the machine just made from `before` (its positions at
  /// `start`) to its positions at `end`, with the world as it was during
  /// the move. Returns the first collision, also kept in events(). For a
  /// knot of a straight line, `lineFrom` and `lineTo` are the line's ends:
  /// what the fingers may overlap (World::collisionQuery: the part they
  /// close or open round) is judged as in one move from lineFrom to lineTo.
  const CollisionEvent* sweep(const SimMachine& machine, const World& world, std::span<const std::int32_t> before,
                              std::span<const std::int32_t> after, vm::Micros start, vm::Micros end,
                              std::span<const std::int32_t> lineFrom = {}, std::span<const std::int32_t> lineTo = {});

  /// The watch's cell is the world's with parts appended from
  /// `worldObjects` on, which `others` poses and moves (a cell run's other
  /// robots; it must outlive the watch). While none of them moves during a
  /// move, they stand where they are; while one does, each check poses
  /// them (and the parts they carry) at its time, and the next check comes
  /// before the moving part and they together could close the gap between
  /// them (kSweepStep where it is less, down to one microsecond of theirs).
  /// `label` names the moving robot in messages ("link 4 (wrist) of robot 'left'").
  void alsoAvoid(std::size_t worldObjects, MovingParts& others, std::string label);

  /// The moves checked from now on are instruction `instruction`'s (the
  /// run says so before each step): the collisions they find carry it.
  void atInstruction(std::uint32_t instruction) { instruction_ = instruction; }
  /// The knots of one straight line follow (CellMachine::moveLine): they
  /// are one move, reported once, with its first contact. A knot swept
  /// after the line's first collision is not checked again (docs/cli.md,
  /// --collisions=warn: each colliding move once).
  void beginLine() { lineFirstEvent_ = events_.size(); }

  const workcell::CollisionModel& model() const { return model_; }
  std::span<const CollisionEvent> events() const { return events_; }
  /// Back to the collisions of a snapshot (Rig::restore).
  void restoreEvents(std::vector<CollisionEvent> events) { events_ = std::move(events); }
  /// How many checks (poses) the sweeps have made so far.
  std::uint64_t checks() const { return checks_; }
  /// Moves checked so far, and how many of them were answered from memory.
  std::uint64_t moves() const { return moves_; }
  std::uint64_t remembered() const { return remembered_; }
  /// Forget every remembered verdict (for measuring the sweep itself).
  void forget() {
    memo_ = SweepMemo();
    worldRevision_.reset();
  }
  /// "link 2 (upper_arm) hits object 3 (block)".
  std::string describe(const workcell::Contact& contact) const;
  /// The same with how deep they are in each other: "object 2 (block) hits
  /// object 1 (pallet), 0.12 deep".
  std::string describe(const CollisionEvent& event) const;
  /// How to get past it, where the move ends in the part it hits by a
  /// little: "the move ends with object 2 (block) 0.2 into object 1
  /// (pallet): end it 0.2 higher"; else "".
  std::string hint(const CollisionEvent& event) const;
  /// "By a little": a move that ends with the parts it collided this far in
  /// each other or less gets hint() (length units; the sweep's own step).
  static constexpr double kEndsInBy = workcell::kSweepStep;

 private:
  SweepVerdict advance(const SimMachine& machine, const World& world, const workcell::CollisionQuery& query,
                       std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                       vm::Micros end);
  void othersAt(const World& world, vm::Micros t, vm::Micros end);
  const CollisionEvent* sweepPosed(const SimMachine& machine, const World& world, std::span<const std::int32_t> before,
                                   std::span<const std::int32_t> after, vm::Micros start, vm::Micros end,
                                   std::span<const std::int32_t> lineFrom, std::span<const std::int32_t> lineTo);
  void othersPose();
  const CollisionEvent* noteVerdict(vm::Micros start, const SweepVerdict& verdict);
  std::optional<double> carriedReach(const workcell::CollisionQuery& query) const;
  void reachKeyOf(const SimMachine& machine, const workcell::CollisionQuery& query,
                  std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                  vm::Micros end);
  /// Stretches a move's reach is worked out over, at most; moves whose
  /// stretches are kept, at most.
  static constexpr std::size_t kStretches = 32, kMoveReaches = 4096;
  // A move's stretches (moveReach): per stretch and part, the part's box
  // at the stretch's start and how near an object must come to it to
  // count; per stretch, their union and the largest; over all, the same.
  struct MoveReach {
    std::size_t parts = 0;
    std::vector<Eigen::AlignedBox3d> boxes, stretchAll;
    std::vector<double> reaches, stretchReach;
    Eigen::AlignedBox3d all;
    double allReach = 0;
  };
  MoveReach moveReach(const SimMachine& machine, const workcell::CollisionQuery& query,
                      std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
                      vm::Micros end);
  void keyOf(const World& world, std::span<const std::int32_t> before, std::span<const std::int32_t> after,
             std::span<const std::int32_t> lineFrom, std::span<const std::int32_t> lineTo);
  double used(const SimMachine& machine, vm::Micros t);
  void partWay(std::span<const std::int32_t> from, std::span<const std::int32_t> to, std::int64_t k,
               std::int64_t steps);

  std::size_t hand_ = 0;  // the robot that moves, its hand in the world
  workcell::CollisionModel model_;
  workcell::CollisionData data_;
  MotionBounds bounds_;
  std::vector<workcell::PartClearance> clearance_;  // per part: this check's gaps
  std::vector<CollisionEvent> events_;
  std::uint32_t instruction_ = 0;  // the instruction whose moves are checked
  std::size_t lineFirstEvent_ = 0;  // events_.size() when the line being run began
  SweepMemo memo_;
  std::optional<std::uint64_t> worldRevision_;  // the world's revision placesId_ was taken at
  std::uint64_t placesId_ = 0;
  std::vector<std::uint64_t> key_;         // scratch: this move's key
  std::vector<std::uint64_t> reachKey_;    // scratch: its key by what it can reach (reachKeyOf)
  std::unordered_map<std::vector<std::uint64_t>, MoveReach, base::WordsHash> reaches_;  // by moveWords_
  std::vector<std::uint64_t> change_;      // scratch: keyOf's change of places
  std::vector<std::size_t> restChanged_;   // scratch: keyOf's objects whose rest the world set since
  std::vector<Eigen::Isometry3d> resting_;  // where the objects rested at placesId_ (poses_ is the queries')
  std::vector<std::uint64_t> moveWords_;   // scratch: a move and what it carries
  std::vector<Eigen::AlignedBox3d> boxes_;  // scratch: reachBoxes'
  std::vector<std::int32_t> stretchFrom_, stretchTo_;  // scratch: the motors at a stretch's ends
  std::vector<std::uint64_t> shapeOf_;     // per object: a number per shape
  // Object o's shape number; past the cell's objects (another robot's
  // parts), a number of its own.
  std::uint64_t shapeNumber(std::size_t o) const { return o < shapeOf_.size() ? shapeOf_[o] : shapeOf_.size() + o; }
  std::vector<std::uint64_t> entries_;     // scratch: reachKeyOf's per object
  std::vector<std::size_t> order_;         // scratch: their order
  std::vector<char> outOfReach_;           // scratch: per object, out of the move's reach
  std::vector<Eigen::Isometry3d> poses_;   // scratch: every object's resting pose
  std::size_t worldObjects_ = 0;           // poses_ past these are others_'
  MovingParts* others_ = nullptr;
  std::string label_;                      // the moving robot's, in a cell of several
  vm::Micros othersAt_ = 0;                // the time others_ poses them at
  bool othersMove_ = false;                // one of them moves during the move checked
  vm::Micros checkAt_ = 0;                 // the time of the last check, while they move
  std::vector<std::pair<std::size_t, std::size_t>> carried_;  // scratch: (object, hand) other hands carry
  std::vector<std::int32_t> at_, probe_;   // scratch: motors at the last check, at a time tried
  std::vector<std::int32_t> next_;         // scratch: motors at the microsecond after the last check's
  std::uint64_t checks_ = 0, moves_ = 0, remembered_ = 0;
};

}  // namespace rs::runtime
