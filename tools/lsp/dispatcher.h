// Method names to handlers. A request's handler returns its result or an
// error; a notification's returns nothing. Handlers read their params
// through lsp::Field (params.h), which checks every field's type. The
// dispatcher answers what no handler knows (MethodNotFound for a request;
// an unknown notification is ignored) and turns a handler that meets
// malformed params (BadParams, or a JSON type error from deeper down) into
// InvalidParams, or for a notification into the message to log, instead
// of an exception leaving the server.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>

#include "tools/lsp/json.h"
#include "tools/lsp/params.h"

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

/// {"jsonrpc":"2.0","id":id,"result":...} or {..., "error":{code,message}}
/// (the result moved in: a large one is not copied).
Json response(const Json& id, Reply&& reply);
/// {"jsonrpc":"2.0","method":method,"params":params}.
Json notification(std::string_view method, Json params);

class Dispatcher {
 public:
  using RequestHandler = std::function<Reply(const Field& params)>;
  using NotificationHandler = std::function<void(const Field& params)>;

  void onRequest(const std::string& method, RequestHandler handler);
  void onNotification(const std::string& method, NotificationHandler handler);
  bool knowsRequest(const std::string& method) const { return requests_.count(method) > 0; }

  /// The reply to a request (MethodNotFound when no handler has it).
  Reply request(const std::string& method, const Json& params) const;
  /// Runs a notification's handler: what was wrong with its params, if
  /// anything ("" when it ran, or when no handler has it).
  std::string notify(const std::string& method, const Json& params) const;
  /// Runs `handler` with the same care: malformed params are InvalidParams.
  static Reply guarded(std::string_view method, const Json& params, const RequestHandler& handler);

 private:
  std::map<std::string, RequestHandler, std::less<>> requests_;
  std::map<std::string, NotificationHandler, std::less<>> notifications_;
};

}  // namespace rs::lsp
