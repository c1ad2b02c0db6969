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
//
// Memory stays a small multiple of the document, whatever its size: the
// lines are read three times (columns, comment column, output) instead of
// being kept, the tokens of both texts are compared as two lexers produce
// them, and the answer has one edit per run of changed lines, or a single
// edit when there would be more than kMaxFormattingEdits. A document over
// kMaxFormattedBytes is refused: its answer could be a message larger than
// any the server accepts itself.
#include <fmt/format.h>

#include <algorithm>

#include "base/ascii.h"
#include "compiler/program/compiler.h"
#include "compiler/program/lexer.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"

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
  bool last = false;         // no line break after it
  bool inPoints = false;     // after the POINTS line
  std::vector<std::string_view> words;  // of the code, without the label
  std::string_view labelName;           // "name" when the line starts with "name:" (or "name :")
  bool labelled = false;
  std::size_t labelSize() const { return labelled ? labelName.size() + 1 : 0; }
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

void split(std::string_view s, std::vector<std::string_view>& words) {
  words.clear();
  for (std::size_t i = 0; i < s.size();) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < s.size() && s[end] != ' ' && s[end] != '\t') ++end;
    if (end > i) words.push_back(s.substr(i, end - i));
    i = end;
  }
}

bool isPointsLine(const Line& l) { return l.words.size() == 1 && !l.labelled && base::sameName(l.words[0], "POINTS"); }

// The lines of a text one at a time, in the one Line it refills.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(Line& l) {
    if (done_) return false;
    std::size_t end = text_.find('\n', start_);
    l.last = end == std::string_view::npos;
    if (l.last) end = text_.size();
    std::string_view raw = text_.substr(start_, end - start_);
    l.cr = !raw.empty() && raw.back() == '\r' && !l.last;
    if (l.cr) raw.remove_suffix(1);
    const std::size_t semi = raw.find(';');
    l.code = trim(raw.substr(0, semi));
    l.comment = {};
    if (semi != std::string_view::npos) {
      l.comment = raw.substr(semi);
      while (!l.comment.empty() && (l.comment.back() == ' ' || l.comment.back() == '\t')) l.comment.remove_suffix(1);
    }
    l.indented = !raw.empty() && (raw[0] == ' ' || raw[0] == '\t');
    split(l.code, l.words);
    l.inPoints = inPoints_;
    l.labelled = false;
    l.labelName = {};
    if (l.words.size() == 1 && base::sameName(l.words[0], "POINTS")) inPoints_ = true;
    if (!l.inPoints && !l.words.empty()) {
      const std::string_view first = l.words[0];
      if (first.size() > 1 && first.back() == ':') {
        l.labelled = true, l.labelName = first.substr(0, first.size() - 1);
        l.words.erase(l.words.begin());
      } else if (l.words.size() >= 2 && l.words[1] == ":") {
        l.labelled = true, l.labelName = first;
        l.words.erase(l.words.begin(), l.words.begin() + 2);
      }
    }
    if (l.last) done_ = true;
    start_ = end + 1;
    return true;
  }

 private:
  std::string_view text_;
  std::size_t start_ = 0;
  bool inPoints_ = false;
  bool done_ = false;
};

struct Columns {
  std::size_t label = kMinLabelColumn;
  std::size_t comment = kMinCommentColumn;
  std::size_t pointName = 0;
  std::vector<std::size_t> pointValues;  // the width of each motor's column
};

void pad(std::string& s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
}

// A line's code, laid out, into `out` (emptied first).
void layOut(const Line& l, const Columns& c, std::string& out) {
  out.clear();
  if (l.inPoints && !l.words.empty()) {
    out += l.words[0];
    if (l.words.size() > 1) pad(out, c.pointName);
    for (std::size_t i = 1; i < l.words.size(); ++i)
      out.append(2 + c.pointValues[i - 1] - l.words[i].size(), ' ').append(l.words[i]);
  } else if (isPointsLine(l)) {
    out += l.words[0];
  } else if (!l.words.empty()) {
    if (l.labelled) out.append(l.labelName).push_back(':');
    pad(out, c.label);
    for (std::size_t i = 0; i < l.words.size(); ++i) (out += i > 0 ? " " : "") += l.words[i];
  } else if (l.labelled) {
    out.append(l.labelName).push_back(':');
  }
}

Columns columnsOf(std::string_view text) {
  Columns c;
  Line l;
  for (LineReader lines(text); lines.next(l);) {
    if (l.labelled) c.label = std::max(c.label, l.labelSize() + 1);
    if (!l.inPoints || l.words.empty()) continue;
    c.pointName = std::max(c.pointName, l.words[0].size());
    for (std::size_t i = 1; i < l.words.size(); ++i) {
      if (c.pointValues.size() < i) c.pointValues.push_back(0);
      c.pointValues[i - 1] = std::max(c.pointValues[i - 1], l.words[i].size());
    }
  }
  std::string laidOut;
  for (LineReader lines(text); lines.next(l);) {
    if (l.comment.empty()) continue;
    layOut(l, c, laidOut);
    if (!laidOut.empty() && laidOut.size() <= kLongCode) c.comment = std::max(c.comment, laidOut.size() + 2);
  }
  c.comment = (c.comment + 3) / 4 * 4;
  return c;
}

