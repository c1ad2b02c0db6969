// libFuzzer target: the language server's message reader. Any bytes from
// an editor go through the Content-Length framing (cut as a pipe cuts
// them, chunked_frames.h) to readMessage(), and what the server does not
// handle (a framing problem, a body that is not JSON or not a JSON-RPC
// message, a client's response) goes to a Server, which must answer each
// bad message with exactly one JSON-RPC error and ignore responses.
// Nothing is handled past the reader: fuzz_lsp runs whole sessions, two
// orders of magnitude slower; this target is the one a ten-million-input
// campaign can cover.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

#include "chunked_frames.h"
#include "tools/lsp/message_reader.h"
#include "tools/lsp/server.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using rs::lsp::IncomingMessage;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::vector<rs::lsp::Frame> unhandled;
  std::size_t invalid = 0;
  for (const rs::lsp::Frame& f : fuzz::chunkedFrames(bytes, fuzz::maxBodyFor(size))) {
    const IncomingMessage m = rs::lsp::readMessage(f);
    switch (m.kind) {
      case IncomingMessage::Kind::Request:
        if (!m.id.is_string() && !m.id.is_number_integer()) std::abort();
        break;
      case IncomingMessage::Kind::Notification:
        if (!m.id.is_null()) std::abort();
        break;
      case IncomingMessage::Kind::Response:
        unhandled.push_back(f);
        break;
      case IncomingMessage::Kind::Invalid:
        if (m.error.message.empty() || m.error.code >= 0) std::abort();
        ++invalid;
        unhandled.push_back(f);
        break;
    }
  }
  std::ostringstream log;
  std::size_t answers = 0;
  rs::lsp::Server server(
      [&](const rs::lsp::Json& reply) {
        if (!reply.contains("error") || reply.contains("result")) std::abort();
        (void)rs::lsp::dumpJson(reply);
        ++answers;
        return true;
      },
      log);
  server.receive(unhandled);
  if (answers != invalid) std::abort();
  return 0;
}
