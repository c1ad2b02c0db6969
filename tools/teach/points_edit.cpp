#include "tools/teach/points_edit.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "base/ascii.h"
#include "vm/opcodes.h"

namespace rs::teach {

namespace {

// A word of a line: [begin, end) byte offsets into its body.
struct Word {
  std::size_t begin = 0, end = 0;
};

// A line's words before its comment, as the language splits them: spaces
// and tabs separate, ';' starts a comment. `comment` is the ';' offset.
struct Scan {
  std::vector<Word> words;
  std::optional<std::size_t> comment;
  bool tabs = false;  // a tab before the comment
};

Scan scan(std::string_view body, std::size_t from = 0) {
  Scan s;
  std::size_t i = from;
  while (i < body.size()) {
    const char c = body[i];
    if (c == ';') {
      s.comment = i;
      break;
    }
    if (c == ' ' || c == '\t') {
      s.tabs |= c == '\t';
      ++i;
      continue;
    }
    Word w{i, i};
    while (w.end < body.size() && body[w.end] != ' ' && body[w.end] != '\t' && body[w.end] != ';') ++w.end;
    s.words.push_back(w);
    i = w.end;
  }
  return s;
}

std::string_view wordText(std::string_view body, const Word& w) { return body.substr(w.begin, w.end - w.begin); }

std::optional<std::int32_t> wholeNumber(std::string_view text) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  std::int32_t v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

// The UTF-8 byte-order mark the compiler ignores at the start of a file.
constexpr std::string_view kBom = "\xEF\xBB\xBF";

}  // namespace

std::string checkPointName(std::string_view name) {
  if (name.empty()) return "a point needs a name";
  if (name.size() > vm::kMaxNameLength)  // the compiler would refuse the program
    return fmt::format("a point name has at most {} characters (this one has {})", vm::kMaxNameLength, name.size());
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!letter(name[0]) || !std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || digit(c); }))
    return "a point name is letters, digits and '_', not starting with a digit";
  for (const vm::OpInfo& op : vm::kOps)
    if (base::sameName(op.name, name)) return fmt::format("{} is an instruction: it cannot name a point", op.name);
  for (std::string_view reserved : {"ON", "OFF", "POINTS"})
    if (base::sameName(reserved, name)) return fmt::format("{} is a reserved word: it cannot name a point", reserved);
  return {};
}

PointsText::PointsText(std::string_view text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) {
      lines_.push_back({std::string(text.substr(pos)), ""});
      break;
    }
    const bool cr = nl > pos && text[nl - 1] == '\r';
    lines_.push_back({std::string(text.substr(pos, nl - pos - (cr ? 1 : 0))), cr ? "\r\n" : "\n"});
    pos = nl + 1;
  }
  reparse();
}

// The POINTS line is the first whose only word is POINTS (any case); each
// line after it with a word is a row: a name, then its values.
void PointsText::reparse() {
  points_.clear();
  pointsLine_.reset();
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    const std::string_view body = lines_[l].body;
    const std::size_t from = l == 0 && body.starts_with(kBom) ? kBom.size() : 0;
    const Scan s = scan(body, from);
    if (!pointsLine_) {
      if (s.words.size() == 1 && base::sameName(wordText(body, s.words[0]), "POINTS")) pointsLine_ = l;
      continue;
    }
    if (s.words.empty()) continue;
    PointRow row;
    row.name = std::string(wordText(body, s.words[0]));
    row.line = l;
    row.pose = s.words.size() > 1 && base::sameName(wordText(body, s.words[1]), "AT");
    for (std::size_t w = 1; w < s.words.size(); ++w) {
      const std::optional<std::int32_t> v = wholeNumber(wordText(body, s.words[w]));
      if (v)
        row.values.push_back(*v);
      else
        row.readable = false;
    }
    points_.push_back(std::move(row));
  }
}

std::string PointsText::text() const {
  std::string out;
  for (const Line& l : lines_) out += l.body, out += l.end;
  return out;
}

