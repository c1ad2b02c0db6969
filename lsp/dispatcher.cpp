#include "lsp/dispatcher.h"

#include <fmt/format.h>

namespace rs::lsp {

Json response(const Json& id, const Reply& reply) {
  Json out = {{"jsonrpc", "2.0"}, {"id", id}};
  if (const Json* result = std::get_if<Json>(&reply)) {
    out["result"] = *result;
  } else {
    const RpcError& e = std::get<RpcError>(reply);
    out["error"] = {{"code", e.code}, {"message", e.message}};
  }
  return out;
}

Json notification(std::string_view method, Json params) {
  return {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
}

void Dispatcher::onRequest(const std::string& method, RequestHandler handler) {
  requests_[method] = std::move(handler);
}

void Dispatcher::onNotification(const std::string& method, NotificationHandler handler) {
  notifications_[method] = std::move(handler);
}

Reply Dispatcher::request(const std::string& method, const Json& params) const {
  const auto it = requests_.find(method);
  if (it == requests_.end()) return RpcError{errc::kMethodNotFound, fmt::format("unknown method '{}'", method)};
  // nlohmann-json reports a missing field or a wrong type by exception: at
  // this edge it becomes the client's error, never the server's end.
  try {
    return it->second(params);
  } catch (const Json::exception& e) {
    return RpcError{errc::kInvalidParams, fmt::format("invalid params for {}: {}", method, e.what())};
  }
}

bool Dispatcher::notify(const std::string& method, const Json& params) const {
  const auto it = notifications_.find(method);
  if (it == notifications_.end()) return false;
  try {
    it->second(params);
  } catch (const Json::exception&) {
    // A notification has no answer: malformed params change nothing.
  }
  return true;
}

}  // namespace rs::lsp
