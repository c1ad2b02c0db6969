// The simulated world around the robot that runs the program: the
// workcell's objects and what the gripper holds. It reacts to what the
// machine does — a move of the gripper motor, RESET — by the rule of
// model/workcell/grasp.h (take at the end of a closing move, let go at the
// start of an opening one, RESET puts everything back). Traces, the
// recording and the summary only look at it.
//
// In a cell of several robots each robot has a hand (its index in
// Workcell::robots); the calls that concern one name it, 0 (the first
// robot) when they do not.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "model/workcell/collision_model.h"
#include "model/workcell/grasp.h"
#include "model/workcell/model.h"
#include "model/workcell/tool_tracker.h"
#include "vm/machine.h"

namespace rs::runtime {

/// The gripper took (`held`) or let go of object `object` (an index in
/// Workcell::objects). A take happens at the end of the closing move
/// (`at`), and `pose` is F_E_object, which the object keeps until let go;
/// a let-go happens as the opening move (or RESET) begins, and `pose` is
/// F_world_object, where the object rests from then on: an opening move's
/// let-go settles it straight down (model/workcell/settle.h) onto `on`
/// (`support`), `drop` below where it was let go; RESET puts it back
/// where the cell placed it (`on` Nothing, no drop).
struct GraspEvent {
  vm::Micros at = 0;
  std::size_t object = 0;
  bool held = false;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  workcell::Settled::On on = workcell::Settled::On::Nothing;
  std::size_t support = 0;
  double drop = 0;
  /// The numbers the run names `object` and `support` by, where fed parts
  /// make them differ from index + 1 (0: index + 1). The world leaves them
  /// 0; the run stamps them (Rig::numbered), as the world knows no feeder.
  std::uint32_t number = 0, supportNumber = 0;
  std::size_t hand = 0;  ///< the robot whose gripper took or let go
  /// A hand-over (model/workcell/grasp.h): the robot it was taken from (a
  /// take), or the robot that has it now (a let-go, which did not settle).
  std::optional<std::size_t> other = std::nullopt;
  /// A let-go that settled: it went down (or up, out of its support) to rest on something.
  bool settled() const { return !held && on != workcell::Settled::On::Nothing; }
  bool operator==(const GraspEvent& o) const {
    return at == o.at && object == o.object && held == o.held && pose.matrix() == o.pose.matrix() && on == o.on &&
           support == o.support && drop == o.drop && hand == o.hand && other == o.other;
  }
};

/// A drop longer than this (length units) is sloppy placing: the part was
/// let go above its support, and the run warns (runtime/run/placing.h).
inline constexpr double kLongDrop = 1.0;

/// A closing move that took nothing, on a workcell with objects: where the
/// tool centre point was at its end, the object whose box is nearest it,
/// how far outside that box it was, and the box's centre (all in the
/// world), so that a message can say which way to move. `fixture`: the
/// tool centre point was in a fixture's box (and no part's), which the
/// gripper closed round and did not take.
struct EmptyClose {
  vm::Micros at = 0;
  Eigen::Vector3d tcp = Eigen::Vector3d::Zero();
  std::optional<std::size_t> fixture;
  std::optional<std::size_t> nearest;
  std::size_t hand = 0;  ///< the robot whose gripper closed
  double distance = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< the nearest box's centre (meaningful with nearest)
  bool operator==(const EmptyClose&) const = default;
};

class World {
 public:
  /// Every robot of `cell` (which must outlive the world) has a hand.
  explicit World(const workcell::Workcell& cell);

  /// Hand `hand`'s robot's motors moved from `before` to `after`, from
  /// `start` to `end`.
  void moved(std::span<const std::int32_t> before, std::span<const std::int32_t> after, vm::Micros start,
             vm::Micros end, std::size_t hand = 0);
  /// RESET at time `at` by hand `hand`'s robot: nothing held by any hand,
  /// every object where the cell placed it.
  void reset(vm::Micros at, std::size_t hand = 0);
  /// Where hand `hand`'s robot's motors are now, for what another robot
  /// sees of the part it carries (must outlive the world; none: the part
  /// shows where it last rested).
  void handMotors(std::size_t hand, const vm::Machine* machine) {
    if (hand < handMachines_.size()) handMachines_[hand] = machine;
  }
  std::size_t handCount() const { return grasping_.handCount(); }

