// JSON for the language server and the debug adapter: nlohmann-json, and the one way a value is
// written out (text that is not UTF-8 becomes U+FFFD instead of an
// exception: a file name or a message may carry any bytes).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace rs::wire {

using Json = nlohmann::json;

inline std::string dumpJson(const Json& value) {
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

/// What a checked read of a client's message found wrong, without
/// nlohmann's internal id: "key 'value' not found" for
/// "[json.exception.out_of_range.403] key 'value' not found".
inline std::string jsonProblem(const Json::exception& e) {
  std::string_view what = e.what();
  if (what.starts_with("[json.exception.")) {
    const std::size_t end = what.find("] ");
    if (end != std::string_view::npos) what.remove_prefix(end + 2);
  }
  return std::string(what);
}

}  // namespace rs::wire
