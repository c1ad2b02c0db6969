// The message readers of the language server and the debug adapter
// (tools/lsp/message_reader.h, tools/dap/message_reader.h): what each makes of a frame
// before acting on it. Expected kinds and error codes are the JSON-RPC 2.0
// and DAP rules, written out by hand.
#include <catch2/catch.hpp>

#include "tools/dap/message_reader.h"
#include "tools/lsp/message_reader.h"

namespace {

rs::wire::Frame messageFrame(std::string body) { return {rs::wire::Frame::Kind::Message, std::move(body), {}}; }

}  // namespace

TEST_CASE("lsp reader: requests, notifications and the client's responses", "[lsp][reader]") {
  using Kind = rs::lsp::IncomingMessage::Kind;
  const auto request = rs::lsp::readMessage(messageFrame(R"({"jsonrpc":"2.0","id":"a7","method":"m","params":[1]})"));
  CHECK(request.kind == Kind::Request);
  CHECK(request.id == "a7");
  CHECK(request.method == "m");
  CHECK(request.params == rs::lsp::Json::array({1}));
  const auto note = rs::lsp::readMessage(messageFrame(R"({"jsonrpc":"2.0","method":"n"})"));
  CHECK(note.kind == Kind::Notification);
  CHECK(note.params.is_null());
  CHECK(rs::lsp::readMessage(messageFrame(R"({"id":3,"result":null})")).kind == Kind::Response);
  CHECK(rs::lsp::readMessage(messageFrame(R"({"id":3,"error":{}})")).kind == Kind::Response);
}

TEST_CASE("lsp reader: each bad message gets its JSON-RPC error, with the id when it could be read", "[lsp][reader]") {
  using Kind = rs::lsp::IncomingMessage::Kind;
  namespace errc = rs::lsp::errc;
  struct Case {
    std::string body;
    int code;
    rs::lsp::Json id;
  };
  const Case cases[] = {
      {"{\"id\":1,", errc::kParseError, nullptr},
      {"[1,2]", errc::kInvalidRequest, nullptr},
      {R"({"id":4})", errc::kInvalidRequest, 4},
      {R"({"id":5,"method":7})", errc::kInvalidRequest, 5},
      {R"({"id":1.5,"method":"m"})", errc::kInvalidRequest, nullptr},
      {R"({"id":null,"method":"m"})", errc::kInvalidRequest, nullptr},
      // A NUL byte is not JSON anywhere, even after a whole object (the
      // JSON library alone takes it for the end of the text).
      {std::string(R"({"jsonrpc":"2.0","id":6,"method":"m"})") + '\0' + "junk", errc::kParseError, nullptr},
  };
  for (const Case& c : cases) {
    INFO(c.body);
    const auto m = rs::lsp::readMessage(messageFrame(c.body));
    CHECK(m.kind == Kind::Invalid);
    CHECK(m.error.code == c.code);
    CHECK(m.id == c.id);
    CHECK_FALSE(m.error.message.empty());
  }
  const auto tooLarge = rs::lsp::readMessage({rs::wire::Frame::Kind::TooLarge, {}, "too large"});
  CHECK(tooLarge.error.code == errc::kInvalidRequest);
  CHECK(tooLarge.error.message == "too large");
  CHECK(rs::lsp::readMessage({rs::wire::Frame::Kind::BadHeader, {}, "bad"}).error.code == errc::kParseError);
}

TEST_CASE("lsp reader: bytes that are not UTF-8 become U+FFFD and are flagged", "[lsp][reader]") {
  const auto m = rs::lsp::readMessage(messageFrame("{\"method\":\"n\",\"params\":\"a\xFF" "b\"}"));
  REQUIRE(m.kind == rs::lsp::IncomingMessage::Kind::Notification);
  CHECK(m.invalidUtf8);
  CHECK(m.params == "a\xEF\xBF\xBD" "b");
}

TEST_CASE("dap reader: requests, the client's events and responses, and bad messages", "[dap][reader]") {
  using Kind = rs::dap::IncomingMessage::Kind;
  const auto request = rs::dap::readMessage(messageFrame(R"({"seq":1,"type":"request","command":"threads"})"));
  CHECK(request.kind == Kind::Request);
  CHECK(request.message["command"] == "threads");
  CHECK(rs::dap::readMessage(messageFrame(R"({"seq":2,"type":"event","event":"x"})")).kind == Kind::Other);
  CHECK(rs::dap::readMessage(messageFrame(R"({"seq":3,"type":"response"})")).kind == Kind::Other);
  struct Case {
    std::string body;
    std::string problem;
    bool keepsMessage;  // the answer can name the request's seq and command
  };
  const Case cases[] = {
      {"{", "the message is not valid JSON", false},
      {"{\"type\":\"request\",\"command\":\"a\xFF\"}", "the message is not valid JSON", false},
      {R"({"seq":4})", "a message is a JSON object with a type", true},
      {R"({"seq":5,"type":1})", "a message is a JSON object with a type", true},
      {R"({"seq":6,"type":"request","command":2})", "a request without a command", true},
  };
  for (const Case& c : cases) {
    INFO(c.body);
    const auto m = rs::dap::readMessage(messageFrame(c.body));
    CHECK(m.kind == Kind::Invalid);
    CHECK(m.problem == c.problem);
    CHECK(m.message.is_object() == c.keepsMessage);
  }
  const auto bad = rs::dap::readMessage({rs::wire::Frame::Kind::BadHeader, {}, "a header block without Content-Length"});
  CHECK(bad.kind == Kind::Invalid);
  CHECK(bad.problem == "a header block without Content-Length");
}
