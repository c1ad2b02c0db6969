// What a test's expectations need from its run, gathered while it runs, so
// that `robotsim test` keeps no log of the run's steps (a RunLog keeps
// 35 to 47 bytes an instruction: a long loop under `robotsim test` reached
// 3.55 GB). For each expectation about a moment (`output 3 on at 2`), a
// window (`during 2..5`), an order (`input 2 on before output 3 on`), a
// count of pulses or a motor's bound, the watch keeps its answer and the
// few values still to be settled: its memory grows with the expectations,
// never with the run.
//
// The answers are the ones runtime::stateAt and runtime::variableAt give on
// a whole RunLog (tests/testrun/test_run_watch.cpp compares both on random
// runs):
// - an output's (or a variable's) value at t is the one after the last step
//   that started at or before t; an input's, after every change due at t;
// - what set it: the last output change (variable write) whose step ended
//   at or before t; for an input, the line of the last step that started at
//   or before t ("line 9 running"), and the input's last change due at or
//   before t with its cause (a stimulus, a rule, a wire: Rig::lastInputChange);
// - a window A..B is checked at A and at every change inside it, in order;
// - inputs are seen as the log keeps them: several changes at one time are
//   one level, the last.
#pragma once

#include <cstdint>
#include <optional>
#include <queue>
#include <vector>

#include "runtime/run/run.h"
#include "tools/testrun/expectation.h"
#include "vm/io_lines.h"

namespace rs::testrun {

/// A line's or variable's value at one moment, and the source line that
/// set it (an output or variable) or was running then (an input).
struct WatchedMoment {
  vm::Micros at = 0;
  std::int32_t value = 0;  ///< 0 or 1 for a line
  std::optional<std::uint32_t> line;
  /// An input's: the change that made it `value` (none: as it started).
  std::optional<runtime::InputChangeRecord> change = {};
};

/// The first move of a motor past its bound.
struct WatchedMove {
  std::int32_t to = 0;
  std::uint32_t line = 0;
  vm::Micros start = 0, end = 0;
};

/// What the run said about one expectation.
struct WatchAnswer {
  /// `at T`: the value then. `during A..B`: the first moment it was not as
  /// expected (none: it held).
  std::optional<WatchedMoment> moment;
  /// Order: when each event first happened.
  std::optional<vm::Micros> first, second;
  /// Pulses: how many times the output turned ON.
  std::uint32_t pulses = 0;
  /// MotorBound: the first move past the bound.
  std::optional<WatchedMove> beyond;
};

class RunWatch final : public vm::StepObserver {
 public:
  /// Watches `run` (not yet started, on the simulated machine) for
  /// `expectations`; both must outlive the watch. It registers itself for
  /// the machine's input changes; pass it to the run's observe() too.
  RunWatch(runtime::Run& run, const std::vector<Expectation>& expectations);
  RunWatch(const RunWatch&) = delete;
  RunWatch& operator=(const RunWatch&) = delete;

  /// Whether any of the expectations needs a watch (else the end of the run
  /// answers them all).
  static bool needed(const std::vector<Expectation>& expectations);

  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  /// After the run: the instruction that stopped it early counts as a step
  /// (as in a RunLog), and every answer still open is settled.
  void finish(const vm::RunOutcome& outcome);

  /// The answer for expectations[i] (empty for one that needs no watch).
  const WatchAnswer& answer(std::size_t i) const { return answers_[i]; }

 private:
  // One expectation being watched.
  struct Watcher {
    std::size_t expectation = 0;
    std::uint32_t slot = 0;        // Variable: the variable's slot
    bool window = false;           // during A..B
    bool failed = false;           // a window already found wrong
    bool was[2] = {false, false};  // Order, Pulses: each event's line was in its state
    vm::Micros queued = -1;        // the last moment queued for it
  };
  // A moment whose answer waits for the clock to pass it.
  enum class ProbeKind : std::uint8_t { Output, InputCause, Variable, Input };
  struct Probe {
    vm::Micros at = 0;
    std::uint64_t order = 0;  // ties resolve in the order queued
    std::uint32_t watcher = 0;
    ProbeKind kind = ProbeKind::Output;
    bool operator>(const Probe& o) const { return at != o.at ? at > o.at : order > o.order; }
  };
  using ProbeQueue = std::priority_queue<Probe, std::vector<Probe>, std::greater<Probe>>;
  // A change of outputs or a write of a variable: by which line, when its step ended.
  struct Setter {
    std::int32_t value = 0;
    std::uint32_t line = 0;
    vm::Micros end = 0;
  };
  struct SlotHistory {
    std::optional<Setter> last, before;
  };

  void step(std::uint32_t index, const vm::Interpreter* vm);
  void inputChanged(vm::Micros at, vm::IoMask mask);
  void finishLevel();
  void level(vm::Micros at, vm::IoMask mask);
  void queue(ProbeQueue& q, std::uint32_t watcher, vm::Micros at, ProbeKind kind);
  void settleInputs(vm::Micros before);
  void settleSteps(vm::Micros before);
  void settle(const Probe& p);
  void outputChanged(vm::IoMask outputs, std::uint32_t line, vm::Micros end);
  void variableWritten(std::uint32_t slot, std::int32_t value, std::uint32_t line, vm::Micros end);
  void moved(std::size_t motor, const runtime::MotorSegment& s, std::uint32_t line);
  void windowFailed(Watcher& w, WatchedMoment m);
  /// Input `input` at `at` in the level `mask`, with the change that made it so.
  WatchedMoment inputMoment(vm::Micros at, vm::IoMask mask, int input) const;
  static std::optional<Setter> setterAt(const SlotHistory& h, vm::Micros t);
  const Expectation& of(const Watcher& w) const { return expectations_[w.expectation]; }

  const runtime::Run& run_;
  const std::vector<Expectation>& expectations_;
  std::vector<WatchAnswer> answers_;
  std::vector<Watcher> watchers_;
  std::vector<std::uint32_t> onOutputs_, onInputLevels_, onVariables_;  // watchers by what they follow
  std::vector<std::vector<std::uint32_t>> boundsOf_;                    // per motor: MotorBound watchers
  ProbeQueue stepProbes_, inputProbes_;
  std::uint64_t probesQueued_ = 0;

  // The run so far, as of the last step seen.
  vm::Micros lastNow_ = 0;
  std::optional<std::uint32_t> lastLine_;  // of the last step
  vm::IoMask outputs_ = 0;
  SlotHistory outputChanges_;           // values unused: the mask is outputs_
  std::vector<SlotHistory> variables_;  // per slot, when any variable is watched
  std::vector<runtime::MotorSegment> segments_;
  std::vector<std::int32_t> positions_;
  // Inputs: the mask now, the level at `pendingAt` that later changes at the
  // same time may still change (or undo), and the last settled level.
  vm::IoMask inputs_ = 0;
  bool pending_ = true;
  vm::Micros pendingAt_ = 0;
  vm::IoMask pendingMask_ = 0;
  std::optional<vm::IoMask> settledMask_;
};

}  // namespace rs::testrun
