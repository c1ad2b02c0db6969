#include "diag/diagnostic.h"

#include <algorithm>
#include <fmt/format.h>

#include "base/text.h"

namespace rs::diag {

bool hasErrors(std::span<const Diagnostic> diagnostics) {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return true;
  return false;
}

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
  // The file name may come from a file (an image records its source's
  // name) and a message may quote one: control characters are escaped.
  const std::string file = base::safeText(d.file);
  const std::string message = base::safeText(d.message);
  std::string out = d.pos.line ? fmt::format("{}:{}:{}: {}: {}\n", file, d.pos.line, d.pos.col,
                                             severityName(d.severity), message)
                               : fmt::format("{}: {}: {}\n", file, severityName(d.severity), message);
  if (source && d.pos.line != 0 && d.pos.line <= source->lineCount()) {
    const DisplayLine shown = displayLine(source->line(d.pos.line), d.pos.col);
    out += fmt::format("  {}\n  {}^\n", shown.text, shown.caretIndent);
  }
  if (!d.hint.empty()) out += fmt::format("  hint: {}\n", base::safeText(d.hint));
  return out;
}

DisplayLine displayLine(std::string_view line, std::uint32_t caretCol) {
  constexpr std::uint32_t kWidth = 100;  // columns of context shown at most
  const std::uint32_t first = caretCol > kWidth / 2 ? caretCol - kWidth / 2 : 1;
  DisplayLine out;
  if (first > 1) out.text = "...", out.caretIndent = "   ";
  std::uint32_t col = 1;
  for (std::size_t i = 0; i < line.size() && col < first + kWidth;) {
    std::size_t n = utf8SequenceLength(line, i);
    const auto c = static_cast<unsigned char>(line[i]);
    // Control characters and bytes that are not UTF-8 print as U+FFFD, one
    // column each, so the caret still lines up and no raw bytes reach a
    // terminal.
    const bool printable = n > 1 || (n == 1 && (c >= 0x20 || c == '\t') && c != 0x7F);
    if (n == 0) n = 1;
    if (col >= first) {
      out.text += printable ? std::string(line.substr(i, n)) : std::string("\xEF\xBF\xBD");
      if (col < caretCol) out.caretIndent += c == '\t' ? '\t' : ' ';
    }
    i += n;
    ++col;
  }
  if (col >= first + kWidth) out.text += "...";
  return out;
}

}  // namespace rs::diag
