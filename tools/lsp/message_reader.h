// What the server makes of one frame before it acts on it: a request, a
// notification, a client's response (ignored), or something it answers
// with a JSON-RPC error (a framing problem, a body that is not JSON, a
// message that is not a JSON-RPC object). Bytes that are not UTF-8 become
// U+FFFD, so the JSON can be read and the document still shows where they
// were. The server's only reader of untrusted bytes above the framing, and
// a pure function: the fuzz target fuzz_lsp_reader drives it.
#pragma once

#include <string>

#include "tools/lsp/dispatcher.h"
#include "tools/lsp/json.h"
#include "tools/lsp/jsonrpc.h"

namespace rs::lsp {

struct IncomingMessage {
  enum class Kind { Request, Notification, Response, Invalid };
  Kind kind = Kind::Invalid;
  Json id;              ///< Request: its id; Invalid: the id to answer (null when none could be read)
  std::string method;   ///< Request, Notification
  Json params;          ///< Request, Notification: null when absent
  bool invalidUtf8 = false;
  RpcError error;       ///< Invalid: the answer
};

IncomingMessage readMessage(const Frame& frame);

}  // namespace rs::lsp
