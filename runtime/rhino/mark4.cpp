// The Mark IV dialect (docs/serial.md, "Mark IV"): two-letter commands with
// comma-separated parameters; only queries answer, with a decimal number and
// CR. Moves are absolute (PD) and started together (MI or MC); SA is polled
// until 0; PA reads each motor's encoder back; SE empties the error stack.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "base/seconds.h"
#include "runtime/rhino/controller_session.h"

namespace rs::rhino {
namespace {

using vm::Status;

constexpr std::int32_t kMaxDestination = 32767;

// The Mark IV error codes (MarkCommander's list) a run is likely to meet.
std::string errorMeaning(long code) {
  switch (code) {
    case 10: return "invalid command";
    case 11: return "parameter out of bounds";
    case 12: return "missing parameter";
    case 13: return "expected delimiter not seen";
    case 14: return "command string too long";
    case 20: return "host input buffer overflow";
    case 21: return "host USART timed out";
    case 22: return "framing or parity error: check the line settings";
    case 27: return "host USART overrun";
    case 50: return "hard home routine failed";
    case 51: return "hard home not set";
    case 56: return "still executing a move";
    case 57: return "inactive motor referenced";
    case 58: return "insufficient move data (velocity or acceleration = 0)";
    case 92: return "invalid motor specifier";
    case 95: return "emergency stop";
    default: break;
  }
  if (code >= 60 && code <= 67) return fmt::format("limit switch {} not found", static_cast<char>('A' + code - 60));
  if (code >= 80 && code <= 87) return fmt::format("limit switch {} stuck", static_cast<char>('A' + code - 80));
  if (code >= 100 && code <= 107) return fmt::format("motor {} stalled", static_cast<char>('A' + code - 100));
  if (code >= 110 && code <= 117)
    return fmt::format("motor {}'s current limit circuit was activated", static_cast<char>('A' + code - 110));
  return "see the Mark IV manual";
}

class Mark4 final : public Controller {
 public:
  Mark4(ControllerSession& session, const std::vector<vm::MotorSpec>& motors)
      : s_(session), cfg_(session.settings()), motors_(motors) {}

  Status begin(std::span<std::int32_t> positions) override {
    if (std::string e = unsupportedMotor(Dialect::Mark4, motors_); !e.empty()) return Status::fault(e);
    if (auto st = s_.send("TH"); !st) return st;
    // Old errors are not ours: empty the stack (it holds a few at most).
    for (int k = 0;; ++k) {
      long code = 0;
      if (auto st = s_.queryNumber("SE", code); !st) return st;
      if (code == 0) break;
      s_.note(fmt::format("old controller error {} ({}) cleared", code, errorMeaning(code)));
      if (k == 16) return Status::fault("the controller's error stack does not empty (SE keeps answering errors)");
    }
    return readPositions(positions, nullptr);
  }

  Status readPositions(std::span<std::int32_t> positions) override { return readPositions(positions, nullptr); }

  std::string refuse(std::span<const std::int32_t> targets) const override {
    for (std::size_t i = 0; i < targets.size(); ++i)
      if (std::abs(targets[i]) > kMaxDestination)
        return fmt::format("motor {} target {} is beyond what a Mark IV accepts (-32767..32767)", motors_[i].letter,
                           targets[i]);
    return {};
  }

  Status move(std::span<const std::int32_t> targets, std::span<std::int32_t> positions) override {
    std::vector<bool> moving(motors_.size(), false);
    for (std::size_t i = 0; i < motors_.size(); ++i) {
      if (targets[i] == positions[i]) continue;
      moving[i] = true;
      if (auto st = s_.send(fmt::format("PD,{},{}", motors_[i].letter, targets[i])); !st) return st;
    }
    if (std::none_of(moving.begin(), moving.end(), [](bool b) { return b; })) return Status::ok();
    if (auto st = s_.send(cfg_.coordinated ? "MC" : "MI"); !st) return st;
    if (auto st = waitIdle(positions, &moving, cfg_.stallTimeout, "move"); !st) return st;
    if (auto st = checkErrors("the move"); !st) return st;
    if (auto st = readPositions(positions, &moving); !st) return st;
    for (std::size_t i = 0; i < motors_.size(); ++i)
      if (moving[i] && std::abs(std::int64_t{positions[i]} - targets[i]) > cfg_.tolerance)
        return Status::fault(fmt::format("motor {} stopped at {}, not at its target {} (tolerance {})",
                                         motors_[i].letter, positions[i], targets[i], cfg_.tolerance));
    return Status::ok();
  }

