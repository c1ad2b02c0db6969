// The frames of a byte stream as a server reads them from a pipe: fed to a
// FrameParser in pieces of 1 to 97 bytes (sizes from a generator seeded by
// the stream's length, so an input always gets the same cuts), checked
// against parseFrames() on the whole stream. How the pipe cuts the stream
// must never change what is read: a difference aborts (a finding).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "tools/wire/framing.h"

namespace fuzz {

inline std::vector<rs::wire::Frame> chunkedFrames(std::string_view bytes, std::size_t maxBody) {
  rs::wire::FrameParser parser(maxBody);
  std::vector<rs::wire::Frame> frames;
  std::uint32_t state = static_cast<std::uint32_t>(bytes.size()) * 2654435761u + 1u;
  for (std::size_t at = 0; at < bytes.size();) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    const std::size_t n = std::min<std::size_t>(1 + state % 97, bytes.size() - at);
    parser.feed(bytes.substr(at, n));
    at += n;
    while (std::optional<rs::wire::Frame> f = parser.next()) frames.push_back(std::move(*f));
  }
  const std::vector<rs::wire::Frame> whole = rs::wire::parseFrames(bytes, maxBody);
  if (whole.size() != frames.size()) std::abort();
  for (std::size_t i = 0; i < whole.size(); ++i)
    if (whole[i].kind != frames[i].kind || whole[i].body != frames[i].body || whole[i].problem != frames[i].problem)
      std::abort();
  return frames;
}

/// A small body limit for odd lengths, so that short inputs reach the
/// refusal of a body over the limit; the server's own limit otherwise.
inline std::size_t maxBodyFor(std::size_t size) { return size % 2 ? 64 : rs::wire::kMaxMessageBytes; }

}  // namespace fuzz
