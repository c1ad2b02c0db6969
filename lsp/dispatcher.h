// Method names to handlers. A request's handler returns its result or an
// error; a notification's returns nothing. The dispatcher answers what no
// handler knows (MethodNotFound for a request; an unknown notification is
// ignored) and turns a handler that trips over malformed params (a JSON
// type error) into InvalidParams instead of an exception leaving the server.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>

#include "lsp/json.h"

namespace rs::lsp {

/// JSON-RPC and LSP error codes.
namespace errc {
inline constexpr int kParseError = -32700;
inline constexpr int kInvalidRequest = -32600;
inline constexpr int kMethodNotFound = -32601;
inline constexpr int kInvalidParams = -32602;
inline constexpr int kInternalError = -32603;
inline constexpr int kServerNotInitialized = -32002;
inline constexpr int kRequestCancelled = -32800;
inline constexpr int kContentModified = -32801;
inline constexpr int kRequestFailed = -32803;
}  // namespace errc

struct RpcError {
  int code = errc::kInternalError;
  std::string message;
};

using Reply = std::variant<Json, RpcError>;

/// {"jsonrpc":"2.0","id":id,"result":...} or {..., "error":{code,message}}.
Json response(const Json& id, const Reply& reply);
/// {"jsonrpc":"2.0","method":method,"params":params}.
Json notification(std::string_view method, Json params);

class Dispatcher {
 public:
  using RequestHandler = std::function<Reply(const Json& params)>;
  using NotificationHandler = std::function<void(const Json& params)>;

  void onRequest(const std::string& method, RequestHandler handler);
  void onNotification(const std::string& method, NotificationHandler handler);
  bool knowsRequest(const std::string& method) const { return requests_.count(method) > 0; }

  /// The reply to a request (MethodNotFound when no handler has it).
  Reply request(const std::string& method, const Json& params) const;
  /// Runs a notification's handler; false when there is none.
  bool notify(const std::string& method, const Json& params) const;

 private:
  std::map<std::string, RequestHandler, std::less<>> requests_;
  std::map<std::string, NotificationHandler, std::less<>> notifications_;
};

}  // namespace rs::lsp
