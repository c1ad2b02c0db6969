// Objects in the gripper (DESIGN.md, "Objects"): a closed gripper whose
// tool centre point lies inside an object holds it; the object moves with
// the gripper until it opens; RESET puts every object back where the
// workcell placed it.
//
// When is a gripper closed? Its motor's RANGE runs from open (min) to
// closed (max). A move that turns the gripper motor towards max closes the
// gripper; one that turns it towards min opens it. So:
//  - at the end of a closing move, the gripper takes the part (ObjectKind
//    Part) whose box (the bounds of its lines) holds the tool centre point,
//    the smallest such box when boxes nest (a block on a table, not the
//    table); a fixture is never taken;
//  - at the start of an opening move, it lets go: the part settles
//    straight down onto what is under it (model/workcell/settle.h);
//  - in between, the object keeps its pose relative to the end-effector
//    frame: F_world_object = F_world_E(q) · F_E_object.
// A closing move with nothing at the tool centre point holds nothing, and a
// closed gripper moved into an object does not take it (it was not closing
// there). Decided here; documented in docs/models.md.
//
// A cell of several robots has one hand per robot (its index in
// Workcell::robots); where the parts rest is shared. Every call names the
// hand (0, the first robot, when it does not: a cell of one robot).
//
// Hand-over: a closing gripper whose tool centre point lies inside a part
// another hand carries takes it too (where that hand carries it now: the
// caller says where, carriedAt). While two hands hold it, it does not
// move; when either opens, the other has it, by the grip it closed with.
// A let-go never settles a part onto one another hand carries (that one
// is somewhere else by the time it lands).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "model/workcell/model.h"
#include "model/workcell/settle.h"
#include "model/workcell/tool_tracker.h"

namespace rs::workcell {

/// What a step did to the gripper's hold.
struct GraspChange {
  std::size_t object = 0;  ///< index in Workcell::objects
  bool held = false;       ///< true: taken; false: let go
  Settled settled;         ///< a let-go: where it came to rest, on what, how far it dropped
  /// A hand-over: the hand it was taken from (a take), or the hand that
  /// has it now (a let-go; then it did not settle).
  std::optional<std::size_t> other = std::nullopt;
};

class Grasping {
 public:
  /// One hand per robot of `cell` (which must outlive this). A robot
  /// without a gripper never holds anything.
  explicit Grasping(const Workcell& cell);

  /// One step of the program moved the robot's motors (arm joints, then
  /// the gripper, as a program sees them) from `before` to `after`. With
  /// `mayTake` false a closing move takes nothing: a still of a moment
  /// during a closing move, which has not ended yet.
  std::optional<GraspChange> step(std::span<const std::int32_t> before, std::span<const std::int32_t> after,
                                  bool mayTake = true, std::size_t hand = 0);
  /// RESET: nothing held by any hand, every object back at its placement
  /// (and in the cell or out of it as PlacedObject::inCell says).
  void reset();
  /// Object `o` comes into the cell, or goes out of it (a feeder fed its
  /// slot; a sink took its part): out of the cell, nothing takes it and it
  /// holds up nothing let go.
  void setInCell(std::size_t o, bool in);
  /// The objects in the cell, by index: what a grasp or a let-go looks
  /// at (a feeder's 64 slots are out of it while empty).
  const std::vector<std::size_t>& inCell() const { return inCell_; }
  bool isInCell(std::size_t o) const { return o < present_.size() && present_[o] != 0; }