std::optional<std::size_t> PointsText::find(std::string_view name) const {
  for (std::size_t i = 0; i < points_.size(); ++i)
    if (base::sameName(points_[i].name, name)) return i;
  return std::nullopt;
}

// The file's own line end: its first line's (a file in CR LF stays so).
std::string PointsText::lineEnd() const {
  for (const Line& l : lines_)
    if (!l.end.empty()) return l.end;
  return "\n";
}

// A row for `name` and `values`, laid out after the row on `templateLine`
// (see the header). Each value column's alignment is read from every
// readable row without tabs: right-aligned when they all end at one column,
// left-aligned when they all start at one, else at the template's end.
std::string PointsText::layoutRow(std::string_view name, std::span<const std::int32_t> values,
                                  std::optional<std::size_t> templateLine, bool keepComment) const {
  std::vector<std::string> fields{std::string(name)};
  for (std::int32_t v : values) fields.push_back(std::to_string(v));
  if (!templateLine) {
    std::string row = fields[0];
    for (std::size_t f = 1; f < fields.size(); ++f) row += ' ' + fields[f];
    return row;
  }
  const std::string_view body = lines_[*templateLine].body;
  const Scan t = scan(body);
  std::string row;
  if (t.tabs) {  // separators as they are
    row = std::string(body.substr(0, t.words.empty() ? 0 : t.words[0].begin)) + fields[0];
    for (std::size_t f = 1; f < fields.size(); ++f)
      row += (f < t.words.size() ? std::string(body.substr(t.words[f - 1].end, t.words[f].begin - t.words[f - 1].end))
                                 : std::string(" ")) +
             fields[f];
  } else {
    std::vector<Scan> rows;
    for (const PointRow& p : points_) {
      if (!p.readable) continue;
      Scan s = scan(lines_[p.line].body);
      if (!s.tabs) rows.push_back(std::move(s));
    }
    row = std::string(body.substr(0, t.words.empty() ? 0 : t.words[0].begin)) + fields[0];
    for (std::size_t f = 1; f < fields.size(); ++f) {
      std::size_t pad = 1;
      if (f < t.words.size()) {
        bool sameEnd = true, sameStart = true;
        for (const Scan& s : rows) {
          if (f >= s.words.size()) continue;
          sameEnd &= s.words[f].end == t.words[f].end;
          sameStart &= s.words[f].begin == t.words[f].begin;
        }
        const std::size_t at = row.size();
        if (!sameEnd && sameStart)
          pad = t.words[f].begin > at ? t.words[f].begin - at : 1;
        else
          pad = t.words[f].end > at + fields[f].size() ? t.words[f].end - at - fields[f].size() : 1;
      }
      row.append(pad, ' ');
      row += fields[f];
    }
  }
  if (keepComment && t.comment) {
    const std::size_t gapBefore = *t.comment - (t.words.empty() ? 0 : t.words.back().end);
    if (t.tabs)
      row += std::string(body.substr(*t.comment - gapBefore, gapBefore));
    else
      row.append(*t.comment > row.size() ? *t.comment - row.size() : std::min<std::size_t>(gapBefore, 1), ' ');
    row += body.substr(*t.comment);
  }
  return row;
}

std::optional<std::size_t> PointsText::countsTemplate() const {
  std::optional<std::size_t> templ;
  for (const PointRow& p : points_)
    if (p.readable && !scan(lines_[p.line].body).tabs) templ = p.line;
  if (!templ && !points_.empty()) templ = points_.back().line;
  return templ;
}

std::string PointsText::withComment(std::string row, std::size_t line) const {
  const std::string_view body = lines_[line].body;
  const Scan s = scan(body);
  if (!s.comment) return row;
  row.append(*s.comment > row.size() ? *s.comment - row.size() : 1, ' ');
  row += body.substr(*s.comment);
  return row;
}

