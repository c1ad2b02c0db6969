#include "compiler/description/description_cursor.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "RobotModelLexer.h"
#include "base/ascii.h"
#include "base/near_names.h"

namespace rs::compiler::description_detail {

namespace {

using MP = rs_grammar::RobotModelLexer;  // its token types
using workcell::Color;

constexpr double kMaxCoordinate = 1e9;

}  // namespace

std::string didYouMean(std::string_view word, std::string_view list) {
  std::vector<std::string_view> keywords;
  for (std::size_t i = 0; i < list.size();) {
    std::size_t j = i;
    while (j < list.size() && std::isalnum(static_cast<unsigned char>(list[j]))) ++j;
    if (j > i && list.substr(i, j - i) != "or") keywords.push_back(list.substr(i, j - i));
    i = j == i ? i + 1 : j;
  }
  const std::string_view near = base::nearestName(word, keywords, base::typoDistance(word));
  return near.empty() ? std::string() : fmt::format("did you mean '{}'?", near);
}

bool Cursor::keyword(std::string_view kw) {
  if (atEnd() || peek().type != MP::NAME || !base::sameName(peek().text, kw)) return false;
  ++i_;
  return true;
}

bool Cursor::isKeyword(std::string_view kw) const {
  return !atEnd() && peek().type == MP::NAME && base::sameName(peek().text, kw);
}

bool Cursor::isName() const { return !atEnd() && peek().type == MP::NAME; }

void Cursor::error(diag::Pos at, std::string message, std::string hint) {
  if (hint.empty() && !form_.empty()) hint = fmt::format("a {} line reads {}", formKeyword_, form_);
  diag_.error(at, std::move(message), diag::Hint{std::move(hint)});
}

bool Cursor::failAt(diag::Pos at, std::string message, std::string hint) {
  error(at, std::move(message), std::move(hint));
  return false;
}

bool Cursor::fail(std::string_view what, std::string hint) {
  error(pos(),
              atEnd() ? fmt::format("expected {} before the end of the line", what)
                      : fmt::format("expected {}, found '{}'", what, diag::excerpt(peek().text)),
              std::move(hint));
  return false;
}

bool Cursor::failOneOf(std::string_view keywords) {
  return fail(keywords, atEnd() || peek().type != MP::NAME ? std::string() : didYouMean(peek().text, keywords));
}

bool Cursor::number(double& out, std::string_view what) {
  if (atEnd() || peek().type != MP::NUMBER) return fail(what);
  if (std::string written, plain; exponent(written, plain)) {
    error(pos(), fmt::format("'{}': exponents are not supported in descriptions", diag::excerpt(written)),
          plain.empty() ? std::string("write the number in full, with its decimals") : fmt::format("write {}", plain));
    return false;
  }
  const std::string& t = peek().text;
  const char* first = t.data() + (t[0] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), out);
  if (ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(out) || std::abs(out) > kMaxCoordinate)
    return fail(fmt::format("{} (at most {:g} in size)", what, kMaxCoordinate));
  ++i_;
  return true;
}

