// The cell's devices acting on its clock (issue 35; docs/models.md,
// "Devices"): belts carry the parts resting on them, sensors see parts
// cross a beam or a zone, feeders put new parts, sinks take them, wires
// carry sensors and outputs to the robot's inputs. No per-tick stepping:
// between two events every part on a running belt moves on a straight line
// at the belt's speed until its stop, and the next event (a sensor's edge,
// a part reaching a sink or running off an open end, a feeder's place
// freed) is solved for on those lines, to the microsecond.
//
// Fed parts live in slots appended to the cell's objects (withFeederSlots):
// kFeederSlots per feeder (fewer with COUNT), parked far below the floor
// while empty. A part's number (the trace's "object 5") is given when it
// appears and never given again.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/chained_memo.h"

#include "model/workcell/model.h"
#include "runtime/cell/input_cause.h"
#include "runtime/cell/robot_sight.h"
#include "runtime/cell/scheduler.h"
#include "runtime/cell/world.h"
#include "vm/machine.h"

namespace rs::runtime {

/// Parts of one feeder that may be in the cell at once; one more stops the
/// run with an error (a feeder that floods the cell).
inline constexpr std::size_t kFeederSlots = 64;

/// A copy of `cell` with its feeders' slots appended to its objects (the
/// same cell when it has no feeders).
std::shared_ptr<const workcell::Workcell> withFeederSlots(std::shared_ptr<const workcell::Workcell> cell);

/// What the devices read and write of the robot that runs the program.
class RobotIo {
 public:
  virtual ~RobotIo() = default;
  virtual bool output(int output) const = 0;
  /// Input `input` turns `on` now, because of `cause` (a wire).
  virtual void setInput(int input, bool on, const InputCause& cause) = 0;
  /// The robot's motors (arm, then gripper) at time `t` of the move under
  /// way, or where they stand (what a sensor that sees the robot or its
  /// carried part looks at).
  virtual void motorsAt(vm::Micros t, std::span<std::int32_t> out) const = 0;
  virtual std::size_t motorCount() const = 0;
  /// Appends words that fix the robot's motion from `origin` on (motorsAt
  /// at every t >= origin): the same words, the same motion. False when it
  /// cannot say (then nothing is remembered of it).
  virtual bool motionKey(vm::Micros /*origin*/, std::vector<std::uint64_t>& /*out*/) const { return false; }
};

/// One thing a device did, for the trace and the run log.
struct DeviceEvent {
  /// RunsOff: a part ran off a conveyor's open end and settled (`device`
  /// is the conveyor; `on`, `support`, `drop` as a let-go's GraspEvent).
  enum class Kind : std::uint8_t { SensorOn, SensorOff, Fed, Waits, Taken, RunsOff };
  Kind kind = Kind::SensorOn;
  vm::Micros at = 0;
  std::size_t device = 0;         ///< in its kind's list of Workcell::devices
  std::size_t object = 0;         ///< Fed, Taken, Waits (what takes the place), RunsOff: index in the objects
  std::uint32_t number = 0;       ///< that object's number
  Eigen::Vector3d place = Eigen::Vector3d::Zero();  ///< Fed: its AT corner
  workcell::Settled::On on = workcell::Settled::On::Nothing;  ///< RunsOff: what it settled on
  std::size_t support = 0;                                    ///<   (an index in the objects)
  std::uint32_t supportNumber = 0;                            ///<   its number
  double drop = 0;                                            ///<   and how far it dropped
  bool operator==(const DeviceEvent& o) const {
    return kind == o.kind && at == o.at && device == o.device && object == o.object && number == o.number &&
           place == o.place && on == o.on && support == o.support && supportNumber == o.supportNumber &&
           drop == o.drop;
  }
};

/// Where a part is from time `at` on, and how it moves (a belt carries
/// it): what the pictures replay (runtime/run/run_log.h keeps them). Its
/// place at t >= at is `pose` moved along `velocity` (units per second) by
/// min(|velocity| (t - at), travel); a part a sink took, or a feeder's
/// empty slot, is at parkedPose(). Never recorded while the gripper holds it.
struct PartMotion {
  vm::Micros at = 0;
  std::size_t object = 0;  ///< index in the objects
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< F_world_design at `at`
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double travel = 0;  ///< may be infinite (an open end)
  /// Where it is at `t` (>= at).
  Eigen::Isometry3d poseAt(vm::Micros t) const;
};

class CellDevices final : public CellProcess {
 public:
  /// `cell` is withFeederSlots' copy (the world's cell); everything must
  /// outlive this. `robots` has one entry per robot of the cell (its
  /// index), null for a robot that runs nothing: its outputs stay OFF and
  /// nothing reads its inputs. Adds itself and a process per wire to
  /// `clock`, and schedules the start of the run (the first parts fed,
  /// every sensor and wire as the cell begins).
  CellDevices(const workcell::Workcell& cell, World& world, std::vector<RobotIo*> robots, Scheduler& clock);
  /// A cell whose first robot alone runs a program.
  CellDevices(const workcell::Workcell& cell, World& world, RobotIo& io, Scheduler& clock);
  ~CellDevices() override;

