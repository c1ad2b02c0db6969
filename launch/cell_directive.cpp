#include "launch/cell_directive.h"

#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include <cctype>

#include "base/ascii.h"
#include "base/text.h"
#include "launch/confined_path.h"

namespace rs::launch {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

// Characters (not bytes) in text[from, to): the column a name starts at.
std::uint32_t characters(std::string_view text, std::size_t from, std::size_t to) {
  std::uint32_t n = 0;
  for (std::size_t i = from; i < to; ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++n;
  return n;
}

// The directive's name on one line (without its line break), if any.
std::optional<CellDirective> onLine(std::string_view line, std::string_view kKey) {
  std::size_t i = 0;
  while (i < line.size() && blank(line[i])) ++i;
  if (i >= line.size() || line[i] != ';') return std::nullopt;
  ++i;
  while (i < line.size() && blank(line[i])) ++i;
  if (line.size() - i < kKey.size() || !base::sameName(line.substr(i, kKey.size()), kKey)) return std::nullopt;
  i += kKey.size();
  while (i < line.size() && blank(line[i])) ++i;
  std::size_t end = i;
  while (end < line.size() && !blank(line[end]) && line[end] != '\r') ++end;
  if (end == i) return std::nullopt;
  return CellDirective{std::string(line.substr(i, end - i)), {0, characters(line, 0, i) + 1}, i};
}

}  // namespace

std::optional<CellDirective> findDirective(std::string_view text, std::string_view key) {
  std::uint32_t lineNumber = 1;
  for (std::size_t start = 0; start <= text.size(); ++lineNumber) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (std::optional<CellDirective> d = onLine(text.substr(start, end - start), key)) {
      d->pos.line = lineNumber;
      d->offset += start;
      return d;
    }
    start = end + 1;
  }
  return std::nullopt;
}

std::optional<CellDirective> findCellDirective(std::string_view text) { return findDirective(text, "cell:"); }

std::optional<CellDirective> findRobotDirective(std::string_view text) { return findDirective(text, "robot:"); }

std::string resolveCellName(const std::string& programFile, const std::string& name) {
  std::error_code ec;
  const std::filesystem::path beside = std::filesystem::path(programFile).parent_path() / name;
  // Anything there but a folder: a FIFO or a device beside the program is
  // then refused by its reader as what it is, not looked up as a name.
  if (!std::filesystem::path(name).is_absolute() && std::filesystem::exists(beside, ec) &&
      !std::filesystem::is_directory(beside, ec))
    return beside.string();
  return name;
}

namespace {

// The directive's name as a message may quote it: made safe, and short.
std::string quotedName(std::string_view name) {
  constexpr std::size_t kLongest = 60;
  if (name.size() <= kLongest) return "'" + base::safeText(name) + "'";
  return "'" + base::safeText(name.substr(0, kLongest)) + "...'";
}

diag::Result<SubmissionCell> refused(const std::string& programFile, const CellDirective& d, const std::string& why) {
  return diag::Diagnostic{programFile,
                          d.pos,
                          diag::Severity::Error,
                          fmt::format("the cell {} is refused: {}", quotedName(d.name), why),
                          "cell-outside-submission",
                          "a submission's '; cell:' names a library robot or cell (robotsim list) or a .rsd file in "
                          "its own folder"};
}

// A name as the library looks it up (stdlib's "scara-pick"): no path.
bool isLibraryName(std::string_view name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

}  // namespace

diag::Result<SubmissionCell> resolveSubmissionCell(const std::string& programFile, const CellDirective& d) {
  namespace fs = std::filesystem;
  const fs::path written(d.name);
  if (written.is_absolute()) return refused(programFile, d, "it is an absolute path");
  std::error_code ec;
  const fs::path besideFolder = fs::absolute(programFile, ec).parent_path();
  const diag::Result<fs::path> folder = resolve(besideFolder, true);
  if (ec || !folder) return refused(programFile, d, "the submission's own folder cannot be followed");
  const fs::path beside = fs::path(programFile).parent_path() / written;
  const bool exists = fs::exists(fs::symlink_status(beside, ec));
  if (!exists && isLibraryName(d.name)) return SubmissionCell{d.name, true};
  if (!exists) return refused(programFile, d, "there is no such file in the submission's folder");
  const diag::Result<fs::path> target = resolve(beside, true);
  if (!target) return refused(programFile, d, "its links cannot be followed");
  if (!isInside(*folder, *target)) return refused(programFile, d, "it leads outside the submission's folder");
  if (!fs::is_regular_file(*target, ec)) return refused(programFile, d, "it is not a regular file");
  return SubmissionCell{beside.lexically_normal().string(), false};
}

}  // namespace rs::launch
