// libFuzzer target: any replies from a Rhino controller. A link in place of
// the serial port answers each command the backend writes with the next
// record of the input (a length byte, then that many bytes); a manual clock
// makes every timeout instant. The backend must turn whatever comes back
// into a fault with a message (and stop), never crash or loop forever. The
// first byte picks the dialect (Mark III or Mark IV).
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "launch/program.h"
#include "runtime/rhino/link.h"
#include "runtime/rhino/rhino_machine.h"
#include "runtime/rhino/settings.h"

namespace {

class ReplayLink final : public rs::rhino::Link {
 public:
  ReplayLink(std::span<const std::uint8_t> replies, rs::rhino::ManualClock& clock) : rest_(replies), clock_(clock) {}

  rs::vm::Status write(std::span<const std::uint8_t> bytes, rs::rhino::Micros) override {
    // One reply per command line: the next record becomes readable.
    if (!bytes.empty() && (bytes.back() == '\r' || bytes.back() == '\n') && !rest_.empty()) {
      const std::size_t n = std::min<std::size_t>(rest_[0], rest_.size() - 1);
      pending_.insert(pending_.end(), rest_.begin() + 1, rest_.begin() + 1 + static_cast<std::ptrdiff_t>(n));
      rest_ = rest_.subspan(1 + n);
    }
    return rs::vm::Status::ok();
  }

  rs::vm::Status read(std::span<std::uint8_t> buffer, rs::rhino::Micros timeout, std::size_t& count) override {
    count = 0;
    if (pending_.empty()) {
      if (rest_.empty() && timeout > 0 && ++idle_ > 1000) return rs::vm::Status::closed("end of the fuzz input");
      clock_.sleepFor(timeout);
      return rs::vm::Status::timeout();
    }
    const std::size_t n = std::min(buffer.size(), pending_.size());
    std::copy_n(pending_.begin(), n, buffer.begin());
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
    count = n;
    return rs::vm::Status::ok();
  }

  std::string name() const override { return "fuzz"; }

 private:
  std::span<const std::uint8_t> rest_;
  rs::rhino::ManualClock& clock_;
  std::vector<std::uint8_t> pending_;
  int idle_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const std::vector<rs::vm::MotorSpec> motors = rs::launch::defaultTarget().motors;
  const auto dialect = (data[0] & 1) ? rs::rhino::Dialect::Mark4 : rs::rhino::Dialect::Mark3;
  rs::rhino::ManualClock clock;
  ReplayLink link(std::span(data + 1, size - 1), clock);
  rs::rhino::RhinoMachine machine(motors, rs::rhino::defaultSettings(dialect), link, clock);
  if (!machine.open()) return 0;
  std::vector<std::int32_t> target;
  for (const rs::vm::MotorSpec& m : motors) target.push_back(m.min + (m.max - m.min) / 3);
  (void)machine.moveTo(target);
  (void)machine.setOutput(1, true);
  (void)machine.input(2);
  (void)machine.waitFor(3, true);
  (void)machine.delay(100'000);
  (void)machine.hardHome();
  (void)machine.reset();
  return 0;
}