  Status home(std::span<std::int32_t> positions) override {
    if (auto st = s_.send("HH"); !st) return st;
    if (auto st = waitIdle(positions, nullptr, cfg_.homeTimeout, "HRDHOME"); !st) return st;
    if (auto st = checkErrors("HH"); !st) return st;
    if (auto st = readPositions(positions, nullptr); !st) return st;
    for (std::size_t i = 0; i < motors_.size(); ++i)
      if (std::abs(positions[i]) > cfg_.tolerance)
        return Status::fault(
            fmt::format("after the hard home motor {} reads {}, not 0", motors_[i].letter, positions[i]));
    return Status::ok();
  }

  Status readInputs(vm::IoMask& mask) override {
    long v = 0;
    if (auto st = s_.queryNumber("IP", v); !st) return st;
    if (v < 0 || v > 255) return s_.garbage("IP", {}, fmt::format("an input port value 0..255, not {}", v));
    mask = static_cast<vm::IoMask>((cfg_.inputsActiveLow ? ~v : v) & 0xFF);  // the port is a byte
    return Status::ok();
  }

  Status writeOutput(int line, bool on, vm::IoMask) override {
    return s_.send(fmt::format("OB,{},{}", line, on ? 1 : 0));
  }

  std::string stopAll() override { return sendStop(s_, stopCommands(Dialect::Mark4, motors_)); }

 private:
  // SA until 0. A move with no change in the motors' read-back positions
  // for `limit` has stalled; HRDHOME (no motors given) only has a deadline.
  Status waitIdle(std::span<std::int32_t> positions, const std::vector<bool>* moving, Micros limit,
                  std::string_view what) {
    const Micros start = s_.now();
    Micros lastCheck = start;
    std::vector<std::int32_t> before(positions.begin(), positions.end());
    for (;;) {
      if (auto st = s_.pause(cfg_.pollInterval); !st) return st;
      long status = 0;
      if (auto st = s_.queryNumber("SA", status); !st) return st;
      if (status < 0) return s_.garbage("SA", {}, fmt::format("a motor status >= 0, not {}", status));
      if (status == 0) return Status::ok();
      if (s_.now() - (moving ? lastCheck : start) <= limit) continue;
      if (!moving) return Status::fault(fmt::format("{} took longer than {} s", what, base::formatSeconds(limit)));
      if (auto st = readPositions(positions, moving); !st) return st;
      if (std::equal(before.begin(), before.end(), positions.begin()))
        return Status::fault(fmt::format("the {} stalled: no motor moved for {} s (SA still {})", what,
                                         base::formatSeconds(limit), status));
      before.assign(positions.begin(), positions.end());
      lastCheck = s_.now();
    }
  }

  Status checkErrors(std::string_view after) {
    if (!cfg_.checkErrors) return Status::ok();
    long code = 0;
    if (auto st = s_.queryNumber("SE", code); !st) return st;
    if (code == 0) return Status::ok();
    return Status::fault(fmt::format("controller error {} ({}) after {}", code, errorMeaning(code), after));
  }

  Status readPositions(std::span<std::int32_t> positions, const std::vector<bool>* only) {
    for (std::size_t i = 0; i < motors_.size(); ++i) {
      if (only && !(*only)[i]) continue;
      const std::string q = fmt::format("PA,{}", motors_[i].letter);
      long v = 0;
      if (auto st = s_.queryNumber(q, v); !st) return st;
      if (v < -kMaxDestination - 1 || v > kMaxDestination)
        return s_.garbage(q, {}, fmt::format("a position -32768..32767, not {}", v));
      positions[i] = static_cast<std::int32_t>(v);
    }
    return Status::ok();
  }

  ControllerSession& s_;
  const RhinoSettings& cfg_;
  std::vector<vm::MotorSpec> motors_;
};

}  // namespace

std::unique_ptr<Controller> makeMark4(ControllerSession& session, const std::vector<vm::MotorSpec>& motors) {
  return std::make_unique<Mark4>(session, motors);
}

}  // namespace rs::rhino
