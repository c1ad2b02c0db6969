// libFuzzer target: any bytes a client sends the teach pendant's server
// on one connection. They are framed as the server frames them
// (tools/live/http_frame.h), fed in pieces of 1 to 97 bytes as a socket cuts
// them and checked against the frames of the whole; each whole request is
// answered by the server's own routes (tools/live/live_routes.h: Host and
// Origin, the token, the route, the body, the JSON command) over a real
// pendant on the gantry cell, whose program is a file in a fresh folder.
// Every request gets exactly one answer, a well-formed HTTP/1.1 response
// that is never a 500; a refused frame ends the connection with a 4xx.
// The seeds (corpus/live_http/) carry the token and a Host the checks
// accept, so mutations reach every route and every command.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/description/library.h"
#include "launch/program.h"
#include "tools/live/http_frame.h"
#include "tools/live/live_routes.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"

namespace {

namespace fs = std::filesystem;

constexpr const char* kToken = "0123456789abcdef0123456789abcdef";  // the seeds' token
constexpr std::string_view kProgram = "        END\nPOINTS\nHOME  0 0 0 0\nABOVE 10 20 30 40\n";

void require(bool ok) {
  if (!ok) std::abort();
}

const std::shared_ptr<const rs::workcell::Workcell>& gantry() {
  static const auto cell = [] {
    rs::compiler::Library library(rs::compiler::librarySearchPath({}));
    std::optional<rs::workcell::Workcell> c = library.workcell("gantry-cell");
    require(c.has_value());
    return std::make_shared<const rs::workcell::Workcell>(*c);
  }();
  return cell;
}

// The program's folder: in memory when /dev/shm is there (teach writes and
// syncs the file at every taught point).
const std::string& programPath() {
  static const std::string path = [] {
    const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    const fs::path dir = base / ("robotsim-fuzz-live-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return (dir / "p.rsp").string();
  }();
  return path;
}

struct Framed {
  std::vector<std::string> requests;
  int refusal = 0;  // the status a frame was refused with, ending the connection
};

// The connection's requests, with `bytes` fed whole or in pieces.
Framed frames(std::string_view bytes, bool inPieces) {
  Framed f;
  std::string buffer;
  std::uint32_t state = static_cast<std::uint32_t>(bytes.size()) * 2654435761u + 1u;
  for (std::size_t at = 0; at < bytes.size() && f.refusal == 0;) {
    std::size_t n = bytes.size() - at;
    if (inPieces) {
      state ^= state << 13;
      state ^= state >> 17;
      state ^= state << 5;
      n = std::min<std::size_t>(1 + state % 97, n);
    }
    buffer.append(bytes.substr(at, n));
    at += n;
    for (;;) {
      const rs::live::RequestFrame frame = rs::live::frameRequest(buffer, rs::live::kMaxHead, rs::live::kMaxBody);
      if (frame.state == rs::live::RequestFrame::State::kRefused) {
        require(frame.status >= 400 && frame.status < 500 && !frame.message.empty());
        f.refusal = frame.status;
        break;
      }
      if (frame.state == rs::live::RequestFrame::State::kIncomplete) break;
      require(frame.length >= frame.headLength && frame.length <= buffer.size());
      f.requests.push_back(buffer.substr(0, frame.length));
      buffer.erase(0, frame.length);
    }
  }
  return f;
}

// A response as the server sends it: a status line, a head, a body as long
// as it says. An answer to HEAD that keeps the connection has no body (its
// Content-Length is the GET's), or the client would read the body as the
// next answer; one that ends the connection may have it.
void checkResponse(const std::string& request, const std::string& r, bool close) {
  require(r.starts_with("HTTP/1.1 ") && r.size() >= 12);
  const int status = std::atoi(r.substr(9, 3).c_str());
  require(status >= 200 && status < 500);
  const std::size_t head = r.find("\r\n\r\n");
  require(head != std::string::npos);
  constexpr std::string_view kLength = "\r\nContent-Length: ";
  const std::size_t at = r.find(kLength);
  require(at != std::string::npos && at < head);
  const std::size_t length = std::strtoull(r.c_str() + at + kLength.size(), nullptr, 10);
  const std::size_t body = r.size() - (head + 4);
  const bool isHead = request.starts_with("HEAD ");
  require(isHead ? body == 0 || (close && body == length) : body == length);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const Framed whole = frames(bytes, false);
  const Framed cut = frames(bytes, true);
  require(whole.requests == cut.requests && whole.refusal == cut.refusal);
  if (whole.requests.empty()) return 0;

  {
    std::ofstream out(programPath(), std::ios::binary | std::ios::trunc);
    out << kProgram;
  }
  rs::diag::Result<rs::teach::ProgramFile> file = rs::teach::ProgramFile::load(programPath());
  require(file.ok());
  rs::teach::Pendant pendant(gantry(), rs::launch::cellTarget(*gantry()).motors, std::move(*file));
  rs::teach::PendantSource source(pendant, "<!DOCTYPE html><title>teach</title>");
  const rs::live::LiveRoutes routes(source, kToken, rs::live::ServerAddress{"127.0.0.1", 8080});
  for (const std::string& request : whole.requests) {
    const rs::live::LiveAnswer a = routes.answer(request, "127.0.0.1");
    if (a.openStream) {
      require(a.response.empty() && !a.close);
      continue;
    }
    checkResponse(request, a.response, a.close);
    if (a.close) break;  // the server ends the connection after this answer
  }
  return 0;
}
