// A file a reader takes as input, whole, as a Result: the one place where
// base/'s sentence for what the system refused ("No such file or
// directory", "file is 300 MiB; the limit is 256 MiB") becomes a
// Diagnostic. base/ cannot know Diagnostic (diag/ is above it), so it keeps
// its own shape and every reader converts here.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "base/file_io.h"
#include "diag/result.h"

namespace rs::diag {

/// The Diagnostic for a file that could not be read: the whole file
/// (line 0), "WHAT: REASON" ("cannot read file: is a directory").
Diagnostic unreadable(const std::string& path, std::string_view what, const std::string& reason);

/// A read by base/ as a Result; `what` begins the message ("cannot read the
/// stimuli file").
Result<std::string> fromFileRead(const std::string& path, base::FileRead read, std::string_view what);

/// The bytes of `path`, at most `limit` of them (base::readFile).
Result<std::string> readInput(const std::string& path, std::size_t limit, std::string_view what);

}  // namespace rs::diag
