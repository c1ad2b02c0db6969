// The pendant server's framing of a request head (tools/live/http_frame.h)
// against the header lines RFC 9112 tells a server to refuse with 400
// (issue 32): before, two Host or two Origin headers passed (the routes
// checked the first, cpp-httplib may read another), an empty Origin
// passed as a missing one, and `Transfer-Encoding : chunked` (a space
// before the colon) was no Transfer-Encoding to the frame, so its body
// was framed by a Content-Length that another reader would not use.
#include <catch2/catch.hpp>

#include <string>

#include "tools/live/http_frame.h"

namespace {

using rs::live::frameRequest;
using rs::live::RequestFrame;

RequestFrame framedHead(const std::string& headers, const std::string& body = {}) {
  const std::string bytes = "POST /api/command HTTP/1.1\r\n" + headers + "\r\n" + body;
  return frameRequest(bytes, 8192, 16384);
}

}  // namespace

TEST_CASE("http frame: one Host, one Origin, not empty", "[teach][live][frame]") {
  const std::string host = "Host: 127.0.0.1:8080\r\n";
  // The requests a browser and curl send are whole.
  CHECK(framedHead(host).state == RequestFrame::State::kComplete);
  CHECK(framedHead(host + "Origin: http://127.0.0.1:8080\r\n").state == RequestFrame::State::kComplete);
  CHECK(framedHead(host + "X-Empty:\r\nContent-Length: 2\r\n", "{}").state == RequestFrame::State::kComplete);
  for (const std::string& bad : {host + host, host + "host: localhost:8080\r\n",
                                 host + "Origin: http://127.0.0.1:8080\r\nOrigin: http://127.0.0.1:8080\r\n",
                                 host + "Origin:\r\n", host + "Origin:   \r\n"}) {
    CAPTURE(bad);
    const RequestFrame f = framedHead(bad);
    CHECK(f.state == RequestFrame::State::kRefused);
    CHECK(f.status == 400);
    CHECK(!f.message.empty());
  }
  CHECK(framedHead(host + host).message == "a request has one Host header, not two");
  CHECK(framedHead(host + "Origin:\r\n").message == "an Origin header may not be empty");
}

TEST_CASE("http frame: a header name with a space before its colon, a folded line, no colon: 400",
          "[teach][live][frame]") {
  const std::string host = "Host: 127.0.0.1:8080\r\n";
  for (const std::string& bad : {host + "Transfer-Encoding : chunked\r\n", std::string("Host : 127.0.0.1:8080\r\n"),
                                 host + "Content-Length\t: 2\r\n", host + "X-A: b\r\n  folded\r\n",
                                 host + "No colon here\r\n", host + ": no name\r\n", host + "X\x01Y: z\r\n"}) {
    CAPTURE(bad);
    const RequestFrame f = framedHead(bad, "{}");
    CHECK(f.state == RequestFrame::State::kRefused);
    CHECK(f.status == 400);
  }
  CHECK(framedHead(host + "Transfer-Encoding : chunked\r\n").message.find("no space before the colon") !=
        std::string::npos);
  // A name of every character RFC 9110's token allows is one.
  CHECK(framedHead(host + "X-!#$%&'*+.^_`|~09az: v\r\n").state == RequestFrame::State::kComplete);
}
