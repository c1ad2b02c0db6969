// The cell's one virtual clock and its event queue: a discrete-event
// kernel. Everything in a cell that acts at a time (a robot's move or
// delay ending, a stimulus, a device's edge) is an event ordered by (time,
// sequence number); the sequence number is given when the model schedules
// the event, never by the container, so the same cell gives the same order
// on every machine. Events due at one instant run in delta cycles, as
// SystemC's and VHDL's kernels do: the evaluate phase wakes every process
// whose event is due (in sequence order), then the update phase lets each
// process woken commit what it wrote (in the model's order; one not woken
// wrote nothing, as SystemC updates only the channels that asked); what
// the update scheduled at the same instant runs in the next delta. A process that reads during evaluation
// sees only what earlier deltas committed, so the order processes are
// visited in one delta does not change what any of them reads.
//
//   Scheduler clock;
//   clock.add(robot);                    // processes, in the model's order
//   clock.schedule(2'000'000, 0, kWake); // robot 0 wakes at 2 s
//   clock.advanceTo(5'000'000);          // runs it, then the clock reads 5 s
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "vm/machine.h"

namespace rs::runtime {

/// One thing that happens at a time: process `process` is woken with `tag`
/// (what the process makes of it is its own).
struct CellEvent {
  vm::Micros at = 0;
  std::uint64_t seq = 0;  ///< order of scheduling, for events at the same time
  std::uint32_t process = 0;
  std::uint32_t tag = 0;
  bool operator<(const CellEvent& o) const { return at != o.at ? at < o.at : seq < o.seq; }
  bool operator==(const CellEvent&) const = default;
};

class Scheduler;

/// Something in the cell that acts when woken: a robot, a device.
class CellProcess {
 public:
  virtual ~CellProcess() = default;
  /// Evaluate: the event is due. Reads see what earlier deltas committed.
  virtual void wake(const CellEvent& event, Scheduler& clock) = 0;
  /// Update, after a delta in which it was woken: commit what wake wrote
  /// (a signal's new value) and schedule whoever it concerns; true when
  /// something changed.
  virtual bool update(Scheduler& /*clock*/) { return false; }
  /// How an error names it ("wire eye TO IN 1").
  virtual std::string name() const = 0;
};

/// Delta cycles one instant may take; one more is an error naming the
/// processes woken in the last (a loop of zero-delay wires or rules).
inline constexpr std::uint64_t kMaxDeltas = 10'000;
/// Events that may wait at once; one more is refused.
inline constexpr std::size_t kMaxCellEvents = 1'000'000;

class Scheduler {
 public:
  vm::Micros now() const { return state_.now; }

  /// Adds a process (the model's order: its index is its number). The
  /// process must outlive the scheduler, or be removed by clearing it.
  std::uint32_t add(CellProcess& process);

  /// Process `process` wakes with `tag` at `at` (not before now: an event
  /// for now runs in the next delta of this instant). False (nothing
  /// added) when kMaxCellEvents wait or `at` is in the past.
  bool schedule(vm::Micros at, std::uint32_t process, std::uint32_t tag = 0);
  /// The sequence number the latest schedule() gave (meaningful after one succeeded).
  std::uint64_t lastSeq() const { return state_.nextSeq - 1; }
  /// The event scheduled at `at` with sequence number `seq` will not
  /// happen (a process's plan that a later plan replaced); false when it
  /// is not waiting (it ran, or was never scheduled).
  bool cancel(vm::Micros at, std::uint64_t seq);

  /// The time of the next event, or nullopt when none waits.
  std::optional<vm::Micros> nextTime() const;
  bool idle() const { return state_.queue.empty(); }

  /// Runs every event due by `t`, instant by instant and delta by delta,
  /// and leaves the clock at `t` (never earlier than now). Fault: an
  /// instant that takes more than kMaxDeltas deltas (the clock stays there).
  vm::Status advanceTo(vm::Micros t);

  /// Deltas the latest instant with events took (1 for a plain instant).
  std::uint64_t lastDeltas() const { return lastDeltas_; }

  /// Everything that changes: the clock, the queue, the next number.
  struct State {
    vm::Micros now = 0;
    std::uint64_t nextSeq = 0;
    std::set<CellEvent> queue;
    bool operator==(const State&) const = default;
  };
  const State& state() const { return state_; }
  void restore(const State& state) { state_ = state; }
  /// Sets the clock alone (a machine put back to its own snapshot).
  void restoreNow(vm::Micros now) { state_.now = now; }

 private:
  vm::Status runInstant(vm::Micros at);
  std::vector<std::uint32_t> woken_;  // runInstant's: the processes woken in the latest delta
  std::vector<std::uint32_t> toUpdate_;  // runInstant's: those to update after it, once each
  std::vector<char> wokenNow_;           // per process: in toUpdate_

  std::vector<CellProcess*> processes_;
  State state_;
  std::uint64_t lastDeltas_ = 0;
};

}  // namespace rs::runtime
