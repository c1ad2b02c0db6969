// The framing of LSP messages (tools/lsp/jsonrpc.h): well-formed frames, and the
// recoveries from bad headers, oversized bodies and header blocks that
// never end.
#include <catch2/catch.hpp>

#include "tools/lsp/jsonrpc.h"

using rs::lsp::Frame;
using rs::lsp::parseFrames;

TEST_CASE("frames are read by Content-Length, with CR LF or LF header ends", "[lsp][framing]") {
  const auto frames = parseFrames("Content-Length: 2\r\n\r\n{}Content-Length: 3\r\nContent-Type: x\r\n\r\n[1]"
                                  "content-length:1\n\n7");
  REQUIRE(frames.size() == 3);
  CHECK(frames[0].kind == Frame::Kind::Message);
  CHECK(frames[0].body == "{}");
  CHECK(frames[1].body == "[1]");
  CHECK(frames[2].body == "7");
}

TEST_CASE("a message cut off waits for the rest", "[lsp][framing]") {
  rs::lsp::FrameParser parser;
  parser.feed("Content-Length: 8\r\n\r\n{\"a\":");
  CHECK_FALSE(parser.next());
  CHECK(parser.partial());
  parser.feed("12}");
  const auto f = parser.next();
  REQUIRE(f);
  CHECK(f->body == "{\"a\":12}");
}

TEST_CASE("a header block without Content-Length is reported and skipped to the next message", "[lsp][framing]") {
  const auto frames = parseFrames("Content-Type: x\r\n\r\n{\"lost\":1}Content-Length: 2\r\n\r\n{}");
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].kind == Frame::Kind::BadHeader);
  CHECK(frames[0].problem == "a header block without Content-Length");
  CHECK(frames[1].kind == Frame::Kind::Message);
  CHECK(frames[1].body == "{}");
}

TEST_CASE("a Content-Length that is not a number is reported and skipped", "[lsp][framing]") {
  const auto frames = parseFrames("Content-Length: ten\r\n\r\n{}Content-Length: 1\r\n\r\n5");
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].kind == Frame::Kind::BadHeader);
  CHECK(frames[0].problem == "Content-Length is not a number");
  CHECK(frames[1].body == "5");
}

TEST_CASE("a body over the limit is refused and its bytes skipped", "[lsp][framing]") {
  const auto frames = parseFrames("Content-Length: 20\r\n\r\n01234567890123456789Content-Length: 2\r\n\r\nok", 10);
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].kind == Frame::Kind::TooLarge);
  CHECK(frames[0].problem == "a message of 20 bytes; the limit is 10 bytes");
  CHECK(frames[1].body == "ok");
}

TEST_CASE("an oversized body is skipped as it arrives, never held", "[lsp][framing]") {
  rs::lsp::FrameParser parser(10);
  parser.feed("Content-Length: 1000\r\n\r\n");
  const auto refused = parser.next();
  REQUIRE(refused);
  CHECK(refused->kind == Frame::Kind::TooLarge);
  parser.feed(std::string(999, 'x'));
  CHECK_FALSE(parser.next());
  parser.feed("xContent-Length: 2\r\n\r\n{}");
  const auto next = parser.next();
  REQUIRE(next);
  CHECK(next->body == "{}");
}

TEST_CASE("bytes that never make a header block are cut off at 8 KiB", "[lsp][framing]") {
  const std::string junk(20000, 'j');
  const auto frames = parseFrames(junk + "Content-Length: 2\r\n\r\n{}");
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].kind == Frame::Kind::BadHeader);
  CHECK(frames[0].problem == "no header block within 8192 bytes");
  CHECK(frames[1].body == "{}");
}

TEST_CASE("frameMessage writes what parseFrames reads", "[lsp][framing]") {
  const std::string body = "{\"jsonrpc\":\"2.0\",\"method\":\"x\",\"params\":\"\xC3\xA9\"}";
  CHECK(rs::lsp::frameMessage(body) == "Content-Length: 44\r\n\r\n" + body);
  const auto frames = parseFrames(rs::lsp::frameMessage(body) + rs::lsp::frameMessage("[]"));
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].body == body);
  CHECK(frames[1].body == "[]");
}

TEST_CASE("a Content-Length too small: the cut body is a frame, and the next message is found again", "[lsp][framing]") {
  const auto frames = parseFrames("Content-Length: 5\r\n\r\n{\"a\":1}Content-Length: 2\r\n\r\n{}");
  REQUIRE(frames.size() == 3);
  CHECK(frames[0].body == "{\"a\":");  // not JSON: the server answers ParseError
  CHECK(frames[1].kind == Frame::Kind::BadHeader);
  CHECK(frames[2].kind == Frame::Kind::Message);
  CHECK(frames[2].body == "{}");
}
