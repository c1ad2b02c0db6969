#include "runtime/sim/sim_machine.h"

#include "base/seconds.h"
#include "vm/interpreter.h"
#include "vm/motor_range.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <utility>

namespace rs::runtime {
namespace {

using vm::Micros;
using vm::Status;

constexpr Micros kClockLimit = std::numeric_limits<Micros>::max();

const char* onOff(bool on) { return on ? "ON" : "OFF"; }

std::int64_t saturatingAdd(std::int64_t a, std::int64_t b) {
  if (b > 0 && a > std::numeric_limits<std::int64_t>::max() - b)
    return std::numeric_limits<std::int64_t>::max();
  if (b < 0 && a < std::numeric_limits<std::int64_t>::min() - b)
    return std::numeric_limits<std::int64_t>::min();
  return a + b;
}

// Degrees kept in 0..359 so that endless VIEW loops cannot overflow.
std::int64_t addDegrees(std::int64_t angle, std::int32_t by) {
  const auto sum = (angle + by) % 360;
  return sum < 0 ? sum + 360 : sum;
}

}  // namespace

SimMachine::SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli)
    : SimMachine(std::move(motors), std::move(stimuli), std::make_unique<Scheduler>(), nullptr) {}

SimMachine::SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, Scheduler& clock)
    : SimMachine(std::move(motors), std::move(stimuli), nullptr, &clock) {}

SimMachine::SimMachine(std::vector<vm::MotorSpec> motors, stimuli::Stimuli stimuli, std::unique_ptr<Scheduler> own,
                       Scheduler* clock)
    : motors_(std::move(motors)),
      rules_(std::move(stimuli.rules)),
      schedule_(stimuli.changes),
      positions_(motors_.size(), 0),
      home_(motors_.size(), 0),
      segments_(motors_.size()),
      ownClock_(std::move(own)),
      clock_(clock ? clock : ownClock_.get()) {
  schedule_.applyUntil(now(), inputs_);
}

// Applies the stimuli due by now, telling the listener of each change.
void SimMachine::applyInputs() {
  if (inputListener_ || causeListener_)
    schedule_.applyUntil(now(), inputs_, [this](Micros at, vm::IoMask mask, const InputCause& cause) {
      if (inputListener_) inputListener_(at, mask);
      if (causeListener_) causeListener_(at, cause);
    });
  else
    schedule_.applyUntil(now(), inputs_);
}

bool SimMachine::setInputNow(int input, bool on) {
  if (!vm::isIoLine(input)) return false;
  applyInputs();
  if (!schedule_.schedule({now(), input, on}, InputCause::Kind::Set)) return false;
  applyInputs();
  return true;
}

SimMachine::State SimMachine::state() const {
  return {positions_, segments_, path_,       now(),   knots_,  outputs_, inputs_, windowShift_,
          viewRotation_, schedule_.state(), waitUntil_, waitInput_, waitOn_, waitMove_, wiresAt_, instantWires_};
}

void SimMachine::restore(const State& s) {
  positions_ = s.positions, segments_ = s.segments, path_ = s.path, knots_ = s.knots;
  clock_->restoreNow(s.now);  // on a cell, the cell's snapshot puts back the rest of its clock
  waitUntil_ = s.waitUntil, waitInput_ = s.waitInput, waitOn_ = s.waitOn, waitMove_ = s.waitMove;
  outputs_ = s.outputs, inputs_ = s.inputs;
  wiresAt_ = s.wiresAt, instantWires_ = s.instantWires;
  windowShift_ = s.windowShift, viewRotation_ = s.viewRotation;
  schedule_.restore(s.schedule);
}

Micros SimMachine::travelTime(std::size_t motor, std::int32_t target) const {
  return runtime::travelTime(motors_[motor], std::abs(std::int64_t{target} - positions_[motor]));
}

