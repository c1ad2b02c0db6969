#include "tools/dap/message_reader.h"

namespace rs::dap {

namespace {

IncomingMessage answeredWithFailure(wire::Json message, std::string problem) {
  return {IncomingMessage::Kind::Invalid, std::move(message), std::move(problem)};
}

}  // namespace

IncomingMessage readMessage(const wire::Frame& frame) {
  if (frame.kind != wire::Frame::Kind::Message) return answeredWithFailure(nullptr, frame.problem);
  wire::Json message = wire::Json::parse(frame.body, nullptr, false);
  if (message.is_discarded()) return answeredWithFailure(nullptr, "the message is not valid JSON");
  if (!message.is_object() || !message.contains("type") || !message["type"].is_string())
    return answeredWithFailure(std::move(message), "a message is a JSON object with a type");
  if (message["type"] != "request") return {IncomingMessage::Kind::Other, nullptr, {}};
  if (!message.contains("command") || !message["command"].is_string())
    return answeredWithFailure(std::move(message), "a request without a command");
  return {IncomingMessage::Kind::Request, std::move(message), {}};
}

}  // namespace rs::dap