std::string PointsText::add(std::string_view name, std::span<const std::int32_t> values) {
  if (std::string why = checkPointName(name); !why.empty()) return why;
  if (std::optional<std::size_t> p = find(name))
    return fmt::format("there is a point {} already (line {})", points_[*p].name, points_[*p].line + 1);
  const std::string row = layoutRow(name, values, countsTemplate(), false);
  const std::string eol = lineEnd();
  if (!pointsLine_) {
    const bool terminated = lines_.empty() || !lines_.back().end.empty();
    if (!lines_.empty() && !terminated) lines_.back().end = eol;
    lines_.push_back({"POINTS", eol});
    lines_.push_back({row, terminated ? eol : ""});
  } else {
    const std::size_t after = points_.empty() ? *pointsLine_ : points_.back().line;
    std::string end = lines_[after].end;
    if (end.empty()) lines_[after].end = eol;  // the last line, unterminated: the new row is now last
    lines_.insert(lines_.begin() + static_cast<std::ptrdiff_t>(after) + 1, Line{row, end.empty() ? "" : end});
  }
  reparse();
  return {};
}

std::string PointsText::replace(std::string_view name, std::span<const std::int32_t> values) {
  const std::optional<std::size_t> p = find(name);
  if (!p) return fmt::format("there is no point {}", name);
  const PointRow& row = points_[*p];
  Line& line = lines_[row.line];
  if (row.pose) {
    // Its words are a pose, not a row of counts to line up with: laid out like the rows of counts.
    std::optional<std::size_t> templ = countsTemplate();
    if (templ == row.line) templ.reset();
    line.body = withComment(layoutRow(row.name, values, templ, false), row.line);
  } else {
    line.body = layoutRow(row.name, values, row.line, true);
  }
  reparse();
  return {};
}

std::string PointsText::replacePose(std::string_view name, std::string_view pose) {
  const std::optional<std::size_t> p = find(name);
  if (!p) return fmt::format("there is no point {}", name);
  const std::size_t l = points_[*p].line;
  const std::string_view body = lines_[l].body;
  const Scan s = scan(body, l == 0 && body.starts_with(kBom) ? kBom.size() : 0);
  // The name as it stands, then the gap it had before its first value (at least one space).
  const std::size_t nameEnd = s.words[0].end;
  std::string row(body.substr(0, nameEnd));
  row += s.words.size() > 1 ? std::string(body.substr(nameEnd, s.words[1].begin - nameEnd)) : std::string(" ");
  row += pose;
  lines_[l].body = withComment(std::move(row), l);
  reparse();
  return {};
}

std::string PointsText::remove(std::string_view name) {
  const std::optional<std::size_t> p = find(name);
  if (!p) return fmt::format("there is no point {}", name);
  // Only the row goes: the line before it keeps its line end, even when
  // the row was the last line and had none.
  const std::size_t l = points_[*p].line;
  lines_.erase(lines_.begin() + static_cast<std::ptrdiff_t>(l));
  reparse();
  return {};
}

std::string PointsText::rename(std::string_view from, std::string_view to) {
  const std::optional<std::size_t> p = find(from);
  if (!p) return fmt::format("there is no point {}", from);
  if (std::string why = checkPointName(to); !why.empty()) return why;
  if (std::optional<std::size_t> q = find(to); q && *q != *p)
    return fmt::format("there is a point {} already (line {})", points_[*q].name, points_[*q].line + 1);
  const PointRow& row = points_[*p];
  if (row.pose) {  // only the name changes: the pose's words stay as written
    Line& line = lines_[row.line];
    const Scan s = scan(line.body, row.line == 0 && line.body.starts_with(kBom) ? kBom.size() : 0);
    line.body.replace(s.words[0].begin, s.words[0].end - s.words[0].begin, to);
    reparse();
    return {};
  }
  if (!row.readable) return fmt::format("point {} has a value that is not a whole number: fix it in an editor", row.name);
  const std::vector<std::int32_t> values = row.values;
  lines_[row.line].body = layoutRow(to, values, row.line, true);
  reparse();
  return {};
}

}  // namespace rs::teach