  void wake(const CellEvent& event, Scheduler& clock) override;
  bool update(Scheduler& clock) override;
  std::string name() const override { return "the cell's devices"; }

  /// Robot `robot`'s output changed now: the devices that read it act.
  /// True when a wire from it turns an input at this same instant (no
  /// AFTER), or a feeder it drives may put a part into a sensor now.
  bool outputChanged(int output, std::size_t robot = 0);
  /// Robot `robot` moves from now until `until`: a sensor that sees the
  /// part it carries (or the robot) changes at the exact microsecond the
  /// move brings it there (robot_sight.h).
  void robotMoves(vm::Micros until, std::size_t robot = 0);
  /// The world may have changed outside the devices (a take, a let-go):
  /// they look again now.
  void sync();
  /// Every part on a running belt moved to where it is now (before the
  /// robot looks at the world).
  void commit();
  /// A device's mistake that stops the run (a feeder out of slots), once.
  std::optional<std::string> takeFault() { return std::exchange(fault_, std::nullopt); }

  /// Object `o`'s number, 0 while it is not in the cell.
  std::uint32_t number(std::size_t o) const { return state_.number[o]; }
  bool present(std::size_t o) const { return state_.number[o] != 0; }
  bool sensorOn(std::size_t s) const { return state_.sensorOn[s]; }
  std::uint64_t sensorCount(std::size_t s) const { return state_.sensorCount[s]; }
  std::uint64_t carried(std::size_t c) const { return state_.carried[c]; }
  std::uint64_t fed(std::size_t f) const { return state_.fed[f]; }
  std::uint64_t taken(std::size_t s) const { return state_.taken[s]; }
  bool running(std::size_t c) const;
  /// The robots' sight searches answered from memory, and made (RobotSight).
  std::uint64_t sightsRemembered() const;
  std::uint64_t sightsSearched() const;

  /// What the devices did since the last call, in order.
  std::vector<DeviceEvent> takeEvents() { return std::exchange(events_, {}); }
  /// The events no one has taken yet (the cell's first instant's, before
  /// the first step), for a snapshot; putBack restores them after restore().
  const std::vector<DeviceEvent>& pendingEvents() const { return events_; }
  void putBack(std::vector<DeviceEvent> events) { events_ = std::move(events); }

  /// Keep a PartMotion whenever a part's motion changes (off by default:
  /// only a run that keeps a log asks). After a restore, the next instant
  /// records every part again.
  void recordMotions(bool on) { recordMotions_ = on, emitted_.clear(); }
  /// The motions recorded since the last call, in time order.
  std::vector<PartMotion> takeMotions() { return std::exchange(motions_, {}); }

