#include "runtime/rhino/rhino_machine.h"

#include <fmt/format.h>

#include <algorithm>

#include "base/seconds.h"
#include "vm/motor_range.h"

namespace rs::rhino {
namespace {

using vm::Status;

const char* onOff(bool on) { return on ? "ON" : "OFF"; }

}  // namespace

RhinoMachine::RhinoMachine(std::vector<vm::MotorSpec> motors, RhinoSettings settings, Link& link, Clock& clock,
                           SerialLog* log, const std::atomic<bool>* interrupt)
    : motors_(std::move(motors)),
      settings_(std::move(settings)),
      clock_(clock),
      log_(log),
      session_(link, clock, settings_, log, interrupt),
      positions_(motors_.size(), 0),
      start_(motors_.size(), 0),
      commanded_(motors_.size(), 0) {
  session_.setDevice(link.name());
  controller_ = settings_.dialect == Dialect::Mark3 ? makeMark3(session_, motors_) : makeMark4(session_, motors_);
}

RhinoMachine::~RhinoMachine() {
  if (log_) log_->comment(failure_.empty() ? "end of run" : "end of run: " + failure_);
}

vm::Micros RhinoMachine::now() const { return opened_ ? clock_.now() - origin_ : 0; }

Status RhinoMachine::open() {
  if (log_) {
    log_->comment(fmt::format("robotsim serial log: {} on {}, {}, timeout {} s", dialectName(settings_.dialect),
                              session_.device(), describe(settings_.line), base::formatSeconds(settings_.timeout)));
    std::string motors;
    for (const vm::MotorSpec& m : motors_) motors += fmt::format(" {} {}..{}", m.letter, m.min, m.max);
    log_->comment("motors:" + motors);
  }
  if (Status st = controller_->begin(positions_); !st) {
    if (session_.lastFailureWasSilence()) openHint_ = probeOtherDialect();
    // Nothing has moved yet, but a controller that answers wrongly may be
    // doing anything: stop it all the same.
    return fail(Status::fault(fmt::format("no working {} controller on {}: {}", dialectTitle(settings_.dialect),
                                          session_.device(), st.message)));
  }
  start_ = positions_;
  commanded_ = positions_;
  opened_ = true;
  origin_ = clock_.now();
  return Status::ok();
}

// The first contact met silence: is the other dialect's controller on the
// line? Each dialect's handshake query is one the other does not know and
// leaves unanswered (a Mark IV puts error 10 on its stack for "I", a Mark
// III ignores "SE"), so one harmless query of the other kind tells them
// apart: a Mark IV answers "SE" with a decimal number and CR, a Mark III
// answers "I" with one byte 0x20..0x7F. docs/rhino-protocol.md, "The
// handshake".
std::string RhinoMachine::probeOtherDialect() {
  if (settings_.dialect == Dialect::Mark3) {
    session_.note("no answer to the Mark III handshake: asking \"SE\" as a Mark IV would be asked");
    long code = 0;
    if (!session_.queryNumber("SE", code)) return {};
    return fmt::format("the controller on {} answers as a Mark IV (\"SE\" was answered with {}): run with --dialect mark4",
                       session_.device(), code);
  }
  session_.note("no answer to the Mark IV handshake: asking \"I\" as a Mark III would be asked");
  std::uint8_t reply = 0;
  if (!session_.queryByte("I", reply) || reply < 0x20 || reply > 0x7F) return {};
  return fmt::format("the controller on {} answers as a Mark III (\"I\" was answered with one byte): run with "
                     "--dialect mark3",
                     session_.device());
}

// Every failure of the controller ends here: stop every motor, remember why.
Status RhinoMachine::fail(Status status) {
  if (status.code != Status::Code::Fault) return status;
  const std::string stop = controller_->stopAll();
  failure_ = fmt::format("{}; {}", status.message, stop);
  session_.note(stop);
  return Status::fault(failure_);
}

Status RhinoMachine::ready() {
  if (!failure_.empty()) return Status::fault(failure_);
  if (!opened_) return Status::fault("the Rhino controller was not opened");
  if (Status st = session_.checkInterrupt(); !st) return fail(st);
  return Status::ok();
}

Status RhinoMachine::moveTo(std::span<const std::int32_t> targets) {
  if (Status st = ready(); !st) return st;
  if (targets.size() != motors_.size())
    return Status::fault(fmt::format("move has {} targets for {} motors", targets.size(), motors_.size()));
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const vm::MotorSpec& m = motors_[i];
    if (!vm::inRange(m, targets[i]))
      return Status::fault(vm::targetOutsideRange(m, targets[i]) + ": nothing was sent to the controller");
  }
  if (std::string refused = controller_->refuse(targets); !refused.empty())
    return Status::fault(refused + ": nothing was sent to the controller");
  commanded_.assign(targets.begin(), targets.end());
  return fail(controller_->move(targets, positions_));
}

