#include "runtime/rhino/emulator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rs::rhino {
namespace {

constexpr std::size_t kMaxCommand = 256;
constexpr std::size_t kMaxKept = 100'000;
// Line noise: the first byte is outside every valid answer of both dialects.
constexpr std::string_view kGarbage = "\x15~?\r";

std::string upper(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (c != ' ' && c != '\t') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string_view faultName(FaultKind k) {
  switch (k) {
    case FaultKind::None: return "none";
    case FaultKind::Silence: return "silence";
    case FaultKind::Garbage: return "garbage";
    case FaultKind::Slow: return "slow";
    case FaultKind::Hangup: return "hangup";
  }
  return "none";
}

bool parseFault(std::string_view text, FaultKind& out) {
  for (const FaultKind k :
       {FaultKind::None, FaultKind::Silence, FaultKind::Garbage, FaultKind::Slow, FaultKind::Hangup})
    if (text == faultName(k)) return out = k, true;
  if (text == "off") return out = FaultKind::None, true;
  return false;
}

// --- the engine ---------------------------------------------------------------

EmulatorEngine::EmulatorEngine(EmulatorConfig config) : config_(std::move(config)) {
  for (int i = 0; i < kEmulatedMotors; ++i) {
    EmulatedMotor& m = motors_[static_cast<std::size_t>(i)];
    m.letter = static_cast<char>('A' + i);
    m.rate = kDefaultStepRate * config_.rateScale;
    m.position = config_.start[static_cast<std::size_t>(i)];
    m.destination = m.position;
  }
  for (const vm::MotorSpec& spec : config_.motors) {
    EmulatedMotor* m = motor(spec.letter);
    if (!m) continue;
    m->used = true;
    m->rate = std::max(1.0, spec.speed * config_.rateScale);
    order_.push_back(spec.letter);
  }
}

EmulatedMotor* EmulatorEngine::motor(char letter) {
  if (letter < 'A' || letter > 'H') return nullptr;
  return &motors_[static_cast<std::size_t>(letter - 'A')];
}

bool EmulatorEngine::switchClosed(char letter) const {
  if (letter < 'A' || letter > 'H') return false;
  const EmulatedMotor& m = motors_[static_cast<std::size_t>(letter - 'A')];
  if (m.forcedSwitch) return *m.forcedSwitch;
  return std::abs(m.position) <= config_.switchWidth;
}

void EmulatorEngine::event(std::string text) {
  if (events_.size() < 1000) events_.push_back(std::move(text));
}

// received_ holds the last commands_ - received_.size() .. commands_ - 1.
std::vector<std::string> EmulatorEngine::receivedSince(std::uint64_t& seen) const {
  const std::uint64_t firstKept = commands_ - received_.size();
  const std::uint64_t from = std::max(seen, firstKept);
  seen = commands_;
  if (from >= commands_) return {};
  return {received_.begin() + static_cast<std::ptrdiff_t>(from - firstKept), received_.end()};
}

std::vector<std::string> EmulatorEngine::takeEvents() { return std::exchange(events_, {}); }

bool EmulatorEngine::faultActive() const {
  return config_.fault.kind != FaultKind::None && commands_ > config_.fault.after;
}

void EmulatorEngine::setFault(FaultPlan plan) {
  config_.fault = plan;
  config_.fault.after += commands_;  // counted from now
  faultAnnounced_ = false;
  if (plan.kind == FaultKind::None) event("fault injection off");
}

void EmulatorEngine::setInput(int line, bool on) {
  if (line < 1 || line > kControllerLines) return;
  const auto bit = static_cast<std::uint8_t>(1u << (line - 1));
  inputs_ = on ? static_cast<std::uint8_t>(inputs_ | bit) : static_cast<std::uint8_t>(inputs_ & ~bit);
}

void EmulatorEngine::forceSwitch(char letter, std::optional<bool> closed) {
  if (EmulatedMotor* m = motor(letter)) m->forcedSwitch = closed;
}

// Each motor earns rate * dt steps, spent on what it still has to go.
void EmulatorEngine::advance(Micros now) {
  if (now <= lastAdvance_) return;
  const double dt = static_cast<double>(now - lastAdvance_) / 1e6;
  lastAdvance_ = now;
  const bool mark3 = config_.settings.dialect == Dialect::Mark3;
  for (EmulatedMotor& m : motors_) {
    const std::int64_t toGo = mark3 ? m.registerSteps : (m.running ? std::int64_t{m.destination} - m.position : 0);
    if (toGo == 0) {
      m.carry = 0;
      m.running = false;
      continue;
    }
    const double budget = m.carry + dt * m.rate;
    std::int64_t steps = static_cast<std::int64_t>(std::floor(budget));
    m.carry = budget - static_cast<double>(steps);
    if (steps >= std::abs(toGo)) {
      steps = std::abs(toGo);
      m.carry = 0;
    }
    const std::int64_t moved = toGo > 0 ? steps : -steps;
    m.position = static_cast<std::int32_t>(m.position + moved);
    if (mark3)
      m.registerSteps = static_cast<int>(m.registerSteps - moved);
    else if (m.position == m.destination)
      m.running = false;
  }
  if (homing_ && std::none_of(motors_.begin(), motors_.end(), [](const EmulatedMotor& m) { return m.running; })) {
    homing_ = false;
    event("hard home done");
  }
}

void EmulatorEngine::receive(std::span<const std::uint8_t> bytes, Micros now) {
  advance(now);
  for (const std::uint8_t b : bytes) {
    if (hungUp_) return;
    if (b == '\r' || b == '\n') {
      if (!pending_.empty()) execute(std::exchange(pending_, {}), now);
      continue;
    }
    if (pending_.size() < kMaxCommand) {
      pending_ += static_cast<char>(b);
    } else if (pending_.size() == kMaxCommand) {
      pending_ += '~';
      event("a command line longer than 256 bytes: the rest is dropped");
    }
  }
}

void EmulatorEngine::execute(std::string command, Micros now) {
  ++commands_;
  if (received_.size() == kMaxKept) received_.pop_front();
  received_.push_back(command);
  if (faultActive() && !faultAnnounced_) {
    faultAnnounced_ = true;
    event(fmt::format("fault active: {} (from command {})", faultName(config_.fault.kind), commands_));
  }
  if (faultActive() && config_.fault.kind == FaultKind::Hangup) {
    hungUp_ = true;
    event("hang-up: the port is closed");
    return;
  }
  if (config_.settings.dialect == Dialect::Mark3)
    executeMark3(upper(command), now);
  else
    executeMark4(upper(command), now);
}

void EmulatorEngine::reply(std::string bytes, Micros now) {
  if (faultActive()) {
    if (config_.fault.kind == FaultKind::Silence) return;
    if (config_.fault.kind == FaultKind::Garbage) bytes = kGarbage;
  }
  Micros due = now + config_.latency;
  if (faultActive() && config_.fault.kind == FaultKind::Slow) due += config_.fault.slowDelay;
  if (!replies_.empty()) due = std::max(due, replies_.back().due);
  replies_.push_back({due, std::move(bytes)});
}

void EmulatorEngine::replyNumber(long value, Micros now) { reply(fmt::format("{}\r", value), now); }

std::optional<Micros> EmulatorEngine::nextReplyAt() const {
  if (replies_.empty()) return std::nullopt;
  return replies_.front().due;
}

std::vector<std::uint8_t> EmulatorEngine::takeReplies(Micros now) {
  std::vector<std::uint8_t> out;
  while (!replies_.empty() && replies_.front().due <= now) {
    out.insert(out.end(), replies_.front().bytes.begin(), replies_.front().bytes.end());
    replies_.pop_front();
  }
  return out;
}
EmulatorSnapshot EmulatorEngine::snapshot() const {
  EmulatorSnapshot s;
  s.motors = motors_;
  s.order = order_;
  s.outputs = outputs_;
  s.inputs = inputs_;
  s.commands = commands_;
  s.faultActive = faultActive();
  s.fault = config_.fault.kind;
  s.hungUp = hungUp_;
  s.hostMode = hostMode_;
  return s;
}

std::string EmulatorEngine::statusLine() const {
  std::string line(dialectName(config_.settings.dialect));
  const auto moving = [&](const EmulatedMotor& m) {
    return config_.settings.dialect == Dialect::Mark3 ? m.registerSteps != 0 : m.running;
  };
  // The robot's motors in its order, then any other port that moved.
  std::vector<char> letters = order_;
  for (const EmulatedMotor& m : motors_)
    if (!m.used && (m.position != 0 || moving(m))) letters.push_back(m.letter);
  for (const char letter : letters) {
    const EmulatedMotor& m = motors_[static_cast<std::size_t>(letter - 'A')];
    line += fmt::format("  {}{:+d}{}{}", m.letter, m.position, moving(m) ? "*" : "", switchClosed(m.letter) ? "h" : "");
  }
  const auto lines = [](std::uint8_t mask) {
    std::string s;
    for (int i = 0; i < kControllerLines; ++i) s += ((mask >> i) & 1) ? static_cast<char>('1' + i) : '.';
    return s;
  };
  line += fmt::format(" | out {} | in {} | {} cmds", lines(outputs_), lines(inputs_), commands_);
  if (config_.fault.kind != FaultKind::None)
    line += fmt::format(" | fault {}{}", faultName(config_.fault.kind), faultActive() ? " ACTIVE" : " armed");
  return line;
}

// --- in-process, on a manual clock ------------------------------------------------

LoopbackLink::LoopbackLink(EmulatorEngine& engine, ManualClock& clock) : engine_(engine), clock_(clock) {
  const LineSettings& line = engine.config().settings.line;
  const int bits = 1 + line.dataBits + (line.parity == Parity::None ? 0 : 1) + line.stopBits;
  byteTime_ = std::max<Micros>(1, Micros{bits} * 1'000'000 / line.baud);
}

vm::Status LoopbackLink::write(std::span<const std::uint8_t> bytes, Micros) {
  if (engine_.hungUp()) return vm::Status::closed("emulator: the port hung up");
  clock_.sleepFor(byteTime_ * static_cast<Micros>(bytes.size()));
  engine_.receive(bytes, clock_.now());
  return vm::Status::ok();
}

vm::Status LoopbackLink::read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) {
  count = 0;
  if (pending_.empty()) {
    if (engine_.hungUp()) return vm::Status::closed("emulator: the port hung up");
    const std::optional<Micros> due = engine_.nextReplyAt();
    if (!due || *due > clock_.now() + timeout) {
      clock_.sleepFor(timeout);
      return vm::Status::timeout();
    }
    clock_.advanceTo(*due);
    const std::vector<std::uint8_t> bytes = engine_.takeReplies(clock_.now());
    pending_.insert(pending_.end(), bytes.begin(), bytes.end());
  }
  const std::size_t n = std::min(buffer.size(), pending_.size());
  std::copy_n(pending_.begin(), n, buffer.begin());
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  count = n;
  return vm::Status::ok();
}

}  // namespace rs::rhino