  std::size_t handCount() const { return hands_.size(); }
  /// What hand `hand` holds. By reference: a copy made here went through
  /// the stack in parts and stalled every move's and wake's read of it.
  const std::optional<std::size_t>& held(std::size_t hand = 0) const {
    static const std::optional<std::size_t> kNothing;
    return hand < hands_.size() ? hands_[hand].hold.held : kNothing;
  }
  /// The hand that holds object `o`, if any (the first, while two do).
  std::optional<std::size_t> holder(std::size_t o) const {  // inline: the devices ask per part per wake
    for (std::size_t h = 0; h < hands_.size(); ++h)
      if (hands_[h].hold.held == o) return h;
    return std::nullopt;
  }
  /// Whether two hands hold object `o` (a hand-over under way: it stays put).
  bool shared(std::size_t o) const {  // inline: the robot's sight asks at every move and wake
    int holders = 0;
    for (const Hand& h : hands_) holders += h.hold.held == o;
    return holders > 1;
  }
  /// Object `o`, held by a hand, is at `pose` now (F_world_design): where a
  /// closing gripper of another hand finds it. The caller knows where each
  /// robot's motors are; this does not.
  void carriedAt(std::size_t o, const Eigen::Isometry3d& pose) { carried_[o] = pose; }
  /// F_E_object of the held object (meaningful while something is held).
  const Eigen::Isometry3d& heldOffset(std::size_t hand = 0) const { return hands_.at(hand).hold.offset; }
  /// Object `o`'s placement (F_world_design of its drawing) with hand
  /// `hand`'s robot's motors at `encoders`: where it rests, or where that
  /// gripper carries it (another hand's part: where it last rested).
  Eigen::Isometry3d objectPose(std::size_t o, std::span<const std::int32_t> encoders, std::size_t hand = 0);
  /// The same for an object that is not held (where it rests now).
  const Eigen::Isometry3d& restingPose(std::size_t o) const { return resting_[o]; }
  /// Object `o` (not held) rests at `pose` from now on: a belt moved it, a
  /// feeder put it, a sink took it (runtime/cell/devices.h).
  void setResting(std::size_t o, const Eigen::Isometry3d& pose) {
    resting_[o] = pose;
    letGo_[o].reset();
  }
  /// The end-effector frame in the world for the robot's motors (identity
  /// for a robot without a gripper).
  Eigen::Isometry3d toolFrame(std::span<const std::int32_t> encoders, std::size_t hand = 0);
  /// The object whose box holds `point`: the smallest such box (objects
  /// where they rest), of any kind.
  std::optional<std::size_t> objectAt(const Eigen::Vector3d& point) const { return smallestAt(point, false); }
  /// The part a closing gripper would take with its tool centre point at
  /// `point`: the smallest part's box that holds it. Fixtures are never
  /// taken. With `hand`, a part one other hand carries counts too, where
  /// carriedAt last put it (a hand-over); without, held parts do not.
  std::optional<std::size_t> partAt(const Eigen::Vector3d& point,
                                    std::optional<std::size_t> hand = std::nullopt) const {
    return smallestAt(point, true, hand);
  }
  /// Where the held part would settle if it were let go with the robot's
  /// motors at `encoders` (meaningful while one is held).
  Settled settleHeld(std::span<const std::int32_t> encoders, std::size_t hand = 0);
  /// Where resting part `o` settles from where it rests, on anything but
  /// object `skip` and the parts hands carry: a part that ran off the open
  /// end of `skip`'s belt (runtime/cell/devices.h) settles as a let-go does.
  Settled settleResting(std::size_t o, std::size_t skip) const { return settleFrom(o, resting_[o], skip); }
  /// Whether a move from `before` to `after` turns the gripper towards open.
  bool opens(std::span<const std::int32_t> before, std::span<const std::int32_t> after, std::size_t hand = 0) const {
    const Hand* h = gripping(hand, before, after);
    return h && after[h->gripperMotor] < before[h->gripperMotor];
  }
  /// Whether it turns the gripper towards closed.
  bool closes(std::span<const std::int32_t> before, std::span<const std::int32_t> after, std::size_t hand = 0) const {
    const Hand* h = gripping(hand, before, after);
    return h && after[h->gripperMotor] > before[h->gripperMotor];
  }
  /// The nearest object's box to `point` and the distance to it (0 inside),
  /// for messages about a grasp that took nothing.
  std::optional<std::pair<std::size_t, double>> nearestObject(const Eigen::Vector3d& point) const;
  /// The centre of object `o`'s box in the world, where it rests now.
  Eigen::Vector3d boxCentre(std::size_t o) const { return resting_[o] * boxes_[o].center(); }
  bool hasGripper(std::size_t hand = 0) const { return hand < hands_.size() && hands_[hand].tool.has_value(); }