  /// Object `o` (not held) rests at `pose` from now on: the cell's devices
  /// move, put and take parts (runtime/cell/devices.h).
  void place(std::size_t o, const Eigen::Isometry3d& pose) {
    grasping_.setResting(o, pose);
    noteRest(o);
  }
  /// Object `o`'s slot holds a new part at `pose` (a feeder fed it: `inCell`)
  /// or none (a sink took it: out of the cell, parked at `pose`): no let-go
  /// put it there, so it has no restOf.
  void replace(std::size_t o, const Eigen::Isometry3d& pose, bool inCell) {
    place(o, pose);
    grasping_.setInCell(o, inCell);
    state_.rests[o].reset();
  }

  /// Part `o` (resting) ran off the open end of object `from`'s belt: it
  /// settles straight down from where it rests, as a let-go does (never
  /// onto `from` nor a part a hand carries), and rests there. No let-go
  /// put it there: it has no restOf.
  workcell::Settled settleRunOff(std::size_t o, std::size_t from) {
    const workcell::Settled s = grasping_.settleResting(o, from);
    place(o, s.pose);
    state_.rests[o].reset();
    return s;
  }

  /// Counts every take and let-go so far.
  std::uint64_t eventCount() const { return state_.events; }
  /// The latest take or let-go (meaningful once eventCount() > 0).
  const GraspEvent& lastEvent() const { return state_.last; }

  const workcell::Workcell& cell() const { return cell_; }
  const std::optional<std::size_t>& held(std::size_t hand = 0) const { return grasping_.held(hand); }
  /// The hand that holds object `o`, if any (the first, while two do).
  std::optional<std::size_t> holder(std::size_t o) const { return grasping_.holder(o); }
  /// Whether object `o` is in the cell (a feeder's slot is not while empty; RESET empties every slot).
  bool inCell(std::size_t o) const { return grasping_.isInCell(o); }
  /// Whether two hands hold object `o`: a hand-over under way, it stays put.
  bool shared(std::size_t o) const { return grasping_.shared(o); }
  /// When the object hand `hand` holds now was taken (the end of its closing move).
  vm::Micros heldSince(std::size_t hand = 0) const {
    return hand < state_.heldSince.size() ? state_.heldSince[hand] : 0;
  }
  /// Object `o`'s placement (F_world_design) at time `at` with hand
  /// `hand`'s robot's motors at `encoders`: carried by that gripper,
  /// carried by another (where its robot's motors are now: handMotors), or
  /// resting. A take that happens after `at` (a closing move still under
  /// way) has not happened yet.
  Eigen::Isometry3d objectPose(std::size_t o, std::span<const std::int32_t> encoders,
                               vm::Micros at = INT64_MAX, std::size_t hand = 0) const;
  /// Where object `o` rests now (its last resting place while it is held).
  const Eigen::Isometry3d& restingPose(std::size_t o) const { return grasping_.restingPose(o); }
  /// F_E_object of the held object (meaningful while one is held).
  const Eigen::Isometry3d& heldOffset(std::size_t hand = 0) const { return grasping_.heldOffset(hand); }
  /// Writes heldOffset's affine part, 3 x 4 by columns, as its 12 words'
  /// bits (what a memory's key holds of how a part is held), straight from
  /// the transform: a copied matrix went through the stack and stalled.
  void writeHeldOffset(std::size_t hand, std::uint64_t* out) const {
    const double* m = heldOffset(hand).matrix().data();  // 4 x 4, by columns
    for (int c = 0; c < 4; ++c) std::memcpy(out + 3 * c, m + 4 * c, sizeof(double) * 3);
  }
  /// Changes whenever what is held or where an object rests may have
  /// changed (a take, a let-go, RESET, restore): a cache of anything that
  /// depends on them is still good while this stays the same. Not part of
  /// the state: it only ever grows.
  std::uint64_t revision() const { return revision_; }
  /// Whether object `o`'s resting pose may have changed after revision
  /// `since`: false means it is bit for bit what it was then, so a cache
  /// of the resting poses looks only at the objects this names.
  bool restMayDifferSince(std::size_t o, std::uint64_t since) const { return restRevision_[o] > since; }
  /// The objects restMayDifferSince(o, since) names, in index order, into
  /// `out` (cleared first), from the world's log of rests it set: a cell's
  /// belts move a part or two between moves, among many objects. False
  /// when the log no longer goes back that far (a RESET, a restore, or
  /// long ago): then ask restMayDifferSince of each object.
  bool restChangedSince(std::uint64_t since, std::vector<std::size_t>& out) const;
  /// The tool centre point in world coordinates, when the robot has a chain.
  std::optional<std::array<double, 3>> tcp(std::span<const std::int32_t> encoders, std::size_t hand = 0) const;

