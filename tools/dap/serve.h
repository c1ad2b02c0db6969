// `robotsim dap` on a byte stream: frames in (tools/wire/framing.h, the
// language server's framing), the adapter, frames out. While a run is
// going, the bytes that arrive are read between its slices, so a pause,
// terminate or disconnect stops it and a client that vanishes (the end of
// input) ends the process cleanly instead of leaving it running.
#pragma once

#include <ostream>

#include "tools/wire/transport.h"

namespace rs::dap {

/// Serves until disconnect or the end of input: 0 after disconnect, 1 when
/// the client left without one.
int serve(wire::Input& in, wire::Output& out, std::ostream& log);

}  // namespace rs::dap