// "6e0", "1.5E3", "2e-3", "1e+3": the lexer reads a number, then a name
// (or "e" and a signed number) right after it. On true, `written` is the
// whole text and `plain` the same value without an exponent ("" if too long).
bool Cursor::exponent(std::string& written, std::string& plain) const {
  const Word& n = w_[i_];
  const auto adjacent = [](const Word& a, const Word& b) {
    return b.pos.line == a.pos.line && b.pos.col == a.pos.col + a.text.size();
  };
  if (i_ + 1 >= w_.size()) return false;
  const Word& e = w_[i_ + 1];
  if (e.type != MP::NAME || !adjacent(n, e) || (e.text[0] != 'e' && e.text[0] != 'E')) return false;
  std::string power = e.text.substr(1);
  written = n.text + e.text;
  if (power.empty() && i_ + 2 < w_.size() && w_[i_ + 2].type == MP::NUMBER && adjacent(e, w_[i_ + 2]) &&
      (w_[i_ + 2].text[0] == '+' || w_[i_ + 2].text[0] == '-')) {
    power = w_[i_ + 2].text;
    written += power;
  }
  const std::size_t signs = !power.empty() && (power[0] == '+' || power[0] == '-') ? 1 : 0;
  if (power.size() == signs ||
      !std::all_of(power.begin() + static_cast<std::ptrdiff_t>(signs), power.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  plain = withoutExponent(n.text, power.size() - signs > 3 ? 1000 : std::stoi(power));
  return true;
}

// "1.5" shifted by 10^k, exactly, as decimal text ("1500"); "" when the
// shift is beyond what anyone would write out.
std::string Cursor::withoutExponent(std::string_view mantissa, int k) {
  if (k > 20 || k < -20) return {};
  std::string sign;
  if (mantissa[0] == '+' || mantissa[0] == '-') sign = mantissa[0] == '-' ? "-" : "", mantissa.remove_prefix(1);
  const std::size_t dot = mantissa.find('.');
  const std::string whole(mantissa.substr(0, dot));
  const std::string frac = dot == std::string_view::npos ? "" : std::string(mantissa.substr(dot + 1));
  std::string digits = whole + frac;
  long point = static_cast<long>(whole.size()) + k;
  if (point <= 0) digits.insert(0, static_cast<std::size_t>(-point) + 1, '0'), point = 1;
  if (static_cast<std::size_t>(point) >= digits.size()) digits.append(static_cast<std::size_t>(point) - digits.size(), '0');
  std::string intPart = digits.substr(0, static_cast<std::size_t>(point));
  std::string fracPart = digits.substr(static_cast<std::size_t>(point));
  intPart.erase(0, std::min(intPart.find_first_not_of('0'), intPart.size() - 1));
  while (!fracPart.empty() && fracPart.back() == '0') fracPart.pop_back();
  const std::string text = fracPart.empty() ? intPart : intPart + "." + fracPart;
  return text == "0" ? text : sign + text;
}

bool Cursor::integer(std::int32_t& out, std::string_view what) {
  double v = 0;
  const diag::Pos at = pos();
  if (!number(v, what)) return false;
  if (v != std::floor(v) || v < -2147483648.0 || v > 2147483647.0) {
    error(at, fmt::format("expected {} (a whole number), found '{}'", what, diag::excerpt(w_[i_ - 1].text)), {});
    return false;
  }
  out = static_cast<std::int32_t>(v);
  return true;
}

bool Cursor::point(Point3& out, std::string_view what) {
  out.pos = pos();
  for (int k = 0; k < 3; ++k)
    if (!number(out.v[k], fmt::format("{} ({} coordinate)", what, "xyz"[k]))) return false;
  return true;
}

bool Cursor::name(NameRef& out, std::string_view what) {
  if (atEnd() || peek().type != MP::NAME) return fail(what);
  out = {peek().text, peek().pos};
  ++i_;
  return true;
}

bool Cursor::path(NameRef& out, std::string_view what) {
  if (atEnd()) return fail(what);
  out = {peek().text, peek().pos};
  diag::Pos next = peek().pos;
  next.col += static_cast<std::uint32_t>(peek().text.size());
  ++i_;
  while (!atEnd() && peek().pos.line == next.line && peek().pos.col == next.col) {
    out.name += peek().text;
    next.col += static_cast<std::uint32_t>(peek().text.size());
    ++i_;
  }
  return true;
}

bool Cursor::letter(char& out, diag::Pos& at) {
  at = pos();
  if (atEnd() || peek().type != MP::NAME || peek().text.size() != 1 || !std::isalpha(static_cast<unsigned char>(peek().text[0])))
    return fail("a motor letter A..Z");
  out = base::asciiUpper(peek().text[0]);
  ++i_;
  return true;
}

bool Cursor::onOff(bool& out) {
  if (keyword("ON")) return out = true, true;
  if (keyword("OFF")) return out = false, true;
  return failOneOf("ON or OFF");
}

bool Cursor::color(Color& out) {
  if (!atEnd()) {
    if (auto c = colorByName(peek().text)) {
      out = *c;
      ++i_;
      return true;
    }
  }
  std::string hint;
  if (!atEnd() && peek().type == MP::NAME)
    if (const std::string_view near = base::nearestName(peek().text, kColorNames, base::typoDistance(peek().text));
        !near.empty())
      hint = fmt::format("did you mean '{}'?", near);
  return fail("a colour: one of the 16 EGA colour names (BLACK .. WHITE) or a number 0..15", std::move(hint));
}

bool Cursor::axis(int& out) {
  for (int k = 0; k < 3; ++k)
    if (keyword(std::string_view("XYZ").substr(static_cast<std::size_t>(k), 1))) return out = k, true;
  return fail("an axis X, Y or Z");
}

}  // namespace rs::compiler::description_detail
