// Paths kept inside a folder: a golden trace inside its test's folder, a
// grading submission's cell inside its own folder (cell_directive.h), a
// submission inside the folder graded. Compared after every symbolic link
// is followed, so that a link inside the folder cannot lead out of it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "diag/result.h"

namespace rs::launch {

/// Whether `path` lies inside `folder` (or is it); both canonical.
bool isInside(const std::filesystem::path& folder, const std::filesystem::path& path);

/// Where `path` leads once every symbolic link is followed (the parts that
/// do not exist yet kept as written), or the system's reason it cannot be
/// followed (a loop, a link to nowhere when `mustExist`) as a failure with
/// no place (diag::refusal): the caller says whose path it was.
diag::Result<std::filesystem::path> resolve(const std::filesystem::path& path, bool mustExist);

}  // namespace rs::launch
