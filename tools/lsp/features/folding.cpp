// Folding ranges: the POINTS section, blocks of two or more comment lines,
// and subroutines (from the entry's label to the last instruction before
// the next subroutine).
#include "tools/lsp/features/features.h"

namespace rs::lsp {

namespace {

bool commentLine(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == ';';
}

Json fold(std::uint32_t first, std::uint32_t last, const char* kind = nullptr) {
  Json j = {{"startLine", first}, {"endLine", last}};
  if (kind) j["kind"] = kind;
  return j;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> subroutineExtents(const ProgramContext& p) {
  const ProgramIndex& index = p.analysis.index();
  const std::vector<IndexedInstruction>& code = index.instructions();
  std::vector<std::uint32_t> entries;  // 0-based instruction indices
  for (const IndexedInstruction& in : code)
    if (!in.label.empty() && index.isSubroutine(in.label)) entries.push_back(in.number - 1);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::uint32_t last = i + 1 < entries.size() ? entries[i + 1] - 1 : static_cast<std::uint32_t>(code.size() - 1);
    out.emplace_back(code[entries[i]].labelPos.line, code[last].pos.line);
  }
  return out;
}

Json foldingRanges(const ProgramContext& p) {
  Json out = Json::array();
  for (const auto& [first, last] : subroutineExtents(p))
    if (last > first) out.push_back(fold(first - 1, last - 1, "region"));
  const ProgramIndex& index = p.analysis.index();
  if (index.pointsHeader().line != 0 && !index.points().empty() &&
      index.points().back().pos.line > index.pointsHeader().line)
    out.push_back(fold(index.pointsHeader().line - 1, index.points().back().pos.line - 1, "region"));
  const std::uint32_t lines = p.doc.lineCount();
  for (std::uint32_t l = 0; l < lines;) {
    if (!commentLine(p.doc.line(l))) {
      ++l;
      continue;
    }
    std::uint32_t end = l;
    while (end + 1 < lines && commentLine(p.doc.line(end + 1))) ++end;
    if (end > l) out.push_back(fold(l, end, "comment"));
    l = end + 1;
  }
  return out;
}

}  // namespace rs::lsp
