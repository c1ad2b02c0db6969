// libFuzzer target: any bytes from an editor to the language server. The
// first byte picks how the rest is read: even, as the raw byte stream
// (Content-Length framing and all, through parseFrames); odd, as message
// bodies separated by NUL bytes, each framed correctly, so that mutations
// reach the JSON-RPC layer, the dispatcher and every feature's handler with
// any parameters. The server must answer or ignore each message, never
// crash, and never stop serving unless told to exit.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <vector>

#include "tools/lsp/jsonrpc.h"
#include "tools/lsp/server.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::vector<rs::lsp::Frame> frames;
  if ((data[0] & 1) == 0) {
    frames = rs::lsp::parseFrames(rest, std::size_t{1} << 20);
  } else {
    std::size_t start = 0;
    while (start <= rest.size()) {
      const std::size_t end = std::min(rest.find('\0', start), rest.size());
      frames.push_back({rs::lsp::Frame::Kind::Message, std::string(rest.substr(start, end - start)), {}});
      start = end + 1;
    }
  }
  std::ostringstream log;
  std::atomic<std::size_t> sent = 0;  // the run worker's thread sends too
  rs::lsp::Server server([&](const rs::lsp::Json&) { return ++sent < 100'000; }, log);
  // Each edit starts a run on the run worker, and a hover may wait for it
  // (250 ms at most): short runs keep an input's time bounded.
  server.setRunBudget(std::chrono::milliseconds(50));
  // One frame a batch, as a slow client sends them: each batch is handled
  // and its diagnostics published before the next.
  for (const rs::lsp::Frame& f : frames) {
    if (server.finished()) break;
    server.receive({f});
    server.publishPending();
  }
  return 0;
}