  /// Closing moves that took nothing, and the latest of them. Only a
  /// workcell with objects counts them: with nothing to take, closing on
  /// nothing is no mistake.
  std::uint64_t emptyCloseCount() const { return state_.emptyCloses; }
  const EmptyClose& lastEmptyClose() const { return state_.lastEmptyClose; }
  /// Closing moves in all, and takes in all.
  std::uint64_t closeCount() const { return state_.closes; }
  std::uint64_t takeCount() const { return state_.takes; }
  /// Closes round a fixture (among the empty closes), and let-gos that
  /// dropped a part more than kLongDrop: what the run warns of.
  std::uint64_t fixtureCloseCount() const { return state_.fixtureCloses; }
  std::uint64_t longDropCount() const { return state_.longDrops; }
  /// How object `o` came to rest where it is: the let-go that settled it
  /// last (none while it is held, or where the cell placed it).
  const std::optional<GraspEvent>& restOf(std::size_t o) const { return state_.rests[o]; }

  /// What the moves since the last call did, recorded as it happened: a
  /// take or a let-go (then lastEvent() is it), a close on nothing (then
  /// lastEmptyClose() is it). The rig asks after every step of a program.
  struct StepEffects {
    bool grasped = false;
    bool closedEmpty = false;
  };
  StepEffects takeStepEffects(std::size_t hand = 0) {
    return hand < step_.size() ? std::exchange(step_[hand], {}) : StepEffects{};
  }

  /// The world as a move from `before` to `after` sees it, for the
  /// collision check: every object's resting pose (written into `poses`,
  /// sized for the objects), what is carried — nothing during an opening
  /// move: it is let go as the move starts and settles at once — and the
  /// part the fingers may overlap: during a closing move the part they
  /// close round (the one it takes at its end), during an opening move the
  /// one they let go. Any other move exempts nothing: fingers that come
  /// down onto a part collide with it.
  /// Another robot's carried part is where that robot holds it now.
  workcell::CollisionQuery collisionQuery(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                          std::span<Eigen::Isometry3d> poses, std::size_t hand = 0) const;

  struct State {
    workcell::Grasping::State grasp;
    std::vector<vm::Micros> heldSince;  // per hand
    std::uint64_t events = 0;
    GraspEvent last;
    std::uint64_t closes = 0, takes = 0, emptyCloses = 0, fixtureCloses = 0, longDrops = 0;
    EmptyClose lastEmptyClose;
    std::vector<std::optional<GraspEvent>> rests;  // per object: restOf
    bool operator==(const State& o) const = default;
  };
  State state() const;
  void restore(const State& state);

 private:
  /// Tells the grasp where the parts hands other than `hand` carry are
  /// now, for a closing gripper of `hand` that may take one over.
  void noteCarried(std::size_t hand) const;

  const workcell::Workcell& cell_;
  // Scratch workspaces of the kinematics: asking where something is does
  // not change the world.
  mutable workcell::Grasping grasping_;
  mutable std::vector<std::optional<workcell::ToolTracker>> tools_;  // per hand
  std::vector<const vm::Machine*> handMachines_;                   // per hand
  mutable std::vector<std::int32_t> otherMotors_;                  // scratch
  State state_;  // all but the grasp, which grasping_ keeps
  std::vector<StepEffects> step_;  // per hand, since its last takeStepEffects (a restore forgets them)
  std::uint64_t revision_ = 0;
  std::vector<std::uint64_t> restRevision_;  // per object: the revision that last set its resting pose
  // Every rest set after revision restLogFrom_, as (revision, object):
  // restChangedSince's. Kept to kRestLog entries (the older half dropped).
  static constexpr std::size_t kRestLog = 4096;
  std::vector<std::pair<std::uint64_t, std::size_t>> restLog_;
  std::uint64_t restLogFrom_ = 0;
  void noteRest(std::size_t o);
  void noteEveryRest();
};

}  // namespace rs::runtime
