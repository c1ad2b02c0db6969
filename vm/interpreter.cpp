#include "vm/interpreter.h"

#include <fmt/format.h>

#include <algorithm>

namespace rs::vm {

namespace {

// Whether an opcode acts on the machine, read from the opcode table at
// compile time, so the dispatch loop pays nothing for asking.
template <Op op>
inline constexpr bool kMachineCall = has(op, kUsesMachine);

bool compare(std::int32_t value, std::uint8_t cmp, std::int32_t with) {
  switch (static_cast<Compare>(cmp)) {
    case Compare::Less: return value < with;
    case Compare::Greater: return value > with;
    case Compare::Equal: return value == with;
  }
  return false;
}

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }

}  // namespace

Interpreter::Interpreter(const Image& image, Machine& machine)
    : image_(image), machine_(machine), target_(image.motors.size(), 0) {
  state_.variables.assign(image.variables.size(), 0);
  state_.softHome.assign(image.motors.size(), 0);
  state_.callStack.reserve(image.callDepthLimit);
  state_.clockSeen = machine.now();
}

std::string formatSeconds(Micros t) {
  const char* sign = t < 0 ? "-" : "";
  const std::uint64_t u = t < 0 ? 0 - static_cast<std::uint64_t>(t) : static_cast<std::uint64_t>(t);
  // Round to the nearest millisecond, halves up: same digits on every machine.
  const std::uint64_t ms = (u + 500) / 1000;
  return fmt::format("{}{}.{:03}", sign, ms / 1000, ms % 1000);
}

// Defence in depth behind the Machine contract (targets already in range):
// the same words as SimMachine's own check.
Status Interpreter::moveTo(std::span<const std::int32_t> targets) {
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const MotorSpec& m = image_.motors[i];
    if (targets[i] < m.min || targets[i] > m.max)
      return Status::fault(
          fmt::format("motor {} target {} is outside its range {}..{}", m.letter, targets[i], m.min, m.max));
  }
  return machine_.moveTo(targets);
}

Status Interpreter::move(const Instr& in) {
  if (has(in.op, kRelative)) {
    const std::span<const std::int32_t> now = machine_.positions();
    for (std::size_t i = 0; i < target_.size(); ++i) {
      const std::int64_t t = std::int64_t{now[i]} + image_.constants[static_cast<std::size_t>(in.c) + i];
      const MotorSpec& m = image_.motors[i];
      if (t < m.min || t > m.max)
        return Status::fault(fmt::format("{} takes motor {} to {}, outside its range {}..{}", info(in.op).name,
                                         m.letter, t, m.min, m.max));
      target_[i] = static_cast<std::int32_t>(t);
    }
    return machine_.moveTo(target_);
  }
  switch (in.op) {
    case Op::MoveTo: return moveTo({image_.constants.data() + in.c, target_.size()});
    case Op::MoveP: return moveTo(image_.points[in.b].values);
    case Op::HrdHome: return machine_.hardHome();
    case Op::GoSoft: return moveTo(state_.softHome);
    default: return Status::fault("not a motion instruction");
  }
}

RunOutcome Interpreter::finish(StopReason reason, std::string message, std::uint32_t index) {
  state_.finished = true;
  state_.outcome = {reason, std::move(message), index, state_.steps};
  return state_.outcome;
}

