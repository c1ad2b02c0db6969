#include "tools/lsp/message_reader.h"

#include "base/text.h"
#include "diag/source_file.h"

namespace rs::lsp {

namespace {

std::string withoutInvalidUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = base::utf8SequenceLength(text, i);
    if (n == 0) {
      out += "\xEF\xBF\xBD";
      ++i;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

IncomingMessage answeredWithError(Json id, int code, std::string message) {
  IncomingMessage m;
  m.id = std::move(id);
  m.error = RpcError{code, std::move(message)};
  return m;
}

}  // namespace

IncomingMessage readMessage(const Frame& frame) {
  if (frame.kind != Frame::Kind::Message)
    return answeredWithError(nullptr, frame.kind == Frame::Kind::TooLarge ? errc::kInvalidRequest : errc::kParseError,
                   frame.problem);
  // JSON has no NUL byte outside a string's \u0000, and nlohmann's parser
  // takes one for the end of the text: `{"id":1}` NUL junk would pass.
  if (const std::size_t nul = frame.body.find('\0'); nul != std::string::npos)
    return answeredWithError(nullptr, errc::kParseError,
                             "the message is not valid JSON: a NUL byte at byte " + std::to_string(nul + 1));
  const bool invalidUtf8 = diag::findInvalidUtf8(frame.body).found;
  Json message = Json::parse(invalidUtf8 ? withoutInvalidUtf8(frame.body) : frame.body, nullptr, false);
  if (message.is_discarded()) return answeredWithError(nullptr, errc::kParseError, "the message is not valid JSON");
  if (!message.is_object()) return answeredWithError(nullptr, errc::kInvalidRequest, "a message is a JSON object");
  const bool hasId = message.contains("id");
  const Json id = hasId ? message["id"] : Json(nullptr);
  if (!message.contains("method")) {
    if (hasId && (message.contains("result") || message.contains("error"))) {
      IncomingMessage m;
      m.kind = IncomingMessage::Kind::Response;
      m.id = id;
      return m;
    }
    return answeredWithError(id, errc::kInvalidRequest, "a message without a method");
  }
  if (!message["method"].is_string()) return answeredWithError(id, errc::kInvalidRequest, "the method is not a string");
  if (hasId && !id.is_string() && !id.is_number_integer())
    return answeredWithError(nullptr, errc::kInvalidRequest, "a request's id is a number or a string");
  IncomingMessage m;
  m.kind = hasId ? IncomingMessage::Kind::Request : IncomingMessage::Kind::Notification;
  m.id = id;
  m.method = message["method"].get<std::string>();
  if (const auto params = message.find("params"); params != message.end()) m.params = std::move(*params);  // no copy of a large text
  m.invalidUtf8 = invalidUtf8;
  return m;
}

}  // namespace rs::lsp