  /// How an object was let go where it rests: the end-effector frame then
  /// and its F_E_object. A take with the end-effector at that very frame
  /// holds it by that offset again, the exact value of
  /// frame⁻¹·(frame·offset), which rounding would otherwise drift by an ulp
  /// or two a take: a loop that puts a block down and takes it again then
  /// leaves the world bit for bit as it was, so the swept check's memory of
  /// moves (runtime/sim/sweep_memo.h) answers its moves again.
  struct LetGo {
    Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    bool operator==(const LetGo& o) const {
      return frame.matrix() == o.frame.matrix() && offset.matrix() == o.offset.matrix();
    }
  };
  /// What one hand holds.
  struct Hold {
    std::optional<std::size_t> held;
    Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
    bool operator==(const Hold& o) const { return held == o.held && offset.matrix() == o.offset.matrix(); }
  };
  /// What a grasp changes, for snapshots of a run.
  struct State {
    std::vector<Hold> hands;  ///< per robot
    std::vector<Eigen::Isometry3d> resting;
    std::vector<std::optional<LetGo>> letGo;  ///< per object: how it was let go where it rests (none: placed there)
    std::vector<char> present;                ///< per object: in the cell (setInCell)
    bool operator==(const State& o) const {  // exact: a restored run must be bit for bit the same
      if (hands != o.hands || resting.size() != o.resting.size() || letGo != o.letGo || present != o.present)
        return false;
      for (std::size_t i = 0; i < resting.size(); ++i)
        if (resting[i].matrix() != o.resting[i].matrix()) return false;
      return true;
    }
  };
  State state() const;
  void restore(const State& s);

 private:
  struct Hand {
    std::optional<ToolTracker> tool;  // empty: the robot has no gripper
    std::size_t gripperMotor = 0;
    Hold hold;
  };
  std::optional<std::size_t> smallestAt(const Eigen::Vector3d& point, bool partsOnly,
                                        std::optional<std::size_t> takingHand = std::nullopt) const;
  /// Where part `o`, let go at `pose`, comes to rest (never on `skip`).
  Settled settleFrom(std::size_t o, const Eigen::Isometry3d& pose, std::optional<std::size_t> skip = std::nullopt) const;
  /// A hand other than `hand` that holds object `o`.
  std::optional<std::size_t> otherHolder(std::size_t o, std::size_t hand) const;
  /// The hand, when it has a gripper whose motor both positions name.
  const Hand* gripping(std::size_t hand, std::span<const std::int32_t> before,
                       std::span<const std::int32_t> after) const {
    if (hand >= hands_.size()) return nullptr;
    const Hand& h = hands_[hand];
    return h.tool && h.gripperMotor < before.size() && h.gripperMotor < after.size() ? &h : nullptr;
  }

  const Workcell* cell_;
  std::vector<Hand> hands_;  // per robot
  std::vector<Eigen::Isometry3d> resting_;
  std::vector<std::optional<LetGo>> letGo_;  // per object, as State::letGo
  std::vector<Eigen::Isometry3d> carried_;   // per object: where a hand carries it (carriedAt); scratch
  std::vector<Eigen::AlignedBox3d> boxes_;  // in each object's design coordinates
  // Per object: how far its box's corners lie from its design origin
  // (smallestAt passes over what is farther from the point), and
  // settleReach (settle passes over what cannot hold a part up).
  std::vector<double> boxReach_, settleReach_;
  mutable SupportBoxes supportBoxes_;  // settle's boxes of the objects, kept from one let-go to the next
  std::vector<char> present_;         // per object, as State::present
  std::vector<std::size_t> inCell_;   // the objects present_, in order
  void listInCell();
};

}  // namespace rs::workcell
