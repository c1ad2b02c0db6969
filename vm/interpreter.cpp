#include "vm/interpreter.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "base/seconds.h"
#include "vm/motor_range.h"

namespace rs::vm {

namespace {

// The opcodes whose flags include `flag`, as one bit each: a test of a
// flag becomes a shift and a test, with no load from the table.
consteval std::uint32_t opsWith(std::uint16_t flag) {
  std::uint32_t bits = 0;
  for (const OpInfo& op : kOps)
    if (op.flags & flag) bits |= std::uint32_t{1} << static_cast<unsigned>(op.op);
  return bits;
}
static_assert(kOpCount <= 32, "opsWith keeps a bit per opcode");
constexpr bool oneOf(std::uint32_t ops, Op op) { return ((ops >> static_cast<unsigned>(op)) & 1) != 0; }

// The opcodes the dispatch loop hands to machineStep: those the opcode
// table marks as acting on the machine, so a new opcode's flags decide
// where the loop runs it; of those, the ones machineCall hands to move().
constexpr std::uint32_t kMachineOps = opsWith(kUsesMachine);
constexpr std::uint32_t kMotorOps = opsWith(kMovesMotors);

// JMPVAR's comparison without a branch per kind: the sign of value - with
// (-1, 0, 1) against the sign each comparison wants, in operand-a order
// (Compare: Less, Greater, Equal). The verifier allows only these three.
constexpr std::int8_t kWantedSign[4] = {-1, 1, 0, 2};
static_assert(static_cast<int>(Compare::Less) == 0 && static_cast<int>(Compare::Greater) == 1 &&
              static_cast<int>(Compare::Equal) == 2);

bool compare(std::int32_t value, std::uint8_t cmp, std::int32_t with) {
  const int sign = (value > with) - (value < with);
  return sign == kWantedSign[cmp & 3];
}

// What ADD and JMPVAR do, written once for both loops below. ADD: false
// (and nothing changed) when the sum overflows 32 bits.
bool addInto(std::int32_t* vars, const Instr& in) {
  std::int32_t sum;
  if (__builtin_add_overflow(vars[in.b], in.c, &sum)) [[unlikely]]
    return false;
  vars[in.b] = sum;
  return true;
}
bool jmpvarTaken(const std::int32_t* vars, const Instr& in) { return compare(vars[in.b], in.a, in.c); }

struct Cursor {
  std::uint32_t pc;
  std::uint64_t steps;
};

// The opcodes computeRun's switch runs; the table must agree that none of
// them acts on the machine (a flag added to one later fails here).
constexpr Op kComputeOps[] = {Op::Set, Op::Add, Op::JmpVar, Op::Goto};
consteval bool computeOpsAgree() {
  for (const Op op : kComputeOps)
    if (has(op, kUsesMachine)) return false;
  return true;
}
static_assert(computeOpsAgree(), "computeRun runs only opcodes that do not act on the machine");

// The instructions that only compute (SET, ADD, JMPVAR, GOTO), in a loop
// of their own that calls nothing, so that its state stays in registers
// and its switch of four cases compiles to a few compares: from `pc` until
// the end of the code, the step count `check`, or an instruction it leaves
// to the main loop (any other, and an ADD that overflows), which the main
// loop then runs. A counted loop runs here from start to end: 52
// instructions of the processor an iteration of the benchmark's loop
// instead of 61, and the same time wherever the linker puts the code
// (docs/performance.md).
[[gnu::noinline]] Cursor computeRun(const Instr* code, std::uint32_t size, std::int32_t* vars, std::uint32_t pc,
                                    std::uint64_t steps, std::uint64_t check) {
  while (pc < size && steps < check) {
    const Instr& in = code[pc];
    switch (in.op) {
      case Op::Set:
        vars[in.b] = in.c;
        ++pc;
        break;
      case Op::Add:
        if (!addInto(vars, in)) return {pc, steps};
        ++pc;
        break;
      case Op::JmpVar:
        pc = jmpvarTaken(vars, in) ? static_cast<std::uint32_t>(in.d) : pc + 1;
        break;
      case Op::Goto:
        pc = static_cast<std::uint32_t>(in.d);
        break;
      default:
        return {pc, steps};
    }
    ++steps;
  }
  return {pc, steps};
}

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

// Instructions in a row the clock may stand still: none means no limit.
std::uint64_t stillLimitOf(const RunLimits& limits) {
  return limits.maxStepsPerInstant ? limits.maxStepsPerInstant : UINT64_MAX;
}

// The step count at which the loop must look up from its work: the
// nearest of the step limit, a step pause and the still-clock limit.
std::uint64_t nextCheck(const RunLimits& limits, const PausePoints& pause, std::uint64_t stillSince) {
  return std::min({limits.maxSteps, pause.atSteps, saturatingAdd(stillSince, stillLimitOf(limits))});
}

}  // namespace

Interpreter::Interpreter(const Image& image, Machine& machine)
    : image_(image), machine_(machine), target_(image.motors.size(), 0) {
  state_.variables.assign(image.variables.size(), 0);
  state_.softHome.assign(image.motors.size(), 0);
  state_.callStack.reserve(image.callDepthLimit);
  state_.clockSeen = machine.now();
}

// Defence in depth behind the Machine contract (targets already in range):
// the same check and words as SimMachine's own.
Status Interpreter::moveTo(std::span<const std::int32_t> targets) {
  if (const auto i = firstOutOfRange(image_.motors, targets))
    return Status::fault(targetOutsideRange(image_.motors[*i], targets[*i]));
  return machine_.moveTo(targets);
}

Status Interpreter::move(const Instr& in) {
  if (has(in.op, kRelative)) {
    const std::span<const std::int32_t> now = machine_.positions();
    for (std::size_t i = 0; i < target_.size(); ++i) {
      const std::int64_t t = std::int64_t{now[i]} + image_.constants[static_cast<std::size_t>(in.c) + i];
      const MotorSpec& m = image_.motors[i];
      if (!inRange(m, t))
        return Status::fault(
            fmt::format("{} takes motor {} to {}, {}", info(in.op).name, m.letter, t, outsideRange(m)));
      target_[i] = static_cast<std::int32_t>(t);
    }
    return machine_.moveTo(target_);
  }
  switch (in.op) {
    case Op::MoveTo: return moveTo({image_.constants.data() + in.c, target_.size()});
    case Op::MoveP: {
      const std::vector<std::int32_t>& values = image_.points[in.b].values;
      if (!(in.a & kPointKeepsGripper)) return moveTo(values);
      // The gripper stays as it is when the move starts; the arm goes to the point.
      const std::span<const std::int32_t> now = machine_.positions();
      for (std::size_t i = 0; i < target_.size(); ++i)
        target_[i] = image_.motors[i].kind == JointKind::Gripper ? now[i] : values[i];
      return moveTo(target_);
    }
    case Op::HrdHome: return machine_.hardHome();
    case Op::GoSoft: return moveTo(state_.softHome);
    case Op::Reset: return machine_.reset();
    case Op::MoveS: {
      const std::span<const std::int32_t> targets = image_.points[in.b].values;
      if (const auto i = firstOutOfRange(image_.motors, targets))
        return Status::fault(targetOutsideRange(image_.motors[*i], targets[*i]));
      return machine_.moveLine(targets);
    }
    case Op::Appro: return machine_.moveAlongTool(in.c);
    case Op::Depart: return machine_.moveAlongTool(-in.c);
    default: return Status::fault("not a motion instruction");
  }
}

// What an instruction that acts on the machine asks of it: a move (the
// table's kMovesMotors) or one of the calls below.
Status Interpreter::machineCall(const Instr& in) {
  if (oneOf(kMotorOps, in.op)) return move(in);
  const std::int32_t* const k = image_.constants.data();
  switch (in.op) {
    case Op::OutSig: return machine_.setOutput(in.a, in.b != 0);
    case Op::WaitFor: return machine_.waitFor(in.a, in.b != 0);
    case Op::Delay: return machine_.delay(Micros{in.c} * 1000);
    case Op::Window: machine_.window(k[in.c], k[in.c + 1], k[in.c + 2]); return Status::ok();
    case Op::View: machine_.view(k[in.c], k[in.c + 1], k[in.c + 2]); return Status::ok();
    default: return Status::fault(fmt::format("{} does not act on the machine", info(in.op).name));
  }
}

RunOutcome Interpreter::finish(StopReason reason, std::string message, std::uint32_t index) {
  state_.finished = true;
  state_.outcome = {reason, std::move(message), index, state_.steps};
  return state_.outcome;
}

Interpreter::AfterCall Interpreter::machineStep(const Instr& in, std::uint32_t at, std::uint32_t next,
                                                std::uint64_t steps, const RunLimits& limits,
                                                const PausePoints& pause, std::uint64_t& check) {
  InterpreterState& st = state_;
  Status status = st.waiting ? (st.waiting = false, machine_.resume()) : machineCall(in);
  if (status.notYet()) {
    // Not counted yet: the step is done when the wait is (the next run resumes it).
    st.pc = at, st.steps = steps - 1, st.waiting = true;
    st.outcome = RunOutcome{StopReason::Paused, {}, at, steps - 1, true, status.until};
    return AfterCall::Waiting;
  }
  const auto stop = [&](StopReason reason, std::string message) {
    st.pc = next, st.steps = steps;
    finish(reason, std::move(message), at);
    return AfterCall::Stopped;
  };
  if (!status)
    return stop(status.code == Status::Code::Deadlock ? StopReason::Deadlock : StopReason::RuntimeError,
                std::move(status.message));
  const Micros now = machine_.now();
  if (now > limits.maxTime)
    return stop(StopReason::TimeLimit, fmt::format("simulated time limit of {} s passed (clock at {} s)",
                                                   base::formatSeconds(limits.maxTime), base::formatSeconds(now)));
  const std::uint64_t knots = machine_.knots();
  if (knots > limits.maxKnots)
    return stop(StopReason::KnotLimit,
                fmt::format("knot limit of {} straight-line moves passed ({} made)", limits.maxKnots, knots));
  if (now != st.clockSeen) {
    st.clockSeen = now, st.stillSince = steps;
    check = nextCheck(limits, pause, st.stillSince);
  }
  return now > pause.afterTime || knots >= pause.atKnots ? AfterCall::Pause : AfterCall::Next;
}

// The dispatch loop: one switch over the opcode, each case a few lines.
// Everything an operand could get wrong was ruled out by the verifier.
// Per instruction it checks one step count (the nearest of the step limit,
// a step pause and the still-clock limit) and, when set, the observer and
// the breakpoints: with them (kWatched) every instruction goes through
// here, the one hook at instruction fetch. Without them, the instructions
// that only compute run in computeRun first. The clock is looked at only
// after a machine call, in machineStep, so that nothing here builds a
// Status or a string (docs/performance.md).
RunOutcome Interpreter::run(const RunLimits& limits, StepObserver* observer, const PausePoints& pause) {
  if (state_.finished) return state_.outcome;
  if (observer || pause.before.size() == image_.code.size()) return loop<true>(limits, observer, pause);
  return loop<false>(limits, nullptr, pause);
}

template <bool kWatched>
RunOutcome Interpreter::loop(const RunLimits& limits, StepObserver* observer, const PausePoints& pause) {
  InterpreterState& st = state_;
  const Instr* const code = image_.code.data();
  const std::uint32_t size = static_cast<std::uint32_t>(image_.code.size());
  const std::int32_t* const k = image_.constants.data();
  std::int32_t* const vars = st.variables.data();
  const std::uint8_t* const before = pause.before.size() == size ? pause.before.data() : nullptr;
  std::uint64_t check = nextCheck(limits, pause, st.stillSince);
  std::uint64_t steps = st.steps;
  std::uint32_t pc = st.pc;
  // The instruction the run ends on: END, or the last one when it runs past it.
  std::uint32_t endIndex = size == 0 ? 0 : size - 1;

  while (pc < size) {
    if constexpr (!kWatched) {
      const Cursor done = computeRun(code, size, vars, pc, steps, check);
      pc = done.pc, steps = done.steps;
      if (pc >= size) break;
    }
    if (steps >= check) [[unlikely]]
      return checkpoint(limits, pc, steps);
    const std::uint32_t at = pc;
    const Instr& in = code[pc++];
    ++steps;
    [[maybe_unused]] bool pauseNow = false;
    switch (in.op) {
      case Op::Set:
        vars[in.b] = in.c;
        break;
      case Op::Add:
        if (!addInto(vars, in))
          return stopAt(StopReason::RuntimeError,
                        fmt::format("ADD overflows variable {} (values are 32-bit)", image_.variables[in.b]), at, pc,
                        steps);
        break;
      case Op::JmpVar:
        if (jmpvarTaken(vars, in)) pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Goto:
        pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Gosub:
        if (st.callStack.size() == image_.callDepthLimit) [[unlikely]]
          return stopAt(StopReason::RuntimeError,
                        fmt::format("call stack overflow: more than {} nested GOSUBs", image_.callDepthLimit), at, pc,
                        steps);
        st.callStack.push_back(pc);
        pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Return:
        if (st.callStack.empty()) [[unlikely]]
          return stopAt(StopReason::RuntimeError, "RETURN without a GOSUB", at, pc, steps);
        pc = st.callStack.back();
        st.callStack.pop_back();
        break;
      case Op::JmpIn:
        if (machine_.input(in.a) == (in.b != 0)) pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::SetSoft:
        for (std::size_t i = 0; i < st.softHome.size(); ++i) st.softHome[i] = k[static_cast<std::size_t>(in.c) + i];
        break;
      case Op::End:
        pc = size;
        endIndex = at;
        break;
      // Every other opcode acts on the machine (kMachineOps, from the
      // table): the call, its failure, the clock and the limits on it, out
      // of line. One the table leaves off the machine has no case here: a
      // runtime error that names it.
      default:
        if (!oneOf(kMachineOps, in.op)) [[unlikely]]
          return stopAt(StopReason::RuntimeError, fmt::format("{} has no case in the interpreter", info(in.op).name),
                        at, pc, steps);
        switch (machineStep(in, at, pc, steps, limits, pause, check)) {
          case AfterCall::Next: break;
          case AfterCall::Stopped: return st.outcome;
          case AfterCall::Waiting: return std::exchange(st.outcome, {});
          case AfterCall::Pause:
            if constexpr (!kWatched) return pauseAt(pc, steps);
            pauseNow = true;
            break;
        }
        break;
    }
    if constexpr (kWatched) {
      if (observer) {
        st.pc = pc, st.steps = steps;  // what the observer sees
        pauseNow |= observer->afterStep(*this, at);
      }
      if (pauseNow || (before && pc < size && before[pc])) return pauseAt(pc, steps);
    }
  }
  return stopAt(StopReason::End, {}, endIndex, pc, steps);
}

RunOutcome Interpreter::pauseAt(std::uint32_t next, std::uint64_t steps) {
  state_.pc = next, state_.steps = steps;
  return RunOutcome{StopReason::Paused, {}, next, steps};
}

RunOutcome Interpreter::stopAt(StopReason reason, std::string message, std::uint32_t index, std::uint32_t next,
                               std::uint64_t steps) {
  state_.pc = next, state_.steps = steps;
  return finish(reason, std::move(message), index);
}

// The step count the loop checks was reached: a limit ends the run, else
// it is a step pause.
RunOutcome Interpreter::checkpoint(const RunLimits& limits, std::uint32_t pc, std::uint64_t steps) {
  if (steps >= limits.maxSteps)
    return stopAt(StopReason::StepLimit, fmt::format("step limit of {} instructions reached", limits.maxSteps), pc, pc,
                  steps);
  const std::uint64_t stillLimit = stillLimitOf(limits);
  if (steps - state_.stillSince >= stillLimit) {
    std::string message = fmt::format("{} instructions ran at {} s without the simulated clock moving", stillLimit,
                                      base::formatSeconds(state_.clockSeen));
    if (std::string why = machine_.stillReason(); !why.empty()) message += "; " + why;
    return stopAt(StopReason::InstantLimit, std::move(message), pc, pc, steps);
  }
  return pauseAt(pc, steps);
}

}  // namespace rs::vm
