// textDocument/formatting: the column layout of the examples.
//
//   label:  INSTRUCTION operands        ; comment
//   ^ col 1 ^ label column               ^ comment column
//
// The label column is 8 wide, or one more than the longest "label:"; the
// comment column is at least 36, past the longest instruction that has a
// comment, on a multiple of 4. Taught points after POINTS line up: names
// left-aligned, each motor's values right-aligned in its own column.
// Whole-line comments at column 1 stay there; an indented one goes to the
// comment column when it continues the comment of the line above, else to
// the label column. Words are only re-spaced, never changed, and the
// result is checked: its tokens must be the original's, one for one, or
// nothing is changed. Formatting twice gives what formatting once does.
#include <algorithm>

#include "base/ascii.h"
#include "compiler/compiler.h"
#include "compiler/lexer.h"
#include "lsp/features/features.h"
#include "lsp/protocol.h"

namespace rs::lsp {

namespace {

constexpr std::size_t kMinLabelColumn = 8;
constexpr std::size_t kMinCommentColumn = 36;
constexpr std::size_t kLongCode = 60;  // longer code does not push the comment column

struct Line {
  std::string_view code;     // trimmed
  std::string_view comment;  // from ';', right-trimmed; empty when none
  bool indented = false;     // starts with a blank
  bool cr = false;           // ends in CR LF
  bool inPoints = false;     // after the POINTS line
  std::vector<std::string_view> words;
  std::string label;         // "name:" when the line starts with one
  std::string laidOut;       // the code, laid out
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> words;
  for (std::size_t i = 0; i < s.size();) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < s.size() && s[end] != ' ' && s[end] != '\t') ++end;
    if (end > i) words.push_back(s.substr(i, end - i));
    i = end;
  }
  return words;
}

std::string join(const std::vector<std::string_view>& words, std::size_t from) {
  std::string out;
  for (std::size_t i = from; i < words.size(); ++i) (out += i > from ? " " : "") += words[i];
  return out;
}

std::string padded(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::vector<Line> readLines(std::string_view text) {
  std::vector<Line> lines;
  bool inPoints = false;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    const bool last = end == std::string_view::npos;
    if (last) end = text.size();
    std::string_view raw = text.substr(start, end - start);
    Line l;
    if (!raw.empty() && raw.back() == '\r' && !last) l.cr = true, raw.remove_suffix(1);
    const std::size_t semi = raw.find(';');
    l.code = trim(raw.substr(0, semi));
    if (semi != std::string_view::npos) {
      l.comment = raw.substr(semi);
      while (!l.comment.empty() && (l.comment.back() == ' ' || l.comment.back() == '\t')) l.comment.remove_suffix(1);
    }
    l.indented = !raw.empty() && (raw[0] == ' ' || raw[0] == '\t');
    l.words = split(l.code);
    l.inPoints = inPoints;
    if (l.words.size() == 1 && base::sameName(l.words[0], "POINTS")) inPoints = true;
    lines.push_back(std::move(l));
    if (last) break;
    start = end + 1;
  }
  return lines;
}

// The sequence of tokens the compiler's lexer sees (type and text).
std::optional<std::vector<std::pair<std::size_t, std::string_view>>> tokens(const diag::SourceFile& source) {
  if (compiler::checkEncoding(source)) return std::nullopt;
  diag::Diagnostics ignored(source.name(), 1);
  compiler::Lexer lexer(source, ignored);
  std::vector<std::pair<std::size_t, std::string_view>> out;
  for (;;) {
    const compiler::RawToken t = lexer.scan();
    out.emplace_back(t.type, std::string_view(source.text()).substr(t.begin, t.end - t.begin));
    if (t.type == antlr4::Token::EOF) return out;
  }
}

bool sameTokens(std::string_view before, std::string_view after) {
  const diag::SourceFile a("before", std::string(before)), b("after", std::string(after));
  const auto ta = tokens(a), tb = tokens(b);
  if (!ta || !tb || ta->size() != tb->size()) return false;
  return *ta == *tb;
}

}  // namespace

