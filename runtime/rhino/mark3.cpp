// The Mark III dialect (docs/serial.md, "Mark III"): relative moves of at
// most a signed byte, fed in chunks; completion by polling "<m>?"; home
// switches read through the I/J/K inquiries; "<m>X" stops a motor. The
// controller cannot report positions: they are tracked from the steps it
// reports done, starting from 0 (the arm is at home when the run starts).
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "base/seconds.h"
#include "runtime/rhino/controller_session.h"

namespace rs::rhino {
namespace {

using vm::Status;

// The register holds a signed byte (-128..127) [S], but one 7-bit answer
// byte can only report 32 + 0..95 steps: never have more to go than that.
constexpr int kReportable = 95;
constexpr int kSignedReportableMin = -32;  // remaining=signed: 0x00 is 32 steps back

// One motor during a move: steps not yet sent, steps sent and not yet done
// (the controller's register, as we believe it), when it last progressed.
struct Track {
  std::int64_t left = 0;
  int outstanding = 0;
  Micros lastProgress = 0;
  bool active = false;
};

class Mark3 final : public Controller {
 public:
  Mark3(ControllerSession& session, const std::vector<vm::MotorSpec>& motors)
      : s_(session), cfg_(session.settings()), motors_(motors) {}

  Status begin(std::span<std::int32_t>) override {
    if (std::string e = unsupportedMotor(Dialect::Mark3, motors_); !e.empty()) return Status::fault(e);
    // First contact: the switch inquiry must answer one good byte.
    std::uint8_t bits = 0;
    return readBits('I', bits);
  }

  std::string refuse(std::span<const std::int32_t>) const override { return {}; }

  // The Mark III reports steps done, not positions: the host's tracked counts stay.
  Status readPositions(std::span<std::int32_t>) override { return Status::ok(); }

  Status move(std::span<const std::int32_t> targets, std::span<std::int32_t> positions) override {
    std::vector<Track> tracks(motors_.size());
    const Micros start = s_.now();
    for (std::size_t i = 0; i < motors_.size(); ++i) {
      tracks[i].left = std::int64_t{targets[i]} - positions[i];
      tracks[i].active = tracks[i].left != 0;
      tracks[i].lastProgress = start;
      if (tracks[i].active)
        if (auto st = sendChunk(i, tracks[i]); !st) return st;
    }
    for (;;) {
      if (std::none_of(tracks.begin(), tracks.end(), [](const Track& t) { return t.active; })) return Status::ok();
      if (auto st = s_.pause(cfg_.pollInterval); !st) return st;
      for (std::size_t i = 0; i < motors_.size(); ++i) {
        Track& t = tracks[i];
        if (!t.active) continue;
        if (auto st = poll(i, t); !st) return st;
        positions[i] = static_cast<std::int32_t>(targets[i] - t.left - t.outstanding);
        if (t.left != 0 && std::abs(t.outstanding) < cfg_.refill)
          if (auto st = sendChunk(i, t); !st) return st;
        if (t.left == 0 && t.outstanding == 0)
          t.active = false;
        else if (s_.now() - t.lastProgress > cfg_.stallTimeout)
          return stalled(i, t);
      }
    }
  }

  Status home(std::span<std::int32_t> positions) override {
    const Micros deadline = s_.now() + cfg_.homeTimeout;
    for (const std::size_t i : homeOrder()) {
      if (auto st = homeOne(i, positions, deadline); !st) return st;
    }
    return Status::ok();
  }

  Status readInputs(vm::IoMask& mask) override {
    vm::IoMask result = 0;
    for (const char command : {'I', 'J', 'K'}) {
      bool used = false;
      for (const BitSource& b : cfg_.inputs) used = used || b.command == command;
      if (!used) continue;
      std::uint8_t bits = 0;
      if (auto st = readBits(command, bits); !st) return st;
      for (int line = 1; line <= vm::kIoCount; ++line) {
        const BitSource& b = cfg_.inputs[static_cast<std::size_t>(line - 1)];
        if (b.command != command) continue;
        const bool high = ((bits >> b.bit) & 1) != 0;
        if (high != cfg_.inputsActiveLow) result = vm::withLine(result, line, true);
      }
    }
    mask = result;
    return Status::ok();
  }

