#include "tools/lsp/dispatcher.h"

#include <fmt/format.h>

namespace rs::lsp {

Json response(const Json& id, Reply&& reply) {
  Json out = {{"jsonrpc", "2.0"}, {"id", id}};
  if (Json* result = std::get_if<Json>(&reply)) {
    out["result"] = std::move(*result);
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

Reply Dispatcher::guarded(std::string_view method, const Json& params, const RequestHandler& handler) {
  try {
    return handler(Field(params));
  } catch (const BadParams& e) {
    return RpcError{errc::kInvalidParams, fmt::format("invalid params for {}: {}", method, e.what())};
  } catch (const Json::exception& e) {
    // What a handler reads below the params reader: still the client's data.
    return RpcError{errc::kInvalidParams, fmt::format("invalid params for {}: {}", method, wire::jsonProblem(e))};
  }
}

Reply Dispatcher::request(const std::string& method, const Json& params) const {
  const auto it = requests_.find(method);
  if (it == requests_.end()) return RpcError{errc::kMethodNotFound, fmt::format("unknown method '{}'", method)};
  return guarded(method, params, it->second);
}

std::string Dispatcher::notify(const std::string& method, const Json& params) const {
  const auto it = notifications_.find(method);
  if (it == notifications_.end()) return {};
  // A notification has no answer: malformed params change nothing, and
  // the server says why in its log.
  const Reply reply = guarded(method, params, [&](const Field& p) -> Reply {
    it->second(p);
    return Json(nullptr);
  });
  const RpcError* error = std::get_if<RpcError>(&reply);
  return error ? error->message : std::string();
}

}  // namespace rs::lsp