Status SimMachine::checkTargets(std::span<const std::int32_t> targets) const {
  if (targets.size() != motors_.size())
    return Status::fault(
        fmt::format("move has {} targets for {} motors", targets.size(), motors_.size()));
  Micros longest = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto& m = motors_[i];
    if (!vm::inRange(m, targets[i])) return Status::fault(vm::targetOutsideRange(m, targets[i]));
    if (m.speed <= 0 && targets[i] != positions_[i])
      return Status::fault(fmt::format("motor {} cannot move: its speed is {}", m.letter, m.speed));
    longest = std::max(longest, travelTime(i, targets[i]));
  }
  if (now() > kClockLimit - longest) return Status::fault("the virtual clock overflowed");
  return Status::ok();
}

Status SimMachine::moveTo(std::span<const std::int32_t> targets) {
  if (auto checked = checkTargets(targets); !checked) return checked;
  Micros longest = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const Micros duration = travelTime(i, targets[i]);
    segments_[i] = {positions_[i], targets[i], now(), now() + duration};
    positions_[i] = targets[i];
    longest = std::max(longest, duration);
  }
  path_.clear();
  return advanceBy(longest, true);
}

Status SimMachine::moveLockStep(std::span<const std::int32_t> targets, std::uint32_t lead) {
  if (auto checked = checkTargets(targets); !checked) return checked;
  Micros longest = 0;
  for (std::size_t i = 0; i < targets.size(); ++i)
    longest = std::max(longest, lockStepTime(motors_[i], std::abs(std::int64_t{targets[i]} - positions_[i])));
  const Micros now = this->now();
  if (now > kClockLimit - longest) return Status::fault("the virtual clock overflowed");
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const bool moves = targets[i] != positions_[i];
    const bool ahead = i < 32 && ((lead >> i) & 1u) != 0;
    segments_[i] = {positions_[i], targets[i], now, moves ? now + longest : now, moves, moves && ahead};
    positions_[i] = targets[i];
  }
  path_.insert(path_.end(), segments_.begin(), segments_.end());
  ++knots_;
  return advanceBy(longest, true, true);
}

void SimMachine::beginPath() { path_.clear(); }

std::int32_t SimMachine::positionAt(std::size_t motor, Micros t) const {
  if (motor >= segments_.size()) return 0;
  // Inside a line: the latest of its knots begun by t (the first when none is).
  const std::size_t n = segments_.size();
  for (std::size_t k = path_.size() / n; k-- > 0;) {
    const MotorSegment& knot = path_[k * n + motor];
    if (knot.start <= t || k == 0) return runtime::positionAt(knot, motors_[motor], t);
  }
  return runtime::positionAt(segments_[motor], motors_[motor], t);
}

bool SimMachine::motionKey(vm::Micros origin, std::vector<std::uint64_t>& out) const {
  const std::size_t n = segments_.size();
  if (n == 0 || path_.size() / n > kMotionKeyKnots) return false;
  // Each number as its two's complement bits (a key's words only compare),
  // written in place: the devices ask at every wake.
  std::size_t at = out.size();
  out.resize(at + 1 + 5 * (segments_.size() + path_.size()));
  std::uint64_t* w = out.data() + at;
  *w++ = path_.size();
  const auto add = [&](const MotorSegment& s) {
    *w++ = static_cast<std::uint64_t>(std::int64_t{s.from}), *w++ = static_cast<std::uint64_t>(std::int64_t{s.to});
    *w++ = static_cast<std::uint64_t>(s.start - origin), *w++ = static_cast<std::uint64_t>(s.end - origin);
    *w++ = (s.lockStep ? 1 : 0) | (s.lead ? 2 : 0);
  };
  for (const MotorSegment& s : segments_) add(s);
  for (const MotorSegment& s : path_) add(s);
  return true;
}

std::int64_t SimMachine::coveredBetween(std::size_t motor, Micros t0, Micros t1) const {
  if (motor >= segments_.size()) return 0;
  std::int64_t covered = 0;
  Micros from = t0;
  std::int32_t at = positionAt(motor, t0);
  const std::size_t n = segments_.size();
  for (std::size_t k = 1; k < path_.size() / n; ++k) {
    const Micros start = path_[k * n + motor].start;
    if (start <= from) continue;
    if (start >= t1) break;
    const std::int32_t there = positionAt(motor, start);
    covered += std::abs(std::int64_t{there} - at);
    from = start, at = there;
  }
  return covered + std::abs(std::int64_t{positionAt(motor, t1)} - at);
}

