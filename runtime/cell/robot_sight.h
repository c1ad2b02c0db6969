// What the robot shows the cell's sensors (issue 35): the part its
// gripper carries (every sensor that sees parts) and its own links and
// gripper (SENSOR ... SEES ROBOTS or SEES ALL: a light curtain), and the
// exact microsecond that changes while it moves. A move's motors each go
// one way from start to end, so the collision model's bound on how far a
// point can move per encoder count (CollisionModel::motorWeights,
// carriedWeights) bounds how far a box can move over any stretch of the
// move (and, for the carried part, each corner's way lies in an ellipsoid
// round its two places: a part lifted straight up keeps its x and z):
// a stretch whose boxes, grown (or shrunk) by that bound, cannot
// change what a sensor sees is passed over whole; the others are halved,
// down to one microsecond. Nothing is sampled and missed. Faster, to the
// same microsecond: a crossing sought along the crossing face's gap
// first (locate), a SCARA's carried box keeping its height, and the last
// search's answer given again to a wake later in the same move.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "base/chained_memo.h"
#include "model/workcell/collision_model.h"
#include "model/workcell/model.h"
#include "runtime/cell/world.h"
#include "vm/machine.h"

namespace rs::runtime {

class RobotSight {
 public:
  /// Where the motors are at time t (each motor goes one way over a move).
  using MotorsAt = std::function<void(vm::Micros, std::span<std::int32_t>)>;

  /// Robot `robot` of `cell` (its index in Workcell::robots, its hand in
  /// the world), with `motors` motors; cell and world must outlive this.
  RobotSight(const workcell::Workcell& cell, const World& world, std::size_t motors, std::size_t robot = 0);
  ~RobotSight();

  /// Whether the robot can ever show a sensor anything (a sensor that sees
  /// parts, or one that sees robots, and a robot with a chain).
  bool matters() const { return matters_; }
  /// Whether it can show a sensor anything now: a part carried, or a
  /// sensor that sees the robot. Otherwise firstChange() finds nothing, and
  /// need not be asked (nor its motion key made).
  bool watches() const { return matters_ && (seesRobots_ || carriedPart()); }
  /// Per sensor (Devices::sensors), whether the carried part or the robot
  /// touches it with the motors at `encoders` (`out` sized for the sensors).
  void sees(std::span<const std::int32_t> encoders, std::vector<bool>& out);
  /// Writes the words of the motion from a search's start on
  /// (RobotIo::motionKey), or returns false when it has none worth keeping;
  /// firstChange() asks only when its last search does not answer.
  using MotionKey = std::function<bool(std::vector<std::uint64_t>&)>;
  /// The first microsecond in (from, to] at which sees() answers other
  /// than at `from`, while the motors move as `at` says; none when it
  /// does not change. At most kMaxProbes poses are looked at: past them,
  /// the microsecond it stopped at (a look there goes on from it).
  /// `motion`, when given, fixes the motion from `from` on (RobotIo::
  /// motionKey): a search made once is answered again for the same motion
  /// with the same part carried the same way, as the sweep's memory
  /// answers a move made again (a production loop asks the same each cycle).
  std::optional<vm::Micros> firstChange(vm::Micros from, vm::Micros to, const MotorsAt& at,
                                        const MotionKey& motion = {});
  /// What sees() answers at `now`, without posing the arm, when the last
  /// firstChange() was asked from `now` to `to` and answered (from its
  /// last search, its memory, or a search): nothing changes from the
  /// search's start until its answer, so it is what it saw at its start.
  /// False: ask sees().
  bool seenAsAsked(vm::Micros now, vm::Micros to, std::vector<bool>& out) const;
  /// Searches answered from memory, and searches made.
  std::uint64_t remembered() const { return remembered_; }
  std::uint64_t searched() const { return searched_; }
  /// Searches remembered at most (then all are forgotten at once).
  static constexpr std::size_t kRemembered = 4096;
  static constexpr int kMaxProbes = 20'000;
  /// Forget the last search (the world or the motion was restored).
  void forget() { last_.reset(), asked_.reset(); }

 private:
  struct Probe;
  /// The part this robot carries (moving with it), if any. A part two
  /// hands hold stays put: the devices see it where it rests. Inline: the
  /// devices ask at every wake and move (out of line, its optionals went
  /// through the stack and stalled).
  std::optional<std::size_t> carriedPart() const {
    const std::optional<std::size_t>& held = world_.held(robot_);
    if (!held || world_.shared(*held)) return std::nullopt;
    return held;
  }
  void probe(vm::Micros t, const MotorsAt& at, Probe& out);
  void look(Probe& p);
  bool stays(const Probe& a, const Probe& b) const;
  std::optional<vm::Micros> search(const Probe& a, const Probe& b, const std::vector<bool>& start, const MotorsAt& at,
                                   int& budget, std::size_t depth);
  std::optional<vm::Micros> locate(const Probe& a, const Probe& b, const std::vector<bool>& start, const MotorsAt& at,
                                   int& budget);
  // Halvings of a move go at most this deep (2^62 microseconds).
  static constexpr std::size_t kDepth = 64;

  const workcell::Workcell& cell_;
  const World& world_;
  std::size_t motors_;
  std::size_t robot_;
  bool matters_ = false;
  bool seesRobots_ = false;
  bool levelTurns_ = false;  // the arm's turns keep every height (a SCARA)
  std::unique_ptr<workcell::CollisionModel> model_;
  std::unique_ptr<workcell::CollisionData> data_;
  std::vector<double> carried_;  // per motor: how far the carried part moves per count
  std::vector<Probe> pool_;      // per depth of the search: its look
  std::vector<Probe> guess_;     // locate's three: the low and high ends, the guess
  std::vector<bool> start_;
  // The last search, whole (its budget not spent): what it found holds
  // from any later start before its answer, in the same move (the same
  // end, the motors there, the same part carried the same way), so the
  // devices' wakes during a move ask again for nothing.
  struct Last {
    vm::Micros from = 0, to = 0;
    std::optional<vm::Micros> change;
    std::vector<std::int32_t> end;  // the motors at `to`
    std::optional<std::size_t> carried;
    Eigen::Matrix<double, 3, 4> offset = Eigen::Matrix<double, 3, 4>::Zero();
    std::vector<bool> start;  // what sees() answered at `from`
  };
  bool remembers(const Last& last, vm::Micros from, vm::Micros to, const Probe& end,
                 const std::optional<std::size_t>& carried) const;
  std::optional<Last> last_;
  /// last_ := this search's answer, and asked_ its span.
  void keepLast(vm::Micros from, vm::Micros to, std::optional<vm::Micros> change, const std::vector<std::int32_t>& end,
                std::optional<std::size_t> held, const std::vector<bool>& start);
  // Whole searches by everything their answer depends on: the time to the
  // move's end, the motion, the part carried and how; the answer counted
  // from the search's start (-1: none), and what it saw there.
  struct Answer {
    vm::Micros after = -1;
    std::vector<bool> start;  // what sees() answered at the start
  };
  base::ChainedMemo<Answer> memory_{kRemembered};
  // The span the last firstChange() was asked for, when last_ answers for it.
  std::optional<std::pair<vm::Micros, vm::Micros>> asked_;
  std::vector<std::uint64_t> key_;
  std::uint64_t remembered_ = 0, searched_ = 0;
};

}  // namespace rs::runtime
