// libFuzzer target: the debug adapter's message reader. Any bytes from a
// client go through the Content-Length framing (cut as a pipe cuts them,
// chunked_frames.h) to readMessage(), and what the adapter does not handle
// (a framing problem, a body that is not JSON, a message without a type, a
// request without a command, a client's response or event) goes to an
// Adapter, which must answer each bad message with exactly one response
// with success false and ignore the client's responses and events.
// Nothing is handled past the reader: fuzz_dap runs whole debugging
// sessions, far slower; this target is the one a ten-million-input
// campaign can cover.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

#include "chunked_frames.h"
#include "tools/dap/adapter.h"
#include "tools/dap/message_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using rs::dap::IncomingMessage;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::ostringstream log;
  std::size_t answers = 0;
  rs::dap::Adapter adapter(
      [&](const rs::wire::Json& reply) {
        if (reply.value("type", "") != "response" || reply.value("success", true)) std::abort();
        (void)rs::wire::dumpJson(reply);
        ++answers;
        return true;
      },
      log);
  std::size_t invalid = 0;
  for (const rs::wire::Frame& f : fuzz::chunkedFrames(bytes, fuzz::maxBodyFor(size))) {
    const IncomingMessage m = rs::dap::readMessage(f);
    if (m.kind == IncomingMessage::Kind::Request) {
      if (!m.message.is_object() || !m.message["command"].is_string()) std::abort();
      continue;
    }
    if (m.kind == IncomingMessage::Kind::Invalid) {
      if (m.problem.empty()) std::abort();
      ++invalid;
    }
    adapter.receive(f);
  }
  if (answers != invalid) std::abort();
  return 0;
}