Status RhinoMachine::hardHome() {
  if (Status st = ready(); !st) return st;
  std::fill(commanded_.begin(), commanded_.end(), 0);
  return fail(controller_->home(positions_));
}

std::optional<FaultState> RhinoMachine::faultState() const {
  if (failure_.empty()) return std::nullopt;
  FaultState f;
  f.failure = failure_;
  f.outputsOn = outputs_;
  for (std::size_t i = 0; i < motors_.size(); ++i) f.motors.push_back({motors_[i].letter, positions_[i], commanded_[i]});
  return f;
}

Status RhinoMachine::reset() { return moveTo(start_); }

Status RhinoMachine::setOutput(int output, bool on) {
  if (Status st = ready(); !st) return st;
  if (!vm::isIoLine(output))
    return Status::fault(fmt::format("output {} does not exist (outputs are 1..{})", output, vm::kIoCount));
  if (vm::lineIsOn(written_, output) && vm::lineIsOn(outputs_, output) == on) return Status::ok();
  const vm::IoMask next = vm::withLine(outputs_, output, on);
  if (Status st = controller_->writeOutput(output, on, next); !st) return fail(st);
  outputs_ = next;
  written_ = vm::withLine(written_, output, true);
  return Status::ok();
}

Status RhinoMachine::readPositions() {
  if (Status st = ready(); !st) return st;
  if (Status st = controller_->readPositions(positions_); !st) return fail(st);
  return readInputs();
}

Status RhinoMachine::readInputs() {
  vm::IoMask mask = 0;
  if (Status st = controller_->readInputs(mask); !st) return fail(st);
  inputs_ = mask;
  return Status::ok();
}

// input() cannot report a failure: the controller is stopped at once and
// the next instruction that talks to the machine ends the run.
bool RhinoMachine::input(int input) {
  if (!vm::isIoLine(input) || !ready() || !readInputs()) return false;
  return vm::lineIsOn(inputs_, input);
}

Status RhinoMachine::waitFor(int input, bool on) {
  if (Status st = ready(); !st) return st;
  if (!vm::isIoLine(input))
    return Status::fault(fmt::format("input {} does not exist (inputs are 1..{})", input, vm::kIoCount));
  for (;;) {
    if (Status st = readInputs(); !st) return st;
    if (vm::lineIsOn(inputs_, input) == on) return Status::ok();
    if (now() >= waitLimit_)
      return Status::deadlock(fmt::format("input {} did not turn {} on the controller within {} s", input, onOff(on),
                                          base::formatSeconds(waitLimit_)));
    if (Status st = session_.pause(settings_.pollInterval); !st) return fail(st);
  }
}

Status RhinoMachine::delay(vm::Micros duration) {
  if (Status st = ready(); !st) return st;
  if (duration < 0) return Status::fault(fmt::format("delay of {} us is negative", duration));
  return fail(session_.pause(duration));
}

}  // namespace rs::rhino