  Status writeOutput(int line, bool on, vm::IoMask mask) override {
    const std::size_t i = static_cast<std::size_t>(line - 1);
    const std::string& tmpl = on ? cfg_.outputOn[i] : cfg_.outputOff[i];
    if (tmpl.empty())
      return Status::fault(fmt::format("output {} has no Mark III command to turn it {} (setting output.{}.{})", line,
                                       on ? "ON" : "OFF", line, on ? "on" : "off"));
    std::string command;
    for (std::size_t k = 0; k < tmpl.size(); ++k) {
      if (tmpl.compare(k, 3, "{n}") == 0) {
        command += std::to_string(line);
        k += 2;
      } else if (tmpl.compare(k, 6, "{port}") == 0) {
        command += std::to_string(mask);
        k += 5;
      } else {
        command += tmpl[k];
      }
    }
    return s_.send(command);
  }

  std::string stopAll() override { return sendStop(s_, stopCommands(Dialect::Mark3, motors_)); }

 private:
  // The next chunk, kept so that the register (steps still to go plus the
  // new ones) stays within a signed byte and within what "m?" can report.
  Status sendChunk(std::size_t i, Track& t) {
    std::int64_t c = std::clamp<std::int64_t>(t.left, -cfg_.chunk, cfg_.chunk);
    const int lowest = cfg_.signedRemaining ? kSignedReportableMin : -kReportable;
    c = std::clamp<std::int64_t>(c, lowest - t.outstanding, kReportable - t.outstanding);
    if (c == 0) return Status::ok();
    if (auto st = s_.send(fmt::format("{}{:+d}", motors_[i].letter, c)); !st) return st;
    t.left -= c;
    t.outstanding += static_cast<int>(c);
    return Status::ok();
  }

  // "<m>?": the steps of the current move not yet done.
  Status poll(std::size_t i, Track& t) {
    const std::string command = fmt::format("{}?", motors_[i].letter);
    std::uint8_t b = 0;
    if (auto st = s_.queryByte(command, b); !st) return st;
    int remaining = 0;
    if (cfg_.signedRemaining) {
      if (b > 0x7F) return s_.garbage(command, {&b, 1}, "one byte 0x00..0x7F: 32 + the signed steps to go");
      remaining = static_cast<int>(b) - 32;
    } else {
      if (b < 0x20 || b > 0x7F) return s_.garbage(command, {&b, 1}, "one byte 0x20..0x7F: 32 + the steps to go");
      remaining = (static_cast<int>(b) - 32) * (t.outstanding < 0 ? -1 : 1);
    }
    const bool sameWay = remaining == 0 || (remaining < 0) == (t.outstanding < 0);
    if (!sameWay || std::abs(remaining) > std::abs(t.outstanding))
      return s_.garbage(command, {&b, 1}, fmt::format("at most {} steps to go, as sent", std::abs(t.outstanding)));
    if (remaining != t.outstanding) t.lastProgress = s_.now();
    t.outstanding = remaining;
    return Status::ok();
  }

  Status stalled(std::size_t i, const Track& t) {
    return Status::fault(fmt::format("motor {} stalled: {} steps still to go and no progress for {} s",
                                     motors_[i].letter, std::abs(t.left + t.outstanding),
                                     base::formatSeconds(cfg_.stallTimeout)));
  }