// The dispatch loop: one switch over the opcode, each case a few lines.
// Everything an operand could get wrong was ruled out by the verifier.
// Per instruction it checks one step count (the nearest of the step limit,
// a step pause and the still-clock limit) and, when set, the observer and
// the breakpoints; the clock is looked at only after a machine call.
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
  // The instruction the run ends on: END, or the last one when it runs past it.
  std::uint32_t endIndex = size == 0 ? 0 : size - 1;
  const std::int32_t* const k = image_.constants.data();
  std::int32_t* const vars = st.variables.data();
  const std::uint8_t* const before = pause.before.size() == size ? pause.before.data() : nullptr;
  const std::uint64_t stillLimit = limits.maxStepsPerInstant ? limits.maxStepsPerInstant : UINT64_MAX;
  const auto nextCheck = [&] {
    return std::min({limits.maxSteps, pause.atSteps, saturatingAdd(st.stillSince, stillLimit)});
  };
  std::uint64_t check = nextCheck();
  std::uint64_t steps = st.steps;
  std::uint32_t pc = st.pc;
  const auto pauseAt = [&](std::uint32_t next) {
    st.pc = next, st.steps = steps;
    return RunOutcome{StopReason::Paused, {}, next, steps};
  };
  const auto stop = [&](StopReason reason, std::string message, std::uint32_t index) {
    st.pc = pc, st.steps = steps;
    return finish(reason, std::move(message), index);
  };

  while (pc < size) {
    if (steps >= check) {
      if (steps >= limits.maxSteps)
        return stop(StopReason::StepLimit, fmt::format("step limit of {} instructions reached", limits.maxSteps), pc);
      if (steps - st.stillSince >= stillLimit)
        return stop(StopReason::InstantLimit,
                    fmt::format("{} instructions ran at {} s without the simulated clock moving", stillLimit,
                                formatSeconds(st.clockSeen)),
                    pc);
      return pauseAt(pc);
    }
    const std::uint32_t at = pc;
    const Instr& in = code[pc++];
    ++steps;
    Status status;
    bool machineCall = false;  // only these can fail or advance the clock
    switch (in.op) {
      case Op::Set:
        vars[in.b] = in.c;
        break;
      case Op::Add:
        if (std::int32_t sum; !__builtin_add_overflow(vars[in.b], in.c, &sum))
          vars[in.b] = sum;
        else
          return stop(StopReason::RuntimeError,
                      fmt::format("ADD overflows variable {} (values are 32-bit)", image_.variables[in.b]), at);
        break;
      case Op::JmpVar:
        if (compare(vars[in.b], in.a, in.c)) pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Goto:
        pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Gosub:
        if (st.callStack.size() == image_.callDepthLimit)
          return stop(StopReason::RuntimeError,
                      fmt::format("call stack overflow: more than {} nested GOSUBs", image_.callDepthLimit), at);
        st.callStack.push_back(pc);
        pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::Return:
        if (st.callStack.empty()) return stop(StopReason::RuntimeError, "RETURN without a GOSUB", at);
        pc = st.callStack.back();
        st.callStack.pop_back();
        break;
      case Op::JmpIn:
        if (machine_.input(in.a) == (in.b != 0)) pc = static_cast<std::uint32_t>(in.d);
        break;
      case Op::OutSig:
        status = machine_.setOutput(in.a, in.b != 0);
        machineCall = kMachineCall<Op::OutSig>;
        break;
      case Op::WaitFor:
        status = machine_.waitFor(in.a, in.b != 0);
        machineCall = kMachineCall<Op::WaitFor>;
        break;
      case Op::Delay:
        status = machine_.delay(Micros{in.c} * 1000);
        machineCall = kMachineCall<Op::Delay>;
        break;
      case Op::Move:
      case Op::MoveTo:
      case Op::MoveP:
      case Op::HrdHome:
      case Op::GoSoft:
        status = move(in);
        machineCall = kMachineCall<Op::Move>;
        break;
      case Op::SetSoft:
        for (std::size_t i = 0; i < st.softHome.size(); ++i) st.softHome[i] = k[static_cast<std::size_t>(in.c) + i];
        break;
      case Op::Reset:
        status = machine_.reset();
        machineCall = kMachineCall<Op::Reset>;
        break;
      case Op::Window:
        machine_.window(k[in.c], k[in.c + 1], k[in.c + 2]);
        machineCall = kMachineCall<Op::Window>;
        break;
      case Op::View:
        machine_.view(k[in.c], k[in.c + 1], k[in.c + 2]);
        machineCall = kMachineCall<Op::View>;
        break;
      case Op::End:
        pc = size;
        endIndex = at;
        break;
    }
    [[maybe_unused]] bool pauseNow = false;
    if (machineCall) {
      if (!status)
        return stop(status.code == Status::Code::Deadlock ? StopReason::Deadlock : StopReason::RuntimeError,
                    status.message, at);
      const Micros now = machine_.now();
      if (now > limits.maxTime)
        return stop(StopReason::TimeLimit,
                    fmt::format("simulated time limit of {} s passed (clock at {} s)", formatSeconds(limits.maxTime),
                                formatSeconds(now)),
                    at);
      if (now != st.clockSeen) {
        st.clockSeen = now, st.stillSince = steps;
        check = nextCheck();
      }
      if (now > pause.afterTime) {
        if constexpr (!kWatched) return pauseAt(pc);
        pauseNow = true;
      }
    }
    if constexpr (kWatched) {
      if (observer) {
        st.pc = pc, st.steps = steps;  // what the observer sees
        pauseNow |= observer->afterStep(*this, at);
      }
      if (pauseNow || (before && pc < size && before[pc])) return pauseAt(pc);
    }
  }
  return stop(StopReason::End, {}, endIndex);
}

}  // namespace rs::vm
