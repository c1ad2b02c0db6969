#include <chrono>
#include <thread>

#include "runtime/rhino/link.h"

namespace rs::rhino {
std::int64_t steadyMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

SteadyClock::SteadyClock() : origin_(steadyMicros()) {}

Micros SteadyClock::now() const { return steadyMicros() - origin_; }

void SteadyClock::sleepFor(Micros duration) {
  if (duration > 0) std::this_thread::sleep_for(std::chrono::microseconds(duration));
}

}  // namespace rs::rhino
