// What the adapter makes of one frame before it acts on it: a request, a
// client's response or event (nothing to do), or something it answers
// with success false (a framing problem, a body that is not JSON, a
// message without a type, a request without a command). The adapter's
// only reader of untrusted bytes above the framing, and a pure function:
// the fuzz target fuzz_dap_reader drives it.
#pragma once

#include <string>

#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace rs::dap {

struct IncomingMessage {
  enum class Kind { Request, Other, Invalid };
  Kind kind = Kind::Invalid;
  wire::Json message;   ///< Request: the request; Invalid: what to answer (its seq and command), or null
  std::string problem;  ///< Invalid: the answer's message
};

IncomingMessage readMessage(const wire::Frame& frame);

}  // namespace rs::dap