// The compiler's lexer reads both texts to the same tokens (type and text),
// compared as they come.
bool sameTokens(const diag::SourceFile& a, const diag::SourceFile& b) {
  if (compiler::checkEncoding(a) || compiler::checkEncoding(b)) return false;
  diag::Diagnostics ignoredA(a.name(), 1), ignoredB(b.name(), 1);
  compiler::Lexer la(a, ignoredA), lb(b, ignoredB);
  const auto text = [](const diag::SourceFile& f, const compiler::RawToken& t) {
    return std::string_view(f.text()).substr(t.begin, t.end - t.begin);
  };
  for (;;) {
    const compiler::RawToken ta = la.scan(), tb = lb.scan();
    if (ta.type != tb.type || text(a, ta) != text(b, tb)) return false;
    if (ta.type == antlr4::Token::EOF) return true;
  }
}

// A line of a text (without its line break) and where the next begins.
std::string_view lineAt(std::string_view text, std::size_t& start) {
  const std::size_t end = std::min(text.find('\n', start), text.size());
  std::string_view line = text.substr(start, end - start);
  if (end < text.size() && !line.empty() && line.back() == '\r') line.remove_suffix(1);
  start = end + 1;
  return line;
}

}  // namespace

std::optional<std::string> formatProgram(std::string_view text) {
  return formatProgram(text, diag::SourceFile("before", std::string(text)));
}

std::optional<std::string> formatProgram(std::string_view text, const diag::SourceFile& source) {
  const Columns c = columnsOf(text);
  std::string out;
  out.reserve(text.size() + text.size() / 4);
  bool aligned = false;  // the line above has a comment at the comment column
  std::string laidOut;
  Line l;
  for (LineReader lines(text); lines.next(l);) {
    layOut(l, c, laidOut);
    const std::size_t before = out.size();
    if (!laidOut.empty()) {
      out += laidOut;
      if (!l.comment.empty()) {
        out += ' ';
        if (out.size() - before < c.comment) out.append(c.comment - (out.size() - before), ' ');
        out += l.comment;
      }
      aligned = !l.comment.empty();
    } else if (!l.comment.empty()) {
      const std::size_t column = !l.indented ? 0 : aligned ? c.comment : c.label;
      out.append(column, ' ').append(l.comment);
      aligned = l.indented && column == c.comment;
    } else {
      aligned = false;
    }
    if (!l.last) out += l.cr ? "\r\n" : "\n";
  }
  if (!sameTokens(source, diag::SourceFile("after", out))) return std::nullopt;
  return out;
}

Reply formatting(const ProgramContext& p) {
  const std::string& text = p.doc.text();
  if (text.size() > kMaxFormattedBytes)
    return RpcError{errc::kRequestFailed,
                    fmt::format("the document is {} MiB: robotsim formats programs up to {} MiB (its answer would be "
                                "a message larger than the server accepts)",
                                text.size() >> 20, kMaxFormattedBytes >> 20)};
  std::optional<std::string> formatted = formatProgram(text, p.analysis.source());
  if (!formatted) return Json::array();
  // Lines map one to one: each run of changed lines is one edit.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;
  std::size_t at = 0;
  for (std::uint32_t line = 0; line < p.doc.lineCount(); ++line) {
    if (lineAt(*formatted, at) == p.doc.line(line)) continue;
    if (!runs.empty() && runs.back().second + 1 == line) runs.back().second = line;
    else runs.emplace_back(line, line);
  }
  if (runs.size() > kMaxFormattingEdits) runs = {{runs.front().first, runs.back().second}};
  if (runs.size() == 1) {
    // One edit (every line, often): its text is cut from the formatted text
    // in place and moved into the answer, never copied.
    std::string text = std::move(*formatted);
    std::size_t from = 0, to = 0, line = 0;
    for (std::size_t at = 0; line <= runs[0].second; ++line) {
      if (line == runs[0].first) from = at;
      const std::string_view l = lineAt(text, at);
      to = static_cast<std::size_t>(l.data() - text.data()) + l.size();
    }
    text.erase(to);
    text.erase(0, from);
    return Json::array({textEdit({{runs[0].first, 0}, {runs[0].second, unitsOf(p.doc.line(runs[0].second), p.enc)}},
                                 std::move(text))});
  }
  Json edits = Json::array();
  std::size_t cursor = 0;
  std::uint32_t cursorLine = 0;
  for (const auto& [first, last] : runs) {
    for (; cursorLine < first; ++cursorLine) lineAt(*formatted, cursor);
    const std::size_t from = cursor;
    std::string_view end;
    for (; cursorLine <= last; ++cursorLine) end = lineAt(*formatted, cursor);
    const std::size_t to = static_cast<std::size_t>(end.data() - formatted->data()) + end.size();
    edits.push_back(textEdit({{first, 0}, {last, unitsOf(p.doc.line(last), p.enc)}}, formatted->substr(from, to - from)));
  }
  return edits;
}

}  // namespace rs::lsp
