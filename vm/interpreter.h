// The interpreter: runs a verified image against a Machine. Variables live
// in slots, the call stack is bounded, and every way a run can stop (END,
// a runtime error, a deadlock, the step or time limit) is an outcome value.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vm/image.h"
#include "vm/machine.h"

namespace rs::vm {

struct RunLimits {
  std::uint64_t maxSteps = 100'000'000;        // instructions executed
  Micros maxTime = Micros{3600} * 1'000'000;   // simulated time
};

enum class StopReason : std::uint8_t {
  End,          // END, or ran past the last instruction
  RuntimeError, // bad value, call stack overflow, machine fault
  Deadlock,     // WAITFOR that nothing will satisfy
  StepLimit,
  TimeLimit,
};

struct RunOutcome {
  StopReason reason = StopReason::End;
  std::string message;     // empty for End
  std::uint32_t index = 0; // 0-based instruction that stopped the run
  std::uint64_t steps = 0; // instructions executed
  bool ok() const { return reason == StopReason::End; }
};

class Interpreter;

/// Called after every executed instruction when set (tracing, recording,
/// later a step debugger). One check per instruction when unset.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  virtual void afterStep(const Interpreter& vm, std::uint32_t index) = 0;
};

class Interpreter {
 public:
  /// `image` must have passed verify(); both must outlive the interpreter.
  Interpreter(const Image& image, Machine& machine);

  RunOutcome run(const RunLimits& limits, StepObserver* observer = nullptr);

  const Image& image() const { return image_; }
  Machine& machine() const { return machine_; }
  std::span<const std::int32_t> variables() const { return vars_; }
  std::size_t callDepth() const { return callStack_.size(); }

 private:
  Status move(const Instr& in);
  Status moveTo(std::span<const std::int32_t> targets);
  std::string rangeError(std::span<const std::int32_t> targets) const;

  const Image& image_;
  Machine& machine_;
  std::vector<std::int32_t> vars_;
  std::vector<std::uint32_t> callStack_;
  std::vector<std::int32_t> softHome_;
  std::vector<std::int32_t> target_;  // scratch, sized once
};

/// Seconds with millisecond digits, e.g. "12.345" (for messages and traces).
std::string formatSeconds(Micros t);

}  // namespace rs::vm
