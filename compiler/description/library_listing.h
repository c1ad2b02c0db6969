// What the library holds, for `robotsim list`: every robot, gripper, object
// and workcell a name can find on the search path (a file NAME.rsd that
// defines NAME, in a directory of the path or its kind's folder), each with
// the first sentence of its file's header comment as what it is.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rs::compiler {

struct LibraryEntry {
  std::string kind;  ///< "robot", "gripper", "object" or "workcell"
  std::string name;
  std::filesystem::path file;
  std::string summary;  ///< the header's first sentence, one line ("" if the file has none)
  /// A name found earlier on the path hides this one (lookup takes the first).
  bool hidden = false;
};

/// A .rsd file of the path that could not be read ("file is 70 MiB; the
/// limit is 64 MiB"), so what it defines is not listed.
struct SkippedFile {
  std::filesystem::path file;
  std::string reason;
};

struct LibraryListing {
  std::vector<std::filesystem::path> searchPath;  ///< as searched, first to last
  /// Grouped by kind (robots, grippers, objects, workcells), by name within a
  /// kind, a hidden entry after the one that hides it.
  std::vector<LibraryEntry> entries;
  std::vector<SkippedFile> skipped;  ///< in the order searched
};

/// Reads every .rsd file of `searchPath`'s directories and kind folders
/// (a directory that does not exist is skipped; a file that cannot be read,
/// as the readers refuse it, is named in `skipped`). Files that do not define
/// their own name are not listed, as no name lookup finds them.
LibraryListing listLibrary(const std::vector<std::filesystem::path>& searchPath);

/// The first sentence of a description's leading `;` comment, its lines
/// joined, without a leading "NAME: " when NAME is the file's name.
std::string headerSummary(const std::string& text, const std::string& name);

}  // namespace rs::compiler
