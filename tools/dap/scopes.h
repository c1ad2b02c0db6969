// The scopes' variablesReference numbers: fixed, the run has one frame of
// globals whatever the call depth (inspect.cpp lists them; setVariable and
// the data breakpoints name variables by them); a cell's carry their thread.
#pragma once

#include <cstdint>

namespace rs::dap {

enum Scope : int { kVariables = 1, kMotors, kIo, kObjects, kClock, kDevices };

/// On a cell of several robots a frame id and a scope's variablesReference
/// carry their thread: thread t's frame d is t * kCellPerThread + d, its
/// scope s t * kCellPerThread + s (cell_requests.cpp).
constexpr std::int64_t kCellPerThread = 1000;
enum CellScope : std::int64_t {
  kCellVariablesScope = 1,
  kCellMotorsScope,
  kCellIoScope,
  kCellClockScope,
  kCellDevicesScope,  ///< on a cell with devices
  kCellLastScope = kCellDevicesScope
};

}  // namespace rs::dap
