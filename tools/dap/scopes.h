// The scopes' variablesReference numbers: fixed, the run has one frame of
// globals whatever the call depth (inspect.cpp lists them; setVariable and
// the data breakpoints name variables by them).
#pragma once

namespace rs::dap {

enum Scope : int { kVariables = 1, kMotors, kIo, kObjects, kClock, kDevices };

}  // namespace rs::dap
