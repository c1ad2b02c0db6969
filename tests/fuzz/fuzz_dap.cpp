// libFuzzer target: any bytes from an editor to the debug adapter. The
// first byte picks how the rest is read: even, as the raw byte stream
// (Content-Length framing and all, through parseFrames, the language
// server's framing); odd, as message bodies separated by NUL bytes, each
// framed correctly, so that mutations reach the request handlers with any
// arguments (launch, breakpoints, stepping forwards and backwards, scopes,
// evaluate). The adapter must answer each request, never crash, and stop
// only on disconnect. A launched program's runs are cut short: the poll
// that would read a client's pause says yes at once, so every forward or
// backward move ends after one slice.
#include <cstdint>
#include <sstream>
#include <string_view>
#include <vector>

#include "tools/dap/adapter.h"
#include "tools/wire/framing.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::vector<rs::wire::Frame> frames;
  if ((data[0] & 1) == 0) {
    frames = rs::wire::parseFrames(rest, std::size_t{1} << 20);
  } else {
    std::size_t start = 0;
    while (start <= rest.size()) {
      const std::size_t end = std::min(rest.find('\0', start), rest.size());
      frames.push_back({rs::wire::Frame::Kind::Message, std::string(rest.substr(start, end - start)), {}});
      start = end + 1;
    }
  }
  std::ostringstream log;
  std::size_t sent = 0;
  rs::dap::Adapter adapter([&](const rs::wire::Json&) { return ++sent < 100'000; }, log);
  adapter.setPoll([] { return true; });
  for (const rs::wire::Frame& f : frames) {
    if (adapter.finished()) break;
    // A program named by a mutated launch is read from disk: never a
    // device or a process file, which could block or never end.
    if (f.body.find("/dev/") != std::string::npos || f.body.find("/proc/") != std::string::npos) continue;
    adapter.receive(f);
  }
  return 0;
}
