#include "base/file_io.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace rs::base {

namespace fs = std::filesystem;

std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t{1} << 20) && bytes % (std::uint64_t{1} << 20) == 0)
    return fmt::format("{} MiB", bytes >> 20);
  if (bytes >= (std::uint64_t{1} << 20)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
  if (bytes >= 1024 && bytes % 1024 == 0) return fmt::format("{} KiB", bytes >> 10);
  return fmt::format("{} bytes", bytes);
}

FileRead readFile(const std::string& path, std::size_t limit) {
  FileRead result;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!ec && fs::is_directory(status)) {
    result.error = "is a directory";
    return result;
  }
  // A regular file is judged by its size before it is opened for reading.
  std::uint64_t size = 0;
  const bool regular = !ec && fs::is_regular_file(status);
  if (regular) {
    size = fs::file_size(path, ec);
    if (!ec && size > limit) {
      result.error = fmt::format("file is {}; the limit is {}", sizeText(size), sizeText(limit));
      return result;
    }
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    result.error = std::strerror(errno);
    return result;
  }
  std::string text;
  if (regular) text.reserve(static_cast<std::size_t>(size));  // one allocation of the right size
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit) {  // a pipe, a device, or a file that grew
      result.error = fmt::format("file is larger than the limit of {}", sizeText(limit));
      return result;
    }
  }
  if (in.bad()) {
    result.error = "read error";
    return result;
  }
  result.bytes = std::move(text);
  return result;
}

}  // namespace rs::base
