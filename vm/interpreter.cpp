#include "vm/interpreter.h"

#include <fmt/format.h>

namespace rs::vm {

Interpreter::Interpreter(const Image& image, Machine& machine)
    : image_(image),
      machine_(machine),
      vars_(image.variables.size(), 0),
      softHome_(image.motors.size(), 0),
      target_(image.motors.size(), 0) {
  callStack_.reserve(image.callDepthLimit);
}

std::string formatSeconds(Micros t) {
  const char* sign = t < 0 ? "-" : "";
  const std::uint64_t u = t < 0 ? 0 - static_cast<std::uint64_t>(t) : static_cast<std::uint64_t>(t);
  // Round to the nearest millisecond, halves up: same digits on every machine.
  const std::uint64_t ms = (u + 500) / 1000;
  return fmt::format("{}{}.{:03}", sign, ms / 1000, ms % 1000);
}

std::string Interpreter::rangeError(std::span<const std::int32_t> targets) const {
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const MotorSpec& m = image_.motors[i];
    if (targets[i] < m.min || targets[i] > m.max)
      return fmt::format("motor {} target {} is outside its range {}..{}", m.letter, targets[i], m.min, m.max);
  }
  return {};
}

Status Interpreter::moveTo(std::span<const std::int32_t> targets) {
  if (std::string e = rangeError(targets); !e.empty()) return Status::fault(std::move(e));
  return machine_.moveTo(targets);
}

Status Interpreter::move(const Instr& in) {
  const std::span<const std::int32_t> now = machine_.positions();
  switch (in.op) {
    case Op::Move:
      for (std::size_t i = 0; i < target_.size(); ++i) {
        const std::int64_t t = std::int64_t{now[i]} + image_.constants[static_cast<std::size_t>(in.c) + i];
        const MotorSpec& m = image_.motors[i];
        if (t < m.min || t > m.max)
          return Status::fault(fmt::format("MOVE takes motor {} to {}, outside its range {}..{}", m.letter, t, m.min, m.max));
        target_[i] = static_cast<std::int32_t>(t);
      }
      return machine_.moveTo(target_);
    case Op::MoveTo:
      return moveTo({image_.constants.data() + in.c, target_.size()});
    case Op::MoveP:
      return moveTo(image_.points[in.b].values);
    case Op::HrdHome:
      return machine_.hardHome();
    case Op::GoSoft:
      return moveTo(softHome_);
    default:
      return Status::fault("not a motion instruction");
  }
}

namespace {

RunOutcome stop(StopReason reason, std::string message, std::uint32_t index, std::uint64_t steps) {
  return {reason, std::move(message), index, steps};
}

RunOutcome fromStatus(const Status& s, std::uint32_t index, std::uint64_t steps) {
  return stop(s.code == Status::Code::Deadlock ? StopReason::Deadlock : StopReason::RuntimeError, s.message, index,
              steps);
}

bool compare(std::int32_t value, std::uint8_t cmp, std::int32_t with) {
  switch (static_cast<Compare>(cmp)) {
    case Compare::Less: return value < with;
    case Compare::Greater: return value > with;
    case Compare::Equal: return value == with;
  }
  return false;
}

}  // namespace

// The dispatch loop: one switch over the opcode, each case a few lines.
// Everything an operand could get wrong was ruled out by the verifier.
RunOutcome Interpreter::run(const RunLimits& limits, StepObserver* observer) {
  const Instr* const code = image_.code.data();
  const std::uint32_t size = static_cast<std::uint32_t>(image_.code.size());
  const std::int32_t* const k = image_.constants.data();
  std::int32_t* const vars = vars_.data();
  std::uint64_t steps = 0;
  std::uint32_t pc = 0;

  while (pc < size) {
    if (steps == limits.maxSteps)
      return stop(StopReason::StepLimit, fmt::format("step limit of {} instructions reached", limits.maxSteps), pc,
                  steps);
    const std::uint32_t at = pc;
    const Instr& in = code[pc++];
    ++steps;
    Status status;
    bool machineCall = true;  // only these can fail or advance the clock
    switch (in.op) {
      case Op::Set:
        vars[in.b] = in.c;
        machineCall = false;
        break;
      case Op::Add:
        if (std::int32_t sum; !__builtin_add_overflow(vars[in.b], in.c, &sum))
          vars[in.b] = sum;
        else
          return stop(StopReason::RuntimeError,
                      fmt::format("ADD overflows variable {} (values are 32-bit)", image_.variables[in.b]), at, steps);
        machineCall = false;
        break;
      case Op::JmpVar:
        if (compare(vars[in.b], in.a, in.c)) pc = static_cast<std::uint32_t>(in.d);
        machineCall = false;
        break;
      case Op::Goto:
        pc = static_cast<std::uint32_t>(in.d);
        machineCall = false;
        break;
      case Op::Gosub:
        if (callStack_.size() == image_.callDepthLimit)
          return stop(StopReason::RuntimeError,
                      fmt::format("call stack overflow: more than {} nested GOSUBs", image_.callDepthLimit), at,
                      steps);
        callStack_.push_back(pc);
        pc = static_cast<std::uint32_t>(in.d);
        machineCall = false;
        break;
      case Op::Return:
        if (callStack_.empty()) return stop(StopReason::RuntimeError, "RETURN without a GOSUB", at, steps);
        pc = callStack_.back();
        callStack_.pop_back();
        machineCall = false;
        break;
      case Op::JmpIn:
        if (machine_.input(in.a) == (in.b != 0)) pc = static_cast<std::uint32_t>(in.d);
        machineCall = false;
        break;
      case Op::OutSig:
        status = machine_.setOutput(in.a, in.b != 0);
        break;
      case Op::WaitFor:
        status = machine_.waitFor(in.a, in.b != 0);
        break;
      case Op::Delay:
        status = machine_.delay(Micros{in.c} * 1000);
        break;
      case Op::Move:
      case Op::MoveTo:
      case Op::MoveP:
      case Op::HrdHome:
      case Op::GoSoft:
        status = move(in);
        break;
      case Op::SetSoft:
        for (std::size_t i = 0; i < softHome_.size(); ++i) softHome_[i] = k[static_cast<std::size_t>(in.c) + i];
        machineCall = false;
        break;
      case Op::Reset:
        status = machine_.reset();
        break;
      case Op::Window:
        machine_.window(k[in.c], k[in.c + 1], k[in.c + 2]);
        break;
      case Op::View:
        machine_.view(k[in.c], k[in.c + 1], k[in.c + 2]);
        break;
      case Op::End:
        pc = size;
        machineCall = false;
        break;
    }
    if (machineCall) {
      if (!status) return fromStatus(status, at, steps);
      if (machine_.now() > limits.maxTime)
      return stop(StopReason::TimeLimit,
                  fmt::format("simulated time limit of {} s passed (clock at {} s)", formatSeconds(limits.maxTime),
                              formatSeconds(machine_.now())),
                    at, steps);
    }
    if (observer) observer->afterStep(*this, at);
  }
  return stop(StopReason::End, {}, pc == 0 ? 0 : pc - 1, steps);
}

}  // namespace rs::vm
