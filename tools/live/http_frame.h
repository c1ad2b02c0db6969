// Where one HTTP/1.1 request ends in the bytes a connection has sent so
// far, so that the live-view server hands a worker only whole requests
// (a client that sends slowly, or nothing, holds no thread). The head ends
// at the first empty line (CR LF CR LF); the body is Content-Length bytes
// (none without it). What cannot be framed is refused with the status to
// answer: a head over its limit (431), a body over its limit (413, from
// Content-Length, before it is read), a chunked body (411: the page and
// curl send Content-Length), a Content-Length that is not one number, a
// head line that ends in a bare LF (400: cpp-httplib would read other
// headers than these frames do), a header line that is no `Name: value`
// (a space before the colon, a folded line), two Host or two Origin
// headers, or an empty Origin (400, as RFC 9112 and RFC 6454 say).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rs::live {

struct RequestFrame {
  enum class State { kIncomplete, kComplete, kRefused };
  State state = State::kIncomplete;
  std::size_t length = 0;        ///< kComplete: the request's bytes (head and body)
  std::size_t headLength = 0;    ///< the head's bytes, its empty line included, once it is whole
  bool expectsContinue = false;  ///< the head asks for "100 Continue" before its body
  int status = 0;                ///< kRefused: the status to answer
  std::string message;           ///< kRefused: why, for the answer's body
};

/// The first request in `bytes` (what a connection sent and is not answered yet).
RequestFrame frameRequest(std::string_view bytes, std::size_t maxHead, std::size_t maxBody);

/// The head's "Expect" header renamed in place (same length): the whole
/// request is in, and cpp-httplib would answer "100 Continue" again.
void disarmExpect(std::string& request, std::size_t headLength);

}  // namespace rs::live
