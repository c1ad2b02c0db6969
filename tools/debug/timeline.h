// Time travel for one run: the run goes forwards as usual, and the
// timeline keeps a snapshot of its whole state every K instructions or W
// knots of straight lines (vm::Machine::knots), whichever comes first: a
// line is one instruction and may be thousands of knots, each a move the
// machine makes and the world answers. Going to an earlier moment restores
// the nearest snapshot at or before it and runs forward again,
// deterministically, to the exact instruction: a reverse step costs one
// restore and at most K instructions or W knots (and the instruction that
// passes them).
//
// The world can be changed from the present on (`setInput`, a debugger's
// `set input`; `setVariable`): the change is kept with the instruction count it was made
// at and applied again whenever execution reaches that count (a moment
// the timeline stops at always has its changes made), so that going back
// and forth replays the changed stimuli. A change forgets the changes
// made later in the run's history (that future no longer exists) and the
// snapshots taken after it.
//
// Snapshots cost memory: past a budget, K and W double and every other
// snapshot is dropped, so a run of any length stays within it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "runtime/run/run.h"

namespace rs::debug {

/// Instructions between snapshots, and knots of straight lines; chosen in
/// bench/ (docs/performance.md).
inline constexpr std::uint64_t kDefaultSnapshotInterval = 4096;
inline constexpr std::uint64_t kDefaultSnapshotKnots = 4096;
/// The memory snapshots may take before the interval doubles.
inline constexpr std::size_t kDefaultSnapshotBudget = std::size_t{64} << 20;

/// A change made by hand after `steps` instructions: an input turned on
/// or off (`set input`), or a variable given a value (`set VAR = VALUE`,
/// the debug adapter's setVariable).
struct Edit {
  enum class Kind : std::uint8_t { Input, Variable };
  std::uint64_t steps = 0;
  Kind kind = Kind::Input;
  int input = 1;  ///< Input: the line, turned `on` or off
  bool on = true;
  std::uint32_t slot = 0;  ///< Variable: its slot, given `value`
  std::int32_t value = 0;
};

/// The bytes a snapshot holds (its vectors and sets included), roughly.
std::size_t snapshotBytes(const runtime::RunSnapshot& s);

class Timeline {
 public:
  /// `run` must be simulated (run.rig().canSnapshot()) and outlive the timeline;
  /// it is taken where it stands (normally at its start).
  explicit Timeline(runtime::Run& run, std::uint64_t interval = kDefaultSnapshotInterval,
                    std::size_t budget = kDefaultSnapshotBudget, std::uint64_t knotInterval = kDefaultSnapshotKnots);

  /// Runs forward under `until` (its step count included), keeping
  /// snapshots and applying the input edits on the way. `interrupted` is
  /// asked between slices of at most K instructions or W knots (and the
  /// instruction that passes them); when it says yes the call returns
  /// paused with `wasInterrupted()` set.
  vm::RunOutcome forward(const runtime::RunUntil& until, const std::function<bool()>& interrupted = {});
  bool wasInterrupted() const { return interrupted_; }

  /// To the moment after exactly `steps` instructions (or the end, if the
  /// run ends before).
  void goToStep(std::uint64_t steps);
  /// To the moment a fresh run paused by Run::runUntil({.time = t}) would be at:
  /// right after the instruction that takes the clock past t (or the end).
  void goToTime(vm::Micros t);

  /// The latest moment s, before the present, at which `matches` says yes;
  /// `reset` is called at the start of every stretch re-run (with the run
  /// at the stretch's first moment, before `matches` hears of the moments
  /// after it). Leaves the run where it was. nullopt when no moment after
  /// the start matches.
  std::optional<std::uint64_t> lastMatch(const std::function<void(const runtime::Run&)>& reset,
                                         const std::function<bool(const runtime::Run&)>& matches);

  /// Input `input` turns `on` from now on; false on a finished run or a
  /// bad input.
  bool setInput(int input, bool on);
  /// Variable `slot` holds `value` from now on; false on a finished run or
  /// a slot the program lacks.
  bool setVariable(std::uint32_t slot, std::int32_t value);
  const std::vector<Edit>& edits() const { return edits_; }

  std::uint64_t interval() const { return interval_; }
  std::uint64_t knotInterval() const { return knotInterval_; }
  std::size_t snapshotCount() const { return snapshots_.size(); }
  std::size_t snapshotMemory() const { return bytes_; }

 private:
  struct Stored {
    runtime::RunSnapshot snapshot;
    std::size_t editsApplied = 0;
    vm::Micros clock = 0;
    std::uint64_t knots = 0;
    std::size_t bytes = 0;
  };
  // Where forward() must stop by itself next: a snapshot to keep (K
  // instructions or W knots after the latest), one kept already, an edit.
  struct Boundary {
    std::uint64_t steps = UINT64_MAX;     // the first of these
    std::uint64_t snapshot = UINT64_MAX;  // K instructions on
    std::uint64_t knots = UINT64_MAX;     // W knots on
  };
  void keep();
  void thin();
  void restoreAtOrBefore(std::uint64_t steps);
  void applyDueEdits();
  /// Makes `edit` now, forgetting the future after it; false if it cannot be made.
  bool record(const Edit& edit);
  Boundary nextBoundary() const;

  runtime::Run& run_;
  std::uint64_t interval_;
  std::size_t budget_;
  std::uint64_t knotInterval_;
  std::map<std::uint64_t, Stored> snapshots_;
  std::size_t bytes_ = 0;
  std::vector<Edit> edits_;
  std::size_t editsApplied_ = 0;  // edits_ before this index are in the run's state
  bool interrupted_ = false;
};

}  // namespace rs::debug