  /// A part's ride along one belt (moveTo): where it began, at what velocity,
  /// the whole microseconds ridden, the distance of travels run to their end.
  struct Ride {
    Eigen::Vector3d from = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero(), at = Eigen::Vector3d::Zero();
    vm::Micros micros = 0;
    double done = 0;
    bool operator==(const Ride&) const = default;
  };
  struct State {
    std::vector<std::uint32_t> number;  // per object; 0: not in the cell
    std::uint32_t nextNumber = 1;
    std::vector<bool> sensorOn;
    std::vector<std::uint64_t> sensorCount, carried, fed, taken;
    std::vector<std::size_t> ridden;         // per object: the conveyor it last rode + 1, 0: none
    std::vector<vm::Micros> nextDue;         // per EVERY feeder: when its next part is due
    std::vector<bool> waiting;               // per feeder: a part waits for its place
    std::vector<bool> whenLevel;             // per WHEN feeder: its signal as last seen
    vm::Micros planAt = 0;                   // the motion below starts here
    std::vector<Eigen::Vector3d> velocity;   // per object, while it rides
    std::vector<double> travel;              // per object: how far it rides (may be infinite)
    std::vector<Ride> rides;                 // per object
    std::uint64_t revision = 0;              // the world's, as the devices last left it
    std::uint64_t wakeTag = 0;               // the plan's wake (older ones are stale)
    vm::Micros planWakeAt = -1;              // the plan's wake waits for this time (-1: none), as
    std::uint64_t planWakeSeq = 0;           //   this event of the clock: a new plan cancels it
    std::vector<vm::Micros> moveUntil;       // per robot: its move under way ends here
    std::vector<vm::Micros> sightWakeAt;     // per robot: the wake for what it shows the sensors next (-1: none)
    std::vector<bool> heldWatched;           // per robot: its hand's part stands in riders' way or over their belt
    vm::Micros lookAt = -1;                  // an untagged wake waits for this instant (wakeNow)
    bool operator==(const State&) const = default;
  };
  const State& state() const { return state_; }
  void restore(const State& state);

 private:
  class Wire;
  // A running belt as the plan sees it (fixed: a conveyor's object is
  // where the cell placed it): a part rides it when present, not held,
  // its bottom on the belt's top and its centre over the belt.
  struct Geometry {
    Eigen::AlignedBox3d belt;
    Eigen::Vector3d dir, lateral;
    double end = 0;  // the belt's far end along dir
  };
  // A part riding a belt, with the parts piled on it (pile_[first, first +
  // count), itself first): the pile's extent along the belt (lead, length),
  // across it (lo, hi) and its top.
  struct Rider {
    std::size_t o, at;  // the part, its place in parts_
    double lead, length, lo, hi, final = 0, top = 0;
    std::size_t first = 0, count = 1;
  };
  // A plan, solved (solvePlan) for the words plan() keys it by: per part
  // present (parts_ order) how it rides; per conveyor, the parts that
  // begin to ride it; when, from the plan's instant, something may next
  // happen (a start, or the first microsecond after an end).
  struct Plan {
    struct Part {
      Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
      double travel = 0;
      std::size_t ridden = 0;
      bool stacked = false;  // it rides on another part, not on the belt
      bool watch = false;    // held: in riders' way or over their belt (its robot's moves' ends are looked at)
    };
    std::vector<Part> parts;
    std::vector<std::uint64_t> carried;
    // The first time from the plan's instant at which something begins
    // (startMicro), and the first at which something ends (afterMicro).
    std::optional<double> firstStart, firstAfter;
    void at(double tau, bool after) {
      std::optional<double>& first = after ? firstAfter : firstStart;
      if (!first || tau < *first) first = tau;
    }
  };
  /// Plans kept at most (all forgotten at once when full).
  static constexpr std::size_t kPlans = 4096;
  /// A part rests on a belt, or on a part, when its bottom is this near the
  /// top (a part let go 1 above the belt, as a gripper holding it 1 above
  /// its middle does, rides it).
  static constexpr double kRestTolerance = 1.0 + 1e-6;
  Plan solvePlan();
  /// Look at the cell now (an untagged wake), once for each instant.
  void wakeNow();
  /// The present parts (parts_) again, from the numbers (after a restore).
  void listParts();
  void plan(vm::Micros now);
  void moveTo(vm::Micros now);
  /// The parts whose centre passed an open end run off and settle (belt_run_off.cpp).
  void runOff(vm::Micros now);
  /// Appends to `pile` every part resting on one in it from `from` on
  /// (transitively), neither held nor takenScratch_ (which it marks).
  void gatherPile(std::vector<std::size_t>& pile, std::size_t from);
  /// Whether box `b` rests on belt `g` (its bottom within the tolerance of the top).
  static bool onBelt(const Eigen::AlignedBox3d& b, const Geometry& g);
  void feed(std::size_t f, vm::Micros now);
  bool signal(const workcell::Signal& s) const;
  /// The robot a signal's or a wire's label names (empty: the first), or
  /// null when it runs nothing.
  RobotIo* robotIo(const std::string& label) const;
  /// Whether that label names robot `robot`.
  bool names(const std::string& label, std::size_t robot) const;
  /// Object `o`'s box in the world where it rests (worked out again when
  /// it moved since).
  const Eigen::AlignedBox3d& worldBox(std::size_t o) const;
  /// A part's box in the world, as worldBox last worked it out: in a wake,
  /// every part's is brought up to date once, after the belts' motion.
  const Eigen::AlignedBox3d& partBox(std::size_t o) const { return boxOf_[o]; }
  void place(std::size_t o, const Eigen::Vector3d& shift);
  /// The next time moving robot `robot` changes what a sensor sees, woken then.
  void watchRobot(vm::Micros now, std::size_t robot);