std::optional<std::string> formatProgram(std::string_view text) {
  std::vector<Line> lines = readLines(text);
  // Labels, and the label column.
  std::size_t labelColumn = kMinLabelColumn;
  for (Line& l : lines) {
    if (l.inPoints || l.words.empty()) continue;
    const std::string_view first = l.words[0];
    if (first.size() > 1 && first.back() == ':') {
      l.label = std::string(first);
      l.words.erase(l.words.begin());
    } else if (l.words.size() >= 2 && l.words[1] == ":") {
      l.label = std::string(first) + ":";
      l.words.erase(l.words.begin(), l.words.begin() + 2);
    }
    if (!l.label.empty()) labelColumn = std::max(labelColumn, l.label.size() + 1);
  }
  // Taught points: the widths of their columns.
  std::size_t nameWidth = 0;
  std::vector<std::size_t> widths;
  for (const Line& l : lines) {
    if (!l.inPoints || l.words.empty()) continue;
    nameWidth = std::max(nameWidth, l.words[0].size());
    for (std::size_t i = 1; i < l.words.size(); ++i) {
      if (widths.size() < i) widths.push_back(0);
      widths[i - 1] = std::max(widths[i - 1], l.words[i].size());
    }
  }
  // The code of every line, laid out.
  for (Line& l : lines) {
    if (l.inPoints && !l.words.empty()) {
      l.laidOut = padded(std::string(l.words[0]), l.words.size() > 1 ? nameWidth : 0);
      for (std::size_t i = 1; i < l.words.size(); ++i)
        l.laidOut += std::string(2 + widths[i - 1] - l.words[i].size(), ' ') + std::string(l.words[i]);
    } else if (!l.words.empty() && l.words.size() == 1 && base::sameName(l.words[0], "POINTS") && l.label.empty()) {
      l.laidOut = std::string(l.words[0]);
    } else if (!l.words.empty()) {
      l.laidOut = padded(l.label, labelColumn) + join(l.words, 0);
    } else if (!l.label.empty()) {
      l.laidOut = l.label;
    }
  }
  std::size_t commentColumn = kMinCommentColumn;
  for (const Line& l : lines)
    if (!l.laidOut.empty() && !l.comment.empty() && l.laidOut.size() <= kLongCode)
      commentColumn = std::max(commentColumn, l.laidOut.size() + 2);
  commentColumn = (commentColumn + 3) / 4 * 4;
  // Whole lines.
  std::string out;
  out.reserve(text.size() + text.size() / 4);
  bool aligned = false;  // the line above has a comment at the comment column
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& l = lines[i];
    std::string line;
    if (!l.laidOut.empty()) {
      line = l.laidOut;
      if (!l.comment.empty()) line = padded(line + " ", commentColumn) + std::string(l.comment);
      aligned = !l.comment.empty();
    } else if (!l.comment.empty()) {
      const std::size_t column = !l.indented ? 0 : aligned ? commentColumn : labelColumn;
      line = std::string(column, ' ') + std::string(l.comment);
      aligned = l.indented && column == commentColumn;
    } else {
      aligned = false;
    }
    out += line;
    if (i + 1 < lines.size()) out += l.cr ? "\r\n" : "\n";
  }
  if (!sameTokens(text, out)) return std::nullopt;
  return out;
}

Json formatting(const Document& doc, Encoding enc) {
  const std::optional<std::string> formatted = formatProgram(doc.text());
  if (!formatted) return Json::array();
  // One edit per line that changed (lines map one to one).
  Document after("", Language::Program, 0, *formatted);
  Json edits = Json::array();
  for (std::uint32_t l = 0; l < doc.lineCount() && l < after.lineCount(); ++l) {
    const std::string_view was = doc.line(l), now = after.line(l);
    if (was == now) continue;
    edits.push_back(textEdit({{l, 0}, {l, unitsOf(was, enc)}}, std::string(now)));
  }
  return edits;
}

}  // namespace rs::lsp
