#include "runtime/serial/emulator.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "runtime/serial/serial_port.h"

namespace rs::serial {
namespace {

constexpr std::size_t kMaxCommand = 256;
constexpr std::size_t kMaxKept = 100'000;
constexpr int kMark4Limit = 32767;
// Line noise: the first byte is outside every valid answer of both dialects.
constexpr std::string_view kGarbage = "\x15~?\r";

std::string upper(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (c != ' ' && c != '\t') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

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
  if (line < 1 || line > 8) return;
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

// I, J, K: 32 + six bits; a closed switch or (active low) an ON input is 0.
std::uint8_t EmulatorEngine::inquiryBits(char command) const {
  unsigned bits = 0x3F;
  const RhinoSettings& s = config_.settings;
  for (int i = 0; i < kEmulatedMotors; ++i) {
    const BitSource& src = s.switches[static_cast<std::size_t>(i)];
    if (src.command == command && switchClosed(static_cast<char>('A' + i))) bits &= ~(1u << src.bit);
  }
  for (int line = 0; line < 8; ++line) {
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
    for (int line = 3; line <= 8; ++line)
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
    if (numberArg(1, 1, 8, v)) replyNumber(((inputs_ >> (v - 1)) & 1) != config_.settings.inputsActiveLow, now);
  } else if (name == "OB") {
    if (numberArg(1, 1, 8, v) && numberArg(2, 0, 1, s)) {
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
    for (int i = 0; i < 8; ++i) s += ((mask >> i) & 1) ? static_cast<char>('1' + i) : '.';
    return s;
  };
  line += fmt::format(" | out {} | in {} | {} cmds", lines(outputs_), lines(inputs_), commands_);
  if (config_.fault.kind != FaultKind::None)
    line += fmt::format(" | fault {}{}", faultName(config_.fault.kind), faultActive() ? " ACTIVE" : " armed");
  return line;
}

// --- on a pseudo-terminal -------------------------------------------------------

std::unique_ptr<PtyEmulator> PtyEmulator::open(EmulatorConfig config, std::string& error) {
  int master = -1;
  int slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    error = fmt::format("cannot create a pseudo-terminal: {}", std::strerror(errno));
    return nullptr;
  }
  char name[256] = {};
  if (::ttyname_r(slave, name, sizeof name) != 0) {
    error = fmt::format("cannot name the pseudo-terminal: {}", std::strerror(errno));
    ::close(master);
    ::close(slave);
    return nullptr;
  }
  if (std::string e = configureTerminal(slave, config.settings.line); !e.empty()) {
    error = fmt::format("cannot configure the pseudo-terminal: {}", e);
    ::close(master);
    ::close(slave);
    return nullptr;
  }
  ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
  ::fcntl(master, F_SETFD, FD_CLOEXEC);
  ::fcntl(slave, F_SETFD, FD_CLOEXEC);
  return std::unique_ptr<PtyEmulator>(new PtyEmulator(std::move(config), master, slave, name));
}

PtyEmulator::PtyEmulator(EmulatorConfig config, int master, int slave, std::string path)
    : engine_(std::move(config)), master_(master), slave_(slave), path_(std::move(path)) {}

PtyEmulator::~PtyEmulator() {
  stop();
  hangUp();
}

void PtyEmulator::hangUp() {
  if (master_ >= 0) ::close(master_);
  if (slave_ >= 0) ::close(slave_);
  master_ = slave_ = -1;
}

bool PtyEmulator::pump(Micros wait, int extraFd) {
  Micros timeout = std::max<Micros>(wait, 0);
  {
    std::lock_guard lock(mutex_);
    if (auto due = engine_.nextReplyAt()) timeout = std::clamp<Micros>(*due - clock_.now(), 0, timeout);
  }
  pollfd fds[2] = {{master_, POLLIN, 0}, {extraFd, POLLIN, 0}};
  const int n = ::poll(fds, 2, static_cast<int>((timeout + 999) / 1000));
  bool extra = false;
  if (n > 0) extra = extraFd >= 0 && (fds[1].revents & (POLLIN | POLLHUP)) != 0;
  std::lock_guard lock(mutex_);
  if (master_ >= 0 && n > 0 && (fds[0].revents & POLLIN)) {
    std::uint8_t buf[512];
    for (;;) {
      const ssize_t got = ::read(master_, buf, sizeof buf);
      if (got <= 0) break;
      engine_.receive({buf, static_cast<std::size_t>(got)}, clock_.now());
    }
  }
  engine_.advance(clock_.now());
  const std::vector<std::uint8_t> out = engine_.takeReplies(clock_.now());
  std::size_t done = 0;
  while (master_ >= 0 && done < out.size()) {
    const ssize_t w = ::write(master_, out.data() + done, out.size() - done);
    if (w > 0)
      done += static_cast<std::size_t>(w);
    else if (w < 0 && errno == EINTR)
      continue;
    else
      break;  // the host is not reading: the answer is lost, as on a real line
  }
  if (engine_.hungUp()) hangUp();
  return extra;
}

void PtyEmulator::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] {
    while (running_) pump(2'000);
  });
}

void PtyEmulator::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

bool PtyEmulator::hungUp() const {
  std::lock_guard lock(mutex_);
  return engine_.hungUp();
}

void PtyEmulator::setInput(int line, bool on) {
  std::lock_guard lock(mutex_);
  engine_.setInput(line, on);
}

void PtyEmulator::forceSwitch(char letter, std::optional<bool> closed) {
  std::lock_guard lock(mutex_);
  engine_.forceSwitch(letter, closed);
}

void PtyEmulator::setFault(FaultPlan plan) {
  std::lock_guard lock(mutex_);
  engine_.setFault(plan);
}

EmulatorSnapshot PtyEmulator::snapshot() {
  std::lock_guard lock(mutex_);
  engine_.advance(clock_.now());
  return engine_.snapshot();
}

std::vector<std::string> PtyEmulator::received() {
  std::lock_guard lock(mutex_);
  return {engine_.received().begin(), engine_.received().end()};
}

std::vector<std::string> PtyEmulator::receivedSince(std::uint64_t& seen) {
  std::lock_guard lock(mutex_);
  return engine_.receivedSince(seen);
}

std::vector<std::string> PtyEmulator::takeEvents() {
  std::lock_guard lock(mutex_);
  return engine_.takeEvents();
}

std::string PtyEmulator::statusLine() {
  std::lock_guard lock(mutex_);
  engine_.advance(clock_.now());
  return engine_.statusLine();
}

// --- in-process, on a manual clock ------------------------------------------------

LoopbackLink::LoopbackLink(EmulatorEngine& engine, ManualClock& clock) : engine_(engine), clock_(clock) {
  const LineSettings& line = engine.config().settings.line;
  const int bits = 1 + line.dataBits + (line.parity == Parity::None ? 0 : 1) + line.stopBits;
  byteTime_ = std::max<Micros>(1, Micros{bits} * 1'000'000 / line.baud);
}

IoResult LoopbackLink::write(std::span<const std::uint8_t> bytes, Micros) {
  if (engine_.hungUp()) return IoResult::closed("emulator: the port hung up");
  clock_.sleepFor(byteTime_ * static_cast<Micros>(bytes.size()));
  engine_.receive(bytes, clock_.now());
  return IoResult::ok(bytes.size());
}

IoResult LoopbackLink::read(std::span<std::uint8_t> buffer, Micros timeout) {
  if (pending_.empty()) {
    if (engine_.hungUp()) return IoResult::closed("emulator: the port hung up");
    const std::optional<Micros> due = engine_.nextReplyAt();
    if (!due || *due > clock_.now() + timeout) {
      clock_.sleepFor(timeout);
      return IoResult::timeout();
    }
    clock_.advanceTo(*due);
    const std::vector<std::uint8_t> bytes = engine_.takeReplies(clock_.now());
    pending_.insert(pending_.end(), bytes.begin(), bytes.end());
  }
  const std::size_t n = std::min(buffer.size(), pending_.size());
  std::copy_n(pending_.begin(), n, buffer.begin());
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  return IoResult::ok(n);
}

}  // namespace rs::serial
