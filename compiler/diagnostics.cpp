#include "compiler/diagnostics.h"

#include <algorithm>
#include <fmt/format.h>

namespace rs::compiler {

std::string_view severityName(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

void Diagnostics::add(Pos pos, Severity s, std::string message) {
  if (s == Severity::Error) ++errors_;
  list_.push_back({file_, pos, s, std::move(message)});
}

std::vector<Diagnostic> Diagnostics::sorted() const {
  std::vector<Diagnostic> out = list_;
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.col < b.pos.col;
  });
  return out;
}

std::string render(const Diagnostic& d, const SourceFile* source) {
  std::string out = d.pos.line ? fmt::format("{}:{}:{}: {}: {}\n", d.file, d.pos.line, d.pos.col,
                                             severityName(d.severity), d.message)
                               : fmt::format("{}: {}: {}\n", d.file, severityName(d.severity), d.message);
  if (!source || d.pos.line == 0 || d.pos.line > source->lineCount()) return out;
  const std::string_view line = source->line(d.pos.line);
  out += fmt::format("  {}\n  ", line);
  // Walk code points up to the column; keep tabs so the caret lines up.
  std::uint32_t col = 1;
  for (std::size_t i = 0; i < line.size() && col < d.pos.col; ++i) {
    if ((static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) continue;
    out += line[i] == '\t' ? '\t' : ' ';
    ++col;
  }
  out += "^\n";
  return out;
}

}  // namespace rs::compiler
