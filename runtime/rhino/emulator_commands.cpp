// The controller's commands in its two dialects (docs/serial.md): the
// Mark III's letters and the Mark IV's host-mode words, each answered as
// the controller would, and the I/J/K inquiry bits both share.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "runtime/rhino/emulator.h"

namespace rs::rhino {
namespace {

constexpr int kMark4Limit = 32767;

bool parseLong(std::string_view s, long& out) {
  if (s.empty() || s.size() > 11) return false;
  std::size_t i = 0;
  const bool negative = s[0] == '-';
  if (negative || s[0] == '+') ++i;
  if (i == s.size()) return false;
  long v = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    v = v * 10 + (s[i] - '0');
  }
  out = negative ? -v : v;
  return true;
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = s.find(',', start);
    parts.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

}  // namespace

// I, J, K: 32 + six bits; a closed switch or (active low) an ON input is 0.
std::uint8_t EmulatorEngine::inquiryBits(char command) const {
  unsigned bits = 0x3F;
  const RhinoSettings& s = config_.settings;
  for (int i = 0; i < kEmulatedMotors; ++i) {
    const BitSource& src = s.switches[static_cast<std::size_t>(i)];
    if (src.command == command && switchClosed(static_cast<char>('A' + i))) bits &= ~(1u << src.bit);
  }
  for (int line = 0; line < kControllerLines; ++line) {
    const BitSource& src = s.inputs[static_cast<std::size_t>(line)];
    if (src.command != command) continue;
    const bool on = (inputs_ >> line) & 1;
    if (on == s.inputsActiveLow)
      bits &= ~(1u << src.bit);
    else
      bits |= 1u << src.bit;
  }
  return static_cast<std::uint8_t>(bits);
}

void EmulatorEngine::executeMark3(const std::string& c, Micros now) {
  if (c.size() >= 2 && c[0] >= 'A' && c[0] <= 'H') {
    EmulatedMotor& m = *motor(c[0]);
    long n = 0;
    if (c.size() == 2 && c[1] == '?') {
      const int r = config_.settings.signedRemaining ? std::clamp(m.registerSteps, -32, 95)
                                                     : std::min(std::abs(m.registerSteps), 95);
      reply(std::string(1, static_cast<char>(32 + r)), now);
    } else if (c.size() == 2 && c[1] == 'X') {
      m.registerSteps = 0;
      m.carry = 0;
    } else if ((c[1] == '+' || c[1] == '-') && c.size() <= 6 && parseLong(c.substr(1), n)) {
      const long sum = m.registerSteps + n;
      if (sum < -128 || sum > 127) {
        m.registerSteps = static_cast<std::int8_t>(static_cast<std::uint8_t>(sum & 0xFF));
        event(fmt::format("motor {}: the move register overflowed ({} steps): it wrapped to {}", m.letter, sum,
                          m.registerSteps));
      } else {
        m.registerSteps = static_cast<int>(sum);
      }
    } else {
      event(fmt::format("unknown command \"{}\" (ignored)", c));
    }
    return;
  }
  const auto setOutput = [&](int line, bool on) {
    const auto bit = static_cast<std::uint8_t>(1u << (line - 1));
    outputs_ = on ? static_cast<std::uint8_t>(outputs_ | bit) : static_cast<std::uint8_t>(outputs_ & ~bit);
    event(fmt::format("output {} {}", line, on ? "ON" : "OFF"));
  };
  long d = 0;
  if (c == "I" || c == "J" || c == "K")
    reply(std::string(1, static_cast<char>(32 + inquiryBits(c[0]))), now);
  else if (c == "L")
    setOutput(1, true);
  else if (c == "M")
    setOutput(1, false);
  else if (c == "N")
    setOutput(2, true);
  else if (c == "O")
    setOutput(2, false);
  else if (c.size() > 1 && c[0] == 'P' && parseLong(c.substr(1), d) && d >= 0 && d <= 255) {
    const auto next = static_cast<std::uint8_t>((outputs_ & 0x03) | (d & 0xFC));
    for (int line = 3; line <= kControllerLines; ++line)
      if (((next ^ outputs_) >> (line - 1)) & 1) setOutput(line, (next >> (line - 1)) & 1);
  } else if (c == "Q") {
    for (EmulatedMotor& m : motors_) m.registerSteps = 0;
    outputs_ = 0;
    event("reset (Q): motors stopped, outputs off");
  } else {
    event(fmt::format("unknown command \"{}\" (ignored)", c));
  }
}

void EmulatorEngine::mark4Error(int code, std::string_view why) {
  if (errors_.size() < 16) errors_.push_back(code);
  event(fmt::format("error {}: {}", code, why));
}

void EmulatorEngine::executeMark4(const std::string& c, Micros now) {
  const std::vector<std::string> p = splitCommas(c);
  const std::string& name = p[0];
  const auto motorArg = [&](std::size_t i) -> EmulatedMotor* {
    if (p.size() <= i) return mark4Error(12, fmt::format("{}: missing motor", c)), nullptr;
    if (p[i].size() != 1 || !motor(p[i][0])) return mark4Error(92, fmt::format("{}: invalid motor", c)), nullptr;
    return motor(p[i][0]);
  };
  const auto numberArg = [&](std::size_t i, long lo, long hi, long& v) {
    if (p.size() <= i) return mark4Error(12, fmt::format("{}: missing parameter", c)), false;
    if (!parseLong(p[i], v) || v < lo || v > hi) return mark4Error(11, fmt::format("{}: out of bounds", c)), false;
    return true;
  };
  long v = 0;
  long s = 0;
  if (name == "TH") {
    hostMode_ = true;
  } else if (name == "HH") {
    for (EmulatedMotor& m : motors_) {
      if (m.forcedSwitch && !*m.forcedSwitch) {
        for (EmulatedMotor& other : motors_) other.running = false;
        mark4Error(50, "hard home failed");
        mark4Error(60 + (m.letter - 'A'), fmt::format("limit switch {} not found", m.letter));
        return;
      }
      m.destination = 0;
      m.running = m.position != 0;
    }
    homing_ = true;
    event("hard home started");
  } else if (name == "PD" || name == "PR") {
    EmulatedMotor* m = motorArg(1);
    if (m && numberArg(2, -kMark4Limit, kMark4Limit, v)) {
      const long d = name == "PD" ? v : m->position + v;
      if (d < -kMark4Limit || d > kMark4Limit)
        mark4Error(11, fmt::format("{}: destination out of bounds", c));
      else
        m->destination = static_cast<std::int32_t>(d);
    }
  } else if (name == "MS") {
    if (EmulatedMotor* m = motorArg(1)) m->running = m->destination != m->position;
  } else if (name == "MI" || name == "MC") {
    for (EmulatedMotor& m : motors_) m.running = m.destination != m.position;
  } else if (name == "MM") {
    if (EmulatedMotor* m = motorArg(1)) m->running = false, m->destination = m->position;
  } else if (name == "MA") {
    for (EmulatedMotor& m : motors_) m.running = false, m.destination = m.position;
    homing_ = false;
  } else if (name == "PA") {
    if (EmulatedMotor* m = motorArg(1)) replyNumber(m->position, now);
  } else if (name == "SA") {
    long busy = 0;
    for (int i = 0; i < kEmulatedMotors; ++i)
      if (motors_[static_cast<std::size_t>(i)].running) busy |= 1L << i;
    replyNumber(busy, now);
  } else if (name == "RL") {
    long closed = 0;
    for (int i = 0; i < kEmulatedMotors; ++i)
      if (switchClosed(static_cast<char>('A' + i))) closed |= 1L << i;
    replyNumber(closed, now);
  } else if (name == "IP") {
    replyNumber(config_.settings.inputsActiveLow ? (~inputs_ & 0xFF) : inputs_, now);
  } else if (name == "IB") {
    if (numberArg(1, 1, kControllerLines, v)) replyNumber(((inputs_ >> (v - 1)) & 1) != config_.settings.inputsActiveLow, now);
  } else if (name == "OB") {
    if (numberArg(1, 1, kControllerLines, v) && numberArg(2, 0, 1, s)) {
      const auto bit = static_cast<std::uint8_t>(1u << (v - 1));
      outputs_ = s ? static_cast<std::uint8_t>(outputs_ | bit) : static_cast<std::uint8_t>(outputs_ & ~bit);
      event(fmt::format("output {} {}", v, s ? "ON" : "OFF"));
    }
  } else if (name == "OP") {
    if (numberArg(1, 0, 255, v)) {
      outputs_ = static_cast<std::uint8_t>(v);
      event(fmt::format("output port {}", v));
    }
  } else if (name == "GC" || name == "GO") {
    EmulatedMotor& a = motors_[0];
    std::int32_t target = 0;
    for (const vm::MotorSpec& spec : config_.motors)
      if (spec.letter == 'A') target = name == "GC" ? spec.max : spec.min;
    a.destination = target;
    a.running = a.destination != a.position;
  } else if (name == "GS") {
    replyNumber(motors_[0].position > 0 ? 1 : 0, now);
  } else if (name == "SE") {
    long code = 0;
    if (!errors_.empty()) {
      code = errors_.back();
      errors_.pop_back();
    }
    replyNumber(code, now);
  } else {
    mark4Error(10, fmt::format("invalid command \"{}\"", c));
  }
}

}  // namespace rs::rhino