Status SimMachine::hardHome() { return moveTo(home_); }

Status SimMachine::reset() {
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    positions_[i] = home_[i];
    segments_[i] = {home_[i], home_[i], now(), now()};
  }
  path_.clear();
  return Status::ok();
}

Status SimMachine::setOutput(int output, bool on) {
  if (!vm::isIoLine(output))
    return Status::fault(fmt::format("output {} does not exist (outputs are 1..{})", output, vm::kIoCount));
  if (vm::lineIsOn(outputs_, output) == on) return Status::ok();  // no change, no rule fires
  outputs_ = vm::withLine(outputs_, output, on);
  Status fired = fireRules(output, on);
  applyInputs();  // rules with no delay act at once
  if (outputListener_ && outputListener_(output, on) && cooperative_ && fired) {
    // The wire acts at this instant, in the cell's rounds: a zero wait lets
    // them run before the robot's next instruction reads the input.
    waitUntil_ = now(), waitInput_ = 0, waitMove_ = false;
    return Status::notYet(now());
  }
  return fired;
}

Status SimMachine::fireRules(int output, bool on) {
  for (const auto& rule : rules_) {
    if (rule.output != output || rule.outputOn != on) continue;
    if (!schedule_.schedule({saturatingAdd(now(), std::max<Micros>(rule.delay, 0)), rule.input, rule.inputOn, rule.line}))
      return Status::fault(fmt::format(
          "the stimuli rule {}'when output {} {} then input {} {} after {}' has {} input changes waiting to happen: "
          "output {} switches faster than the rule's delay",
          rule.line ? fmt::format("of line {} ", rule.line) : std::string(), rule.output, onOff(rule.outputOn),
          rule.input, onOff(rule.inputOn), base::formatSeconds(rule.delay), kMaxPendingReactive, output));
  }
  return Status::ok();
}

bool SimMachine::input(int input) {
  applyInputs();
  return vm::lineIsOn(inputs_, input);
}

Status SimMachine::waitFor(int input, bool on) {
  if (!vm::isIoLine(input))
    return Status::fault(fmt::format("input {} does not exist (inputs are 1..{})", input, vm::kIoCount));
  if (this->input(input) == on) return Status::ok();
  if (cooperative_) {
    waitInput_ = input, waitOn_ = on;
    return waitForInput(input, on);
  }
  const auto when = schedule_.whenReads(input, on, inputs_);
  if (!when)
    return Status::deadlock(
        fmt::format("input {} never turns {}: {}", input, onOff(on),
                    schedule_.hasPendingFor(input)
                        ? fmt::format("no scheduled stimulus leaves it {}", onOff(on))
                        : std::string("no stimulus is scheduled")));
  return advanceBy(*when - now());
}

// Waiting on the scheduler: the input already reads `on`, or NotYet until
// the next stimulus that makes it so (when no stimulus will, until
// whatever else in the cell changes it: the scheduler knows).
Status SimMachine::waitForInput(int input, bool on) {
  applyInputs();
  if (vm::lineIsOn(inputs_, input) == on) {
    waitInput_ = 0;
    return Status::ok();
  }
  const auto when = schedule_.whenReads(input, on, inputs_);
  return Status::notYet(when ? *when : Status::kNever);
}

void SimMachine::endWait(Status status) { endWait_ = std::move(status); }

Status SimMachine::waitDeadlock() const {
  const int input = waitInput_;
  const bool on = waitOn_;
  return Status::deadlock(fmt::format("input {} never turns {}: {}", input, onOff(on),
                                      schedule_.hasPendingFor(input)
                                          ? fmt::format("no scheduled stimulus leaves it {}", onOff(on))
                                          : std::string("no stimulus is scheduled")));
}

