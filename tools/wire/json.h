// JSON for the language server and the debug adapter: nlohmann-json, and the one way a value is
// written out (text that is not UTF-8 becomes U+FFFD instead of an
// exception: a file name or a message may carry any bytes).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rs::wire {

using Json = nlohmann::json;

inline std::string dumpJson(const Json& value) {
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace rs::wire