  // I, J or K: one byte, 32 + six bits.
  Status readBits(char command, std::uint8_t& bits) {
    const std::string q(1, command);
    std::uint8_t b = 0;
    if (auto st = s_.queryByte(q, b); !st) return st;
    if (b < 0x20 || b > 0x5F) return s_.garbage(q, {&b, 1}, "one byte 0x20..0x5F: 32 + six switch bits");
    bits = static_cast<std::uint8_t>(b - 0x20);
    return Status::ok();
  }

  Status switchClosed(std::size_t i, bool& closed) {
    const BitSource& src = cfg_.switches[static_cast<std::size_t>(motors_[i].letter - 'A')];
    std::uint8_t bits = 0;
    if (auto st = readBits(src.command, bits); !st) return st;
    closed = ((bits >> src.bit) & 1) == 0;  // a 0 bit: the switch is closed [S/I]
    return Status::ok();
  }

  std::vector<std::size_t> homeOrder() const {
    std::vector<std::size_t> order;
    if (cfg_.homeOrder.empty()) {
      for (std::size_t i = 0; i < motors_.size(); ++i) order.push_back(i);
      return order;
    }
    for (const char c : cfg_.homeOrder)
      for (std::size_t i = 0; i < motors_.size(); ++i)
        if (motors_[i].letter == c) order.push_back(i);
    for (std::size_t i = 0; i < motors_.size(); ++i)  // motors the order forgot, last
      if (cfg_.homeOrder.find(motors_[i].letter) == std::string::npos) order.push_back(i);
    return order;
  }

  // One motor: step towards its switch (towards 0 as tracked), poll the
  // switch until it reads closed, then "<m>X"; that place is encoder 0.
  Status homeOne(std::size_t i, std::span<std::int32_t> positions, Micros deadline) {
    const vm::MotorSpec& m = motors_[i];
    const BitSource& src = cfg_.switches[static_cast<std::size_t>(m.letter - 'A')];
    if (!src.wired()) {  // no switch: back to 0 as tracked
      std::vector<std::int32_t> targets(positions.begin(), positions.end());
      targets[i] = 0;
      return move(targets, positions);
    }
    bool closed = false;
    if (auto st = switchClosed(i, closed); !st) return st;
    const int direction = positions[i] > 0 ? -1 : positions[i] < 0 ? 1 : cfg_.homeDirection;
    const std::int64_t budget =
        cfg_.homeSearch > 0 ? cfg_.homeSearch : std::max<std::int64_t>(std::int64_t{m.max} - m.min, 1);
    Track t;
    t.left = direction * budget;
    t.lastProgress = s_.now();
    const std::int32_t from = positions[i];
    while (!closed) {
      if (t.left != 0 && std::abs(t.outstanding) < cfg_.refill)
        if (auto st = sendChunk(i, t); !st) return st;
      if (auto st = s_.pause(cfg_.pollInterval); !st) return st;
      if (auto st = poll(i, t); !st) return st;
      positions[i] = static_cast<std::int32_t>(from + direction * budget - t.left - t.outstanding);
      if (auto st = switchClosed(i, closed); !st) return st;
      if (closed) break;
      if (t.left == 0 && t.outstanding == 0)
        return Status::fault(fmt::format("motor {}: home switch not found within {} steps", m.letter, budget));
      if (s_.now() - t.lastProgress > cfg_.stallTimeout) return stalled(i, t);
      if (s_.now() > deadline)
        return Status::fault(
            fmt::format("HRDHOME took longer than {} s (motor {})", base::formatSeconds(cfg_.homeTimeout), m.letter));
    }
    if (auto st = s_.send(fmt::format("{}X", m.letter)); !st) return st;
    positions[i] = 0;
    return Status::ok();
  }

  ControllerSession& s_;
  const RhinoSettings& cfg_;
  std::vector<vm::MotorSpec> motors_;
};

}  // namespace

std::unique_ptr<Controller> makeMark3(ControllerSession& session, const std::vector<vm::MotorSpec>& motors) {
  return std::make_unique<Mark3>(session, motors);
}

}  // namespace rs::rhino
