// Whole files in, for every reader of the product: only a regular file is
// read (a FIFO, a device or a socket is refused by what it is, never opened
// to wait on: a FIFO nobody writes would hang the command), and a read is
// refused from the file's size before a byte is read when it is over the
// caller's limit. Writes are file_write.h's (included here for the callers
// that read and write).
#pragma once

#include <sys/types.h>

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

/// Reads the whole file at `path`, refusing anything over `limit` bytes
/// and anything that is not a regular file (openRegularFile).
FileRead readFile(const std::string& path, std::size_t limit);

/// Opens `path` (links followed) for reading when it is a regular file:
/// anything else is refused from its stat() before it is opened (opening a
/// device can act on it), and the open itself cannot block (O_NONBLOCK: a
/// FIFO put at the name in between is opened at once, then refused by its
/// fstat()). The descriptor (close-on-exec), or -1 with `error` set ("is
/// a FIFO (a named pipe), not a regular file"); `size` is the file's size.
int openRegularFile(const std::string& path, std::string& error, std::uint64_t* size = nullptr);

/// "is a directory", "is a FIFO (a named pipe), not a regular file", ...:
/// why a file of this st_mode is not read; "" for a regular file.
std::string notRegularFileReason(mode_t mode);

/// "300 MiB", "12 KiB", "100 bytes": a size for a message.
std::string sizeText(std::uint64_t bytes);

}  // namespace rs::base
