#include "compiler/description/library_listing.h"

#include <algorithm>
#include <array>
#include <set>
#include <string_view>
#include <system_error>

#include "base/file_io.h"
#include "compiler/description/description.h"
#include "compiler/description/library.h"
#include "diag/diagnostic.h"
#include "model/urdf/urdf_read.h"

namespace rs::compiler {

namespace fs = std::filesystem;

namespace {

// The kinds in the order the listing shows them, with their folders.
struct ListedKind {
  std::string_view kind, folder;
};
constexpr std::array<ListedKind, 4> kListedKinds{{
    {"robot", "robots"}, {"gripper", "grippers"}, {"object", "objects"}, {"workcell", "workcells"}}};

int kindOrder(const std::string& kind) {
  for (std::size_t i = 0; i < kListedKinds.size(); ++i)
    if (kListedKinds[i].kind == kind) return static_cast<int>(i);
  return static_cast<int>(kListedKinds.size());
}

template <typename Def>
bool defines(const std::vector<Def>& defs, const std::string& name) {
  return std::any_of(defs.begin(), defs.end(), [&](const Def& d) { return d.name == name; });
}

// The kind a lookup of NAME finds in this file ("" if it defines no NAME).
std::string kindDefined(const DescriptionFile& f, const std::string& name) {
  if (defines(f.workcells, name)) return "workcell";
  if (defines(f.robots, name)) return "robot";
  if (defines(f.grippers, name)) return "gripper";
  if (defines(f.objects, name)) return "object";
  return "";
}

// The .rsd files of one directory, sorted, so that the listing is the same
// on every file system.
std::vector<fs::path> filesOf(const fs::path& dir, std::string_view extension) {
  std::vector<fs::path> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == extension && it->is_regular_file(ec)) files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<fs::path> rsdFiles(const fs::path& dir) { return filesOf(dir, ".rsd"); }

// A URDF file's summary: the name its <robot> element gives, found in its
// text without parsing the XML (the listing runs no URDF reader).
std::string urdfSummary(std::string_view text) {
  std::string name;
  const std::size_t robot = text.find("<robot");
  const std::size_t attr = robot == std::string_view::npos ? robot : text.find("name=", robot);
  if (attr != std::string_view::npos && attr + 6 < text.size()) {
    const char quote = text[attr + 5];
    const std::size_t end = text.find(quote, attr + 6);
    if ((quote == '"' || quote == '\'') && end != std::string_view::npos && end - attr < 80)
      name = std::string(text.substr(attr + 6, end - attr - 6));
  }
  return name.empty() ? std::string("a URDF file.") : "a URDF file, robot " + name + ".";
}

}  // namespace

std::string headerSummary(const std::string& text, const std::string& name) {
  std::string joined;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + at, end - at);
    at = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() != ';') break;
    line.remove_prefix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    if (line.empty()) break;  // the header's first paragraph ends
    if (!joined.empty()) joined += ' ';
    joined += line;
  }
  // The first sentence: up to a full stop at the end or before a space and
  // a word that is not a number ("Figs. 4-7" goes on).
  const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  for (std::size_t i = 0; i < joined.size(); ++i)
    if (joined[i] == '.' && (i + 1 == joined.size() ||
                             (joined[i + 1] == ' ' && i + 2 < joined.size() && !isDigit(joined[i + 2])))) {
      joined.resize(i + 1);
      break;
    }
  const std::string prefix = name + ": ";
  if (joined.compare(0, prefix.size(), prefix) == 0) joined.erase(0, prefix.size());
  return joined;
}

LibraryListing listLibrary(const std::vector<fs::path>& searchPath) {
  LibraryListing listing{searchPath, {}, {}};
  std::set<std::string> found;  // kind and name of each entry found, for hiding
  for (const fs::path& dir : searchPath) {
    std::vector<fs::path> files = rsdFiles(dir);
    for (const ListedKind& k : kListedKinds)
      for (fs::path& f : rsdFiles(dir / k.folder)) files.push_back(std::move(f));
    for (const fs::path& file : files) {
      // The readers' own limit: a file listed is one a command can use, and
      // one that cannot be read is named, not left out in silence.
      base::FileRead read = base::readFile(file.string(), kMaxDescriptionBytes);
      if (!read.bytes) {
        listing.skipped.push_back({file, std::move(read.error)});
        continue;
      }
      const std::string name = file.stem().string();
      std::string summary = headerSummary(*read.bytes, name);
      diag::Diagnostics ignored(file.string());
      const DescriptionFile parsed =
          parseDescription(std::make_unique<diag::SourceFile>(file.string(), std::move(*read.bytes)), ignored);
      const std::string kind = kindDefined(parsed, name);
      if (kind.empty()) continue;
      const bool hidden = !found.insert(kind + ' ' + name).second;
      listing.entries.push_back({kind, name, file, std::move(summary), hidden});
    }
    // URDF files, named by their file name (docs/models.md, "Reading URDF").
    for (const fs::path& dirOrRobots : {dir, dir / "robots"})
      for (const fs::path& file : filesOf(dirOrRobots, ".urdf")) {
        // The URDF reader's own limit, as for descriptions above.
        base::FileRead read = base::readFile(file.string(), urdf::kMaxUrdfBytes);
        if (!read.bytes) {
          listing.skipped.push_back({file, std::move(read.error)});
          continue;
        }
        const std::string name = file.filename().string();
        const bool hidden = !found.insert("robot " + name).second;
        listing.entries.push_back({"robot", name, file, urdfSummary(*read.bytes), hidden});
      }
  }
  // stable: a hidden entry stays after the one found first on the path.
  std::stable_sort(listing.entries.begin(), listing.entries.end(), [](const LibraryEntry& a, const LibraryEntry& b) {
    const int ka = kindOrder(a.kind), kb = kindOrder(b.kind);
    return ka != kb ? ka < kb : a.name < b.name;
  });
  return listing;
}

}  // namespace rs::compiler