  const workcell::Workcell& cell_;
  World& world_;
  std::vector<RobotIo*> robots_;  // per robot of the cell; null: runs nothing
  Scheduler& clock_;
  std::uint32_t id_ = 0;
  std::size_t firstSlot_ = 0;
  std::vector<std::size_t> slotStart_;           // per feeder: its first slot
  std::vector<std::size_t> slotCount_;
  std::vector<Eigen::AlignedBox3d> designBoxes_;  // per object, its lines' bounds
  // box(o) for the pose it was worked out at: a wake asks for a part's
  // box many times, and only riding parts move between wakes.
  mutable std::vector<Eigen::Isometry3d> boxPose_;
  mutable std::vector<Eigen::AlignedBox3d> boxOf_;
  std::vector<RobotIo*> runFrom_;  // per conveyor: the robot whose output its RUN names (else null)
  bool anyOpenEnd_ = false;        // some belt says END OPEN: parts may run off
  mutable std::vector<std::uint64_t> boxSeen_;  // per object: 1 + the world's revision when boxOf_ was last right (0: never)
  std::vector<std::optional<Geometry>> belts_;  // per conveyor: none when its object has no belt
  // The parts in the cell (present, kind Part), by index: what the
  // devices loop over (a feeder's 64 slots are parked while empty).
  std::vector<std::size_t> parts_;
  std::vector<bool> takenScratch_;  // plan's: a part rides one belt
  std::vector<Rider> riders_;
  std::vector<std::size_t> pile_;           // the riders' piles (Rider::first, count)
  std::vector<std::size_t> held_;           // plan's: the held parts present
  std::vector<Eigen::AlignedBox3d> heldBox_;  // per object: a held part's box where its hand has it now
  std::vector<std::int32_t> heldMotors_;    // scratch
  std::vector<std::pair<std::size_t, std::size_t>> runOff_;  // runOff's: (part, conveyor)
  base::ChainedMemo<Plan> plans_{kPlans};
  std::vector<std::uint64_t> planKey_;  // plan()'s scratch
  std::vector<std::unique_ptr<Wire>> wires_;
  State state_;
  std::vector<bool> nextSensor_;  // evaluate's sensor values, committed in update
  std::vector<std::unique_ptr<RobotSight>> sights_;  // per robot that runs (and can show a sensor anything)
  std::vector<bool> robotSees_;   // scratch: what a robot shows each sensor now
  std::vector<std::int32_t> motorsNow_;
  std::vector<DeviceEvent> events_;
  std::optional<std::string> fault_;
  void recordChangedMotions(vm::Micros now);
  bool recordMotions_ = false;
  bool emittedAny_ = false;  // the first instant records only the parts that left their placement
  std::vector<std::optional<PartMotion>> emitted_;  // per object: the last recorded, while it holds
  std::vector<PartMotion> motions_;
};

/// A signal as the description spells it: "ON", "left.OUT 1", "IN 2", "sensor eye".
std::string signalText(const workcell::Signal& s);

/// Where an empty slot waits: far below any floor.
Eigen::Isometry3d parkedPose();

}  // namespace rs::runtime
