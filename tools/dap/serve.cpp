#include "tools/dap/serve.h"

#include <deque>
#include <vector>

#include "tools/dap/adapter.h"
#include "tools/dap/message_reader.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace rs::dap {

namespace {

// Does this frame ask a running program to stop (pause, terminate,
// disconnect)? A frame that is not such a request waits.
bool stopsARun(const wire::Frame& f) {
  const IncomingMessage m = readMessage(f);
  if (m.kind != IncomingMessage::Kind::Request) return false;
  const std::string& c = m.message["command"].get_ref<const std::string&>();
  return c == "pause" || c == "terminate" || c == "disconnect";
}

}  // namespace

int serve(wire::Input& in, wire::Output& out, std::ostream& log) {
  Adapter adapter([&out](const Json& m) { return out.write(wire::frameMessage(wire::dumpJson(m))); }, log);
  wire::FrameParser parser;
  std::deque<wire::Frame> queue;
  std::vector<char> buffer(std::size_t{1} << 16);
  bool eof = false;
  const auto pump = [&](bool wait) {
    if (eof || (!wait && !in.ready())) return;
    const std::size_t n = in.read(buffer.data(), buffer.size());
    if (n == 0) {
      eof = true;
      return;
    }
    parser.feed(std::string_view(buffer.data(), n));
    while (std::optional<wire::Frame> f = parser.next()) queue.push_back(std::move(*f));
  };
  adapter.setPoll([&] {
    pump(false);
    if (eof && queue.empty()) return true;  // gone, with nothing left to say
    for (const wire::Frame& f : queue)
      if (stopsARun(f)) return true;
    return false;
  });
  while (!adapter.finished()) {
    if (queue.empty()) {
      if (eof) break;
      pump(true);
      continue;
    }
    const wire::Frame f = std::move(queue.front());
    queue.pop_front();
    adapter.receive(f);
  }
  if (adapter.disconnected()) return 0;
  if (parser.partial()) log << "robotsim dap: the input ended inside a message\n";
  log << "robotsim dap: the client left without disconnect\n";
  return 1;
}

}  // namespace rs::dap
