// Document symbols (the outline: subroutines with the labels inside them,
// other labels, the POINTS section with its points) and workspace symbols.
#include <fmt/format.h>

#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"

namespace rs::lsp {

namespace {

Range wholeLines(const ProgramContext& p, std::uint32_t first, std::uint32_t last) {
  return {{first - 1, 0}, {last - 1, unitsOf(p.doc.line(last - 1), p.enc)}};
}

Json symbol(std::string name, std::string detail, int kind, const Range& range, const Range& selection) {
  return {{"name", std::move(name)}, {"detail", std::move(detail)}, {"kind", kind},
          {"range", toJson(range)}, {"selectionRange", toJson(selection)}};
}

}  // namespace

Json documentSymbols(const ProgramContext& p) {
  const ProgramIndex& index = p.analysis.index();
  const auto extents = subroutineExtents(p);
  Json out = Json::array();
  Json* current = nullptr;  // the subroutine whose extent we are in
  std::size_t next = 0;     // the next extent
  std::uint32_t currentEnd = 0;
  for (const IndexedInstruction& in : index.instructions()) {
    if (in.label.empty()) continue;
    const Range selection = p.doc.rangeOf(in.labelPos, in.label.size(), p.enc);
    if (current && in.labelPos.line > currentEnd) current = nullptr;
    if (next < extents.size() && extents[next].first == in.labelPos.line) {
      currentEnd = extents[next].second;
      out.push_back(symbol(std::string(in.label), fmt::format("subroutine, instruction {}", in.number),
                           symbol_kind::kFunction, wholeLines(p, extents[next].first, currentEnd), selection));
      out.back()["children"] = Json::array();
      current = &out.back();
      ++next;
      continue;
    }
    Json label = symbol(std::string(in.label), fmt::format("instruction {}", in.number), symbol_kind::kKey,
                        wholeLines(p, in.labelPos.line, in.pos.line), selection);
    if (current)
      (*current)["children"].push_back(std::move(label));
    else
      out.push_back(std::move(label));
  }
  if (index.pointsHeader().line != 0) {
    const std::uint32_t header = index.pointsHeader().line;
    const std::uint32_t last = index.points().empty() ? header : index.points().back().pos.line;
    Json section = symbol("POINTS", fmt::format("{} taught points", index.points().size()), symbol_kind::kNamespace,
                          wholeLines(p, header, last), p.doc.rangeOf(index.pointsHeader(), 6, p.enc));
    section["children"] = Json::array();
    for (const IndexedPoint& point : index.points())
      section["children"].push_back(symbol(std::string(point.name), "point", symbol_kind::kConstant,
                                           wholeLines(p, point.pos.line, point.pos.line),
                                           p.doc.rangeOf(point.pos, point.name.size(), p.enc)));
    out.push_back(std::move(section));
  }
  return out;
}

void workspaceSymbols(const ProgramContext& p, std::string_view query, Json& into) {
  const ProgramIndex& index = p.analysis.index();
  const std::string container = p.analysis.source().name();
  for (const IndexedInstruction& in : index.instructions())
    if (!in.label.empty() && fuzzyMatch(query, in.label))
      into.push_back({{"name", std::string(in.label)},
                      {"kind", index.isSubroutine(in.label) ? symbol_kind::kFunction : symbol_kind::kKey},
                      {"location", location(p.doc.uri(), p.doc.rangeOf(in.labelPos, in.label.size(), p.enc))},
                      {"containerName", container}});
  for (const IndexedPoint& point : index.points())
    if (fuzzyMatch(query, point.name))
      into.push_back({{"name", std::string(point.name)},
                      {"kind", symbol_kind::kConstant},
                      {"location", location(p.doc.uri(), p.doc.rangeOf(point.pos, point.name.size(), p.enc))},
                      {"containerName", container}});
}

}  // namespace rs::lsp