bool SimMachine::setInputBy(int input, bool on, const InputCause& cause) {
  if (!vm::isIoLine(input)) return false;
  applyInputs();
  const vm::IoMask after = vm::withLine(inputs_, input, on);
  if (after == inputs_) return true;
  inputs_ = after;
  if (cause.kind == InputCause::Kind::Wire) noteWire(cause);
  if (inputListener_) inputListener_(now(), inputs_);
  if (causeListener_) causeListener_(now(), cause);
  return true;
}

// A program that answers its own inputs through wires without AFTER keeps
// the clock still: the stop names the wires that did it at this instant.
void SimMachine::noteWire(const InputCause& cause) {
  if (wiresAt_ != now()) instantWires_.clear(), wiresAt_ = now();
  // The wire, not the value it carries; put in words only if the run stops
  // (an input change through a wire is frequent, a stop rare).
  InputCause wire = cause;
  wire.on = false;
  if (instantWires_.size() < kMaxStillWires &&
      std::find(instantWires_.begin(), instantWires_.end(), wire) == instantWires_.end())
    instantWires_.push_back(std::move(wire));
}

std::string SimMachine::stillReason() const {
  if (wiresAt_ != now() || instantWires_.empty()) return {};
  std::vector<std::string> wires;
  for (const InputCause& w : instantWires_)
    wires.push_back(
        fmt::format("{} TO {}{}IN {} (line {})", w.source, w.robot, w.robot.empty() ? "" : ".", w.input, w.line));
  return fmt::format("wires changed its inputs at that instant without end: {}", fmt::join(wires, ", "));
}

Status SimMachine::resume() {
  if (endWait_) {
    Status s = std::move(*endWait_);
    endWait_.reset();
    waitInput_ = 0, waitMove_ = false, waitUntil_ = now();
    return s;
  }
  if (waitInput_) return waitForInput(waitInput_, waitOn_);
  if (now() < waitUntil_) return Status::notYet(waitUntil_);
  applyInputs();
  if (std::exchange(waitMove_, false) && moveListener_) moveListener_();
  return Status::ok();
}

Status SimMachine::delay(Micros duration) {
  if (duration < 0) return Status::fault(fmt::format("delay of {} us is negative", duration));
  if (now() > kClockLimit - duration) return Status::fault("the virtual clock overflowed");
  return advanceBy(duration);
}

// The one place the machine moves the cell's clock: inputs always match
// now(). Waiting on the scheduler, the wait begins and the clock is left to it.
bool SimMachine::finishesAlone(Micros until, bool knot) {
  if (!finishAlone_ || knot) return false;
  if (aloneBefore_) aloneBefore_();
  const std::optional<Micros> next = clock_->nextTime();
  return !next || *next > until;
}

Status SimMachine::advanceBy(Micros duration, bool move, bool knot) {
  const Micros until = now() + duration;
  if (move && duration > 0 && moveBegunListener_) moveBegunListener_(until);
  if (cooperative_ && duration > 0) {
    if (!finishesAlone(until, knot)) {
      waitUntil_ = until, waitInput_ = 0, waitMove_ = move;
      return Status::notYet(until);
    }
    Status status = clock_->advanceTo(until);  // nothing is due by then: the clock alone moves
    if (aloneAfter_) aloneAfter_();
    applyInputs();
    if (move && moveListener_) moveListener_();
    return status;
  }
  Status status = clock_->advanceTo(until);
  applyInputs();
  if (move && moveListener_) moveListener_();
  return status;
}

void SimMachine::window(std::int32_t x, std::int32_t y, std::int32_t z) {
  windowShift_ = {saturatingAdd(windowShift_.x, x), saturatingAdd(windowShift_.y, y),
                  saturatingAdd(windowShift_.z, z)};
}

void SimMachine::view(std::int32_t x, std::int32_t y, std::int32_t z) {
  viewRotation_ = {addDegrees(viewRotation_.x, x), addDegrees(viewRotation_.y, y),
                   addDegrees(viewRotation_.z, z)};
}

}  // namespace rs::runtime
