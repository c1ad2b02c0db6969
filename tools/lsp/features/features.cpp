#include "tools/lsp/features/features.h"

#include <cctype>

#include "base/ascii.h"

namespace rs::lsp {

const Occurrence* occurrenceAt(const ProgramContext& p, Position at) {
  return p.analysis.index().occurrenceAt(p.doc.toPos(at, p.enc));
}

Range rangeOf(const ProgramContext& p, const Occurrence& o) { return p.doc.rangeOf(o.pos, o.length, p.enc); }

std::string_view codeOf(std::string_view line) {
  line = line.substr(0, line.find(';'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.remove_suffix(1);
  return line;
}

std::string_view instructionText(const ProgramContext& p, const IndexedInstruction& in) {
  const Position at = p.doc.fromPos(in.pos, Encoding::Utf8);
  const std::string_view code = codeOf(p.doc.line(at.line));
  return at.character <= code.size() ? code.substr(at.character) : std::string_view();
}

bool fuzzyMatch(std::string_view query, std::string_view name) {
  std::size_t i = 0;
  for (const char c : name)
    if (i < query.size() && base::asciiUpper(c) == base::asciiUpper(query[i])) ++i;
  return i == query.size();
}

}  // namespace rs::lsp
