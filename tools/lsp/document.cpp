#include "tools/lsp/document.h"

#include <algorithm>

namespace rs::lsp {

namespace {

// Bytes of the UTF-8 character starting with `lead` (1 for a byte that
// starts none: text from JSON is valid UTF-8, but be safe).
std::size_t charBytes(unsigned char lead) {
  if (lead < 0x80) return 1;
  if ((lead & 0xE0) == 0xC0) return 2;
  if ((lead & 0xF0) == 0xE0) return 3;
  if ((lead & 0xF8) == 0xF0) return 4;
  return 1;
}

bool endsWith(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

}  // namespace

Language languageOf(std::string_view languageId, std::string_view uri) {
  if (languageId == "robotsim-program" || languageId == "rsp") return Language::Program;
  if (languageId == "robotsim-description" || languageId == "rsd") return Language::Description;
  if (languageId == "robotsim-stimuli" || languageId == "stim") return Language::Stimuli;
  if (endsWith(uri, ".rsp")) return Language::Program;
  if (endsWith(uri, ".rsd")) return Language::Description;
  if (endsWith(uri, ".stim")) return Language::Stimuli;
  if (languageId == "urdf" || endsWith(uri, ".urdf")) return Language::Urdf;
  return Language::Other;
}

std::uint32_t unitsOf(std::string_view text, Encoding enc) {
  if (enc == Encoding::Utf8) return static_cast<std::uint32_t>(text.size());
  std::uint32_t units = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = charBytes(static_cast<unsigned char>(text[i]));
    units += n == 4 ? 2 : 1;  // beyond the BMP: a surrogate pair
    i += n;
  }
  return units;
}

std::size_t bytesFor(std::string_view line, std::uint32_t units, Encoding enc) {
  std::size_t i = 0;
  std::uint32_t u = 0;
  while (i < line.size()) {
    const std::size_t n = std::min(charBytes(static_cast<unsigned char>(line[i])), line.size() - i);
    const std::uint32_t w = enc == Encoding::Utf8 ? static_cast<std::uint32_t>(n) : (n == 4 ? 2 : 1);
    if (u + w > units) break;
    u += w;
    i += n;
  }
  return i;
}

Document::Document(std::string uri, Language language, std::int64_t version, std::string text)
    : uri_(std::move(uri)), language_(language), version_(version), text_(std::move(text)) {
  index();
}

void Document::index() {
  lineStarts_.clear();
  lineStarts_.push_back(0);
  for (std::size_t i = text_.find('\n'); i != std::string::npos; i = text_.find('\n', i + 1))
    lineStarts_.push_back(i + 1);
  ++revision_;
}

std::size_t Document::lineStart(std::uint32_t i) const {
  return i < lineStarts_.size() ? lineStarts_[i] : text_.size();
}

std::string_view Document::line(std::uint32_t i) const {
  if (i >= lineStarts_.size()) return {};
  const std::size_t start = lineStarts_[i];
  std::size_t end = i + 1 < lineStarts_.size() ? lineStarts_[i + 1] - 1 : text_.size();
  if (end > start && i + 1 < lineStarts_.size() && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(start, end - start);
}

std::size_t Document::offsetOf(Position p, Encoding enc) const {
  if (p.line >= lineStarts_.size()) return text_.size();
  return lineStarts_[p.line] + bytesFor(line(p.line), p.character, enc);
}

Position Document::positionOf(std::size_t offset, Encoding enc) const {
  offset = std::min(offset, text_.size());
  const auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
  const auto l = static_cast<std::uint32_t>(it - lineStarts_.begin() - 1);
  const std::string_view text = line(l);
  const std::size_t within = std::min(offset - lineStarts_[l], text.size());
  return {l, unitsOf(text.substr(0, within), enc)};
}

Position Document::fromPos(diag::Pos pos, Encoding enc) const {
  if (pos.line == 0 || pos.line > lineStarts_.size()) return {};
  const std::uint32_t l = pos.line - 1;
  const std::string_view text = line(l);
  // Columns count characters: step over col-1 of them (after a byte-order
  // mark, which the compiler does not see).
  std::size_t i = l == 0 ? text.size() - diag::withoutByteOrderMark(text).size() : 0;
  for (std::uint32_t c = 1; c < pos.col && i < text.size(); ++c)
    i += std::min(charBytes(static_cast<unsigned char>(text[i])), text.size() - i);
  return {l, unitsOf(text.substr(0, i), enc)};
}

diag::Pos Document::toPos(Position p, Encoding enc) const {
  const std::string_view text = line(p.line);
  const std::size_t bytes = bytesFor(text, p.character, enc);
  std::uint32_t col = 1;
  for (std::size_t i = p.line == 0 ? text.size() - diag::withoutByteOrderMark(text).size() : 0; i < bytes; i += charBytes(static_cast<unsigned char>(text[i]))) ++col;
  return {p.line + 1, col};
}

Range Document::rangeOf(diag::Pos pos, std::size_t length, Encoding enc) const {
  const Position start = fromPos(pos, enc);
  const std::size_t begin = offsetOf(start, enc);
  return {start, positionOf(begin + length, enc)};
}

Range Document::wordAt(diag::Pos pos, Encoding enc) const {
  if (pos.line == 0 || pos.line > lineStarts_.size()) return {};
  const std::string_view text = line(pos.line - 1);
  const std::size_t skip = pos.line == 1 ? text.size() - diag::withoutByteOrderMark(text).size() : 0;
  return wordRange(text.substr(skip), pos.line - 1, pos.col, unitsOf(text.substr(0, skip), enc), enc);
}

Range wordRange(std::string_view line, std::uint32_t lineIndex, std::uint32_t col, std::uint32_t lead, Encoding enc) {
  std::size_t i = 0;
  for (std::uint32_t c = 1; c < col && i < line.size(); ++c)
    i += std::min(charBytes(static_cast<unsigned char>(line[i])), line.size() - i);
  std::size_t end = i;
  while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != ';') ++end;
  if (end == i && i < line.size()) end = std::min(i + charBytes(static_cast<unsigned char>(line[i])), line.size());
  return {{lineIndex, lead + unitsOf(line.substr(0, i), enc)}, {lineIndex, lead + unitsOf(line.substr(0, end), enc)}};
}

void Document::edit(const std::optional<Range>& range, std::string_view text, Encoding enc) {
  if (!range) {
    text_.assign(text);
  } else {
    std::size_t begin = offsetOf(range->start, enc), end = offsetOf(range->end, enc);
    if (end < begin) std::swap(begin, end);
    text_.replace(begin, end - begin, text);
  }
  index();
}

}  // namespace rs::lsp
