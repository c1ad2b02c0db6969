#include "diag/read_input.h"

#include <utility>

namespace rs::diag {

Diagnostic unreadable(const std::string& path, std::string_view what, const std::string& reason) {
  std::string message(what);
  message += ": ";
  message += reason;
  return {path, {}, Severity::Error, std::move(message)};
}

Result<std::string> fromFileRead(const std::string& path, base::FileRead read, std::string_view what) {
  if (!read.bytes) return unreadable(path, what, read.error);
  return std::move(*read.bytes);
}

Result<std::string> readInput(const std::string& path, std::size_t limit, std::string_view what) {
  return fromFileRead(path, base::readFile(path, limit), what);
}

}  // namespace rs::diag
