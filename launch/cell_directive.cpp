#include "launch/cell_directive.h"

#include <filesystem>
#include <system_error>

#include "base/ascii.h"

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
std::optional<CellDirective> onLine(std::string_view line) {
  constexpr std::string_view kKey = "cell:";
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

std::optional<CellDirective> findCellDirective(std::string_view text) {
  std::uint32_t lineNumber = 1;
  for (std::size_t start = 0; start <= text.size(); ++lineNumber) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (std::optional<CellDirective> d = onLine(text.substr(start, end - start))) {
      d->pos.line = lineNumber;
      d->offset += start;
      return d;
    }
    start = end + 1;
  }
  return std::nullopt;
}

std::string resolveCellName(const std::string& programFile, const std::string& name) {
  std::error_code ec;
  const std::filesystem::path beside = std::filesystem::path(programFile).parent_path() / name;
  if (!std::filesystem::path(name).is_absolute() && std::filesystem::is_regular_file(beside, ec))
    return beside.string();
  return name;
}

}  // namespace rs::launch
