#include "diag/diagnostic.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
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

Diagnostic Diagnostics::make(Pos pos, Severity s, std::string message, std::string_view code,
                              std::vector<Related> related, std::string hint) const {
  return {file_, pos, s, std::move(message), code, std::move(hint), std::move(related)};
}

void Diagnostics::add(Pos pos, Severity s, std::string message, std::string_view code, std::vector<Related> related,
                      std::string hint) {
  if (s == Severity::Error) ++errors_;
  const Key key{pos, reported_++, list_.size()};
  if (keep_ == 0) {
    list_.push_back(make(pos, s, std::move(message), code, std::move(related), std::move(hint)));
    return;
  }
  if (list_.size() < keep_) {
    heap_.push_back(key);
    std::push_heap(heap_.begin(), heap_.end(), before);
    list_.push_back(make(pos, s, std::move(message), code, std::move(related), std::move(hint)));
    return;
  }
  // Full: the new one replaces the last kept, if it comes before it.
  if (!before(key, heap_.front())) return omitted_.count(s);
  std::pop_heap(heap_.begin(), heap_.end(), before);
  const std::size_t slot = heap_.back().slot;
  omitted_.count(list_[slot].severity);
  heap_.back() = {pos, key.seq, slot};
  std::push_heap(heap_.begin(), heap_.end(), before);
  list_[slot] = make(pos, s, std::move(message), code, std::move(related), std::move(hint));
}

std::vector<Diagnostic> Diagnostics::sorted() const {
  if (keep_ == 0) {
    std::vector<Diagnostic> out = list_;
    std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
      return a.pos.line != b.pos.line ? a.pos.line < b.pos.line : a.pos.col < b.pos.col;
    });
    return out;
  }
  std::vector<Key> keys = heap_;
  std::sort(keys.begin(), keys.end(), before);
  std::vector<Diagnostic> out;
  out.reserve(keys.size());
  for (const Key& k : keys) out.push_back(list_[k.slot]);
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
    const DisplayLine shown = displayLine(*source, d.pos);
    out += fmt::format("  {}\n  {}^\n", shown.text, shown.caretIndent);
  }
  if (!d.hint.empty()) out += fmt::format("  hint: {}\n", base::safeText(d.hint));
  for (const Related& r : d.related)
    out += fmt::format("{}:{}:{}: note: {}\n", base::safeText(r.file), r.pos.line, r.pos.col, base::safeText(r.message));
  return out;
}

DisplayLine displayLine(const SourceFile& source, Pos pos) {
  constexpr std::uint32_t kWidth = 100;        // columns of context shown at most
  constexpr std::string_view kCut = "\u2026";  // "…", one column
  if (pos.line == 0 || pos.line > source.lineCount()) return {};
  const std::string_view text = source.text();
  const std::string_view line = source.line(pos.line);
  const std::uint32_t caretCol = std::max<std::uint32_t>(pos.col, 1);
  const std::uint32_t first = caretCol > kWidth / 2 ? caretCol - kWidth / 2 : 1;
  const auto lineEnd = static_cast<std::size_t>(line.data() - text.data()) + line.size();
  DisplayLine out;
  if (first > 1) out.text = kCut, out.caretIndent = " ";
  std::uint32_t col = first;
  std::size_t i = source.offsetOf({pos.line, first});
  for (; i < lineEnd && col < first + kWidth; ++col) {
    std::size_t n = utf8SequenceLength(text, i);
    const auto c = static_cast<unsigned char>(text[i]);
    // Control characters and bytes that are not UTF-8 print as U+FFFD, one
    // column each, so the caret still lines up and no raw bytes reach a
    // terminal.
    const bool printable = n > 1 || (n == 1 && (c >= 0x20 || c == '\t') && c != 0x7F);
    if (n == 0) n = 1;
    out.text += printable ? text.substr(i, n) : std::string_view("\xEF\xBF\xBD");
    if (col < caretCol) out.caretIndent += c == '\t' ? '\t' : ' ';
    i += n;
  }
  if (i < lineEnd) out.text += kCut;
  return out;
}

std::string excerpt(std::string_view text, std::size_t max) {
  std::uint32_t col = 0;
  const std::size_t cut = stepColumns(text, 0, text.size(), col, static_cast<std::uint32_t>(max), SIZE_MAX);
  if (cut >= text.size()) return std::string(text);
  return std::string(text.substr(0, cut)) + "\u2026";
}

}  // namespace rs::diag
