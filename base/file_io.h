// Whole files in and out, for every reader and writer of the product: a
// read is refused from the file's size before a byte is read when it is over
// the caller's limit (a pipe or a device is read up to the limit and no
// further, so /dev/zero cannot hang a command), and a write is all or
// nothing (a temporary file renamed into place).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rs::base {

/// A file's bytes, or why they could not be had ("is a directory", "No such
/// file or directory", "file is 300 MiB; the limit is 256 MiB").
struct FileRead {
  std::optional<std::string> bytes;
  std::string error;  ///< set when bytes is empty
};

/// Reads the whole file at `path`, refusing anything over `limit` bytes.
FileRead readFile(const std::string& path, std::size_t limit);

/// Writes all bytes or nothing; on failure returns false and sets `error`.
bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string& error);
bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error);
/// The same, with the bytes written by `write` to the temporary file as it
/// makes them (never held whole); `write` returns false when it failed.
bool writeFileAtomically(const std::string& path, const std::function<bool(std::ostream&)>& write, std::string& error);

/// "300 MiB", "12 KiB", "100 bytes": a size for a message.
std::string sizeText(std::uint64_t bytes);

}  // namespace rs::base
