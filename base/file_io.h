// Whole files in, for every reader of the product: a read is refused from
// the file's size before a byte is read when it is over the caller's limit
// (a pipe or a device is read up to the limit and no further, so /dev/zero
// cannot hang a command). Writes are file_write.h's (included here for the
// callers that read and write).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/file_write.h"

namespace rs::base {

/// A file's bytes, or why they could not be had ("is a directory", "No such
/// file or directory", "file is 300 MiB; the limit is 256 MiB").
struct FileRead {
  std::optional<std::string> bytes;
  std::string error;  ///< set when bytes is empty
};

/// Reads the whole file at `path`, refusing anything over `limit` bytes.
FileRead readFile(const std::string& path, std::size_t limit);

/// "300 MiB", "12 KiB", "100 bytes": a size for a message.
std::string sizeText(std::uint64_t bytes);

}  // namespace rs::base
