#include "compiler/description.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "RobotModelLexer.h"
#include "RobotModelParser.h"
#include "base/ascii.h"
#include "base/near_names.h"
#include "compiler/compiler.h"

namespace rs::compiler {

namespace {

using MP = rs_grammar::RobotModelParser;
using workcell::Color;

constexpr std::array<std::string_view, 16> kColorNames{
    "BLACK",    "BLUE",      "GREEN",      "CYAN",      "RED",      "MAGENTA",      "BROWN",  "LIGHTGRAY",
    "DARKGRAY", "LIGHTBLUE", "LIGHTGREEN", "LIGHTCYAN", "LIGHTRED", "LIGHTMAGENTA", "YELLOW", "WHITE"};

constexpr double kMaxCoordinate = 1e9;

struct Word {
  size_t type;
  std::string text;
  diag::Pos pos;
};

// "did you mean 'LINE'?" when `word` is a near miss of one of the
// keywords named in `list` ("LINE, BOX, ROTATE, MOVE, COLOR or END"): the
// suggestion is always a keyword the message itself offers.
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

// Reads one line's words left to right. Each reader reports what it
// expected at the word it stopped on (or at the end of the line) and
// returns false; the caller then drops the rest of the line, so one slip
// gives one message.
class Cursor {
 public:
  Cursor(const std::vector<Word>& words, diag::Pos lineEnd, diag::Diagnostics& d) : w_(words), end_(lineEnd), diag_(d) {}

  bool atEnd() const { return i_ >= w_.size(); }
  const Word& peek() const { return w_[i_]; }
  diag::Pos pos() const { return atEnd() ? end_ : w_[i_].pos; }

  bool keyword(std::string_view kw) {
    if (atEnd() || peek().type != MP::NAME || !base::sameName(peek().text, kw)) return false;
    ++i_;
    return true;
  }

  bool fail(std::string_view what, std::string hint = {}) {
    diag_.error(pos(),
                atEnd() ? fmt::format("expected {} before the end of the line", what)
                        : fmt::format("expected {}, found '{}'", what, peek().text),
                diag::Hint{std::move(hint)});
    return false;
  }

  /// "expected LINE, BOX, ... or END, found 'LIEN'" with the hint "did you
  /// mean 'LINE'?" when the word found is a near miss of one in the list.
  bool failOneOf(std::string_view keywords) {
    return fail(keywords, atEnd() || peek().type != MP::NAME ? std::string() : didYouMean(peek().text, keywords));
  }

  bool number(double& out, std::string_view what) {
    if (atEnd() || peek().type != MP::NUMBER) return fail(what);
    if (std::string written, plain; exponent(written, plain)) {
      diag_.error(pos(), fmt::format("'{}': exponents are not supported in descriptions", written),
                  diag::Hint{plain.empty() ? std::string("write the number in full, with its decimals")
                                           : fmt::format("write {}", plain)});
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
  bool exponent(std::string& written, std::string& plain) const {
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
  static std::string withoutExponent(std::string_view mantissa, int k) {
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

  bool integer(std::int32_t& out, std::string_view what) {
    double v = 0;
    const diag::Pos at = pos();
    if (!number(v, what)) return false;
    if (v != std::floor(v) || v < -2147483648.0 || v > 2147483647.0) {
      diag_.error(at, fmt::format("expected {} (a whole number), found '{}'", what, w_[i_ - 1].text));
      return false;
    }
    out = static_cast<std::int32_t>(v);
    return true;
  }

  bool point(Point3& out, std::string_view what) {
    out.pos = pos();
    for (int k = 0; k < 3; ++k)
      if (!number(out.v[k], fmt::format("{} ({} coordinate)", what, "xyz"[k]))) return false;
    return true;
  }

  bool name(NameRef& out, std::string_view what) {
    if (atEnd() || peek().type != MP::NAME) return fail(what);
    out = {peek().text, peek().pos};
    ++i_;
    return true;
  }

  bool letter(char& out, diag::Pos& at) {
    at = pos();
    if (atEnd() || peek().type != MP::NAME || peek().text.size() != 1 || !std::isalpha(static_cast<unsigned char>(peek().text[0])))
      return fail("a motor letter A..Z");
    out = base::asciiUpper(peek().text[0]);
    ++i_;
    return true;
  }

  bool onOff(bool& out) {
    if (keyword("ON")) return out = true, true;
    if (keyword("OFF")) return out = false, true;
    return failOneOf("ON or OFF");
  }

  bool color(Color& out) {
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

  bool axis(int& out) {
    for (int k = 0; k < 3; ++k)
      if (keyword(std::string_view("XYZ").substr(static_cast<std::size_t>(k), 1))) return out = k, true;
    return fail("an axis X, Y or Z");
  }

 private:
  const std::vector<Word>& w_;
  std::size_t i_ = 0;
  diag::Pos end_;
  diag::Diagnostics& diag_;
};

enum class Block { None, Link, Object, Gripper, Robot, Workcell };

std::string_view blockName(Block b) {
  switch (b) {
    case Block::Link: return "LINK";
    case Block::Object: return "OBJECT";
    case Block::Gripper: return "GRIPPER";
    case Block::Robot: return "ROBOT";
    case Block::Workcell: return "WORKCELL";
    case Block::None: break;
  }
  return "";
}

constexpr std::array<std::string_view, 6> kBoxEdges{"left", "right", "top", "bottom", "front", "back"};

// A BOX's 8 corners as a collision piece: x left..right, y bottom..top,
// z back..front, as its lines; corner 4i + 2j + k takes the i-th x, the
// j-th y and the k-th z.
workcell::ConvexPiece boxPiece(const double (&e)[6]) {
  workcell::ConvexPiece piece;
  piece.box = true;
  const double xs[2] = {e[0], e[1]}, ys[2] = {e[3], e[2]}, zs[2] = {e[5], e[4]};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) piece.points.emplace_back(xs[i], ys[j], zs[k]);
  return piece;
}

// ROTATE and MOVE turn every collision point drawn so far with the lines.
template <typename F>
void forEachPoint(ShapeDef& shape, F&& f) {
  for (workcell::ConvexPiece& piece : shape.boxes)
    for (Eigen::Vector3d& p : piece.points) f(p);
  for (workcell::ConvexPiece& piece : shape.given)
    for (Eigen::Vector3d& p : piece.points) f(p);
  for (Eigen::Vector3d& p : shape.linePoints) f(p);
}

Eigen::Matrix3d axisRotation(int axis, double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

class Parser {
 public:
  Parser(DescriptionFile& file, diag::Diagnostics& d) : f_(file), diag_(d) {}
  void line(const std::vector<Word>& words, diag::Pos lineEnd);
  void finish();

 private:
  void readLine(const std::vector<Word>& words, diag::Pos lineEnd);
  void markDamaged(Block b);
  void open(Cursor& c, const Word& head);
  bool shapeClause(Cursor& c, ShapeDef& shape);
  bool gripperClause(Cursor& c, GripperDef& g);
  bool robotClause(Cursor& c, RobotDef& r);
  bool workcellClause(Cursor& c, WorkcellDef& w);
  bool motorClause(Cursor& c, char& letter, diag::Pos& letterPos, double& precision, std::int32_t& min, std::int32_t& max,
                   diag::Pos& rangePos, std::int32_t& speed, std::int32_t& acceleration, diag::Pos& accelerationPos,
                   bool* hasLetter, bool* hasPrecision, bool* hasRange);

  DescriptionFile& f_;
  diag::Diagnostics& diag_;
  Block block_ = Block::None;
  diag::Pos blockPos_;
  Color color_ = Color::White;
  enum class Item { None, Link, Joint };
  Item robotItem_ = Item::None;  // in a ROBOT: what the last LINK or JOINT line added
};

// A line with an error damages the definition it belongs to (and, in a
// robot, the link or joint it was about): see ShapeDef.
void Parser::line(const std::vector<Word>& words, diag::Pos lineEnd) {
  const Block before = block_;
  const std::size_t errors = diag_.errorCount();
  readLine(words, lineEnd);
  if (diag_.errorCount() > errors) markDamaged(before == Block::None ? block_ : before);
}

void Parser::markDamaged(Block b) {
  switch (b) {
    case Block::Link: if (!f_.links.empty()) f_.links.back().damaged = true; break;
    case Block::Object: if (!f_.objects.empty()) f_.objects.back().damaged = true; break;
    case Block::Gripper: if (!f_.grippers.empty()) f_.grippers.back().damaged = true; break;
    case Block::Workcell: if (!f_.workcells.empty()) f_.workcells.back().damaged = true; break;
    case Block::Robot:
      if (f_.robots.empty()) break;
      f_.robots.back().damaged = true;
      if (robotItem_ == Item::Joint) f_.robots.back().joints.back().damaged = true;
      if (robotItem_ == Item::Link) f_.robots.back().links.back().damaged = true;
      break;
    case Block::None: break;
  }
}

void Parser::readLine(const std::vector<Word>& words, diag::Pos lineEnd) {
  if (words.empty()) return;
  for (const Word& w : words)
    if (w.type == MP::OTHER) return diag_.error(w.pos, fmt::format("unexpected character '{}'", w.text));
  Cursor c(words, lineEnd, diag_);
  if (block_ == Block::None) return open(c, words[0]);
  if (c.keyword("END")) {
    if (!c.atEnd()) diag_.error(c.pos(), fmt::format("END takes nothing after it, found '{}'", c.peek().text));
    block_ = Block::None;
    return;
  }
  while (!c.atEnd()) {
    bool ok = false;
    switch (block_) {
      case Block::Link: ok = shapeClause(c, f_.links.back()); break;
      case Block::Object: ok = shapeClause(c, f_.objects.back()); break;
      case Block::Gripper: ok = gripperClause(c, f_.grippers.back()); break;
      case Block::Robot: ok = robotClause(c, f_.robots.back()); break;
      case Block::Workcell: ok = workcellClause(c, f_.workcells.back()); break;
      case Block::None: break;
    }
    if (!ok) return;
  }
}

void Parser::open(Cursor& c, const Word& head) {
  static constexpr std::array<Block, 5> kinds{Block::Link, Block::Object, Block::Gripper, Block::Robot, Block::Workcell};
  Block kind = Block::None;
  for (Block k : kinds)
    if (c.keyword(blockName(k))) kind = k;
  if (kind == Block::None) {
    constexpr std::string_view kBlockKinds = "LINK, OBJECT, GRIPPER, ROBOT or WORKCELL";
    diag_.error(head.pos, fmt::format("expected {}, found '{}'", kBlockKinds, head.text),
                diag::Hint{head.type == MP::NAME ? didYouMean(head.text, kBlockKinds) : std::string()});
    return;
  }
  // Without a name the block still opens (the error is reported), so the
  // lines inside it are read as what they are, not as stray text.
  NameRef name;
  if (!c.name(name, fmt::format("a name for the {}", blockName(kind)))) {
  } else if (!c.atEnd()) {
    diag_.error(c.pos(), fmt::format("unexpected '{}' after the {} name (statements go on the next lines)",
                                     c.peek().text, blockName(kind)));
  }
  block_ = kind;
  blockPos_ = head.pos;
  robotItem_ = Item::None;
  color_ = Color::White;
  switch (kind) {
    case Block::Link: f_.links.emplace_back(), f_.links.back().name = name.name, f_.links.back().pos = head.pos; break;
    case Block::Object: f_.objects.emplace_back(), f_.objects.back().name = name.name, f_.objects.back().pos = head.pos; break;
    case Block::Gripper: f_.grippers.push_back({}), f_.grippers.back().name = name.name, f_.grippers.back().pos = head.pos; break;
    case Block::Robot: f_.robots.push_back({}), f_.robots.back().name = name.name, f_.robots.back().pos = head.pos; break;
    case Block::Workcell: f_.workcells.push_back({name.name, head.pos, {}}); break;
    case Block::None: break;
  }
}

void Parser::finish() {
  if (block_ != Block::None)
    diag_.error(blockPos_, fmt::format("{} has no END", blockName(block_)));
}

// LINE, BOX, ROTATE, MOVE, COLOR: the DESIGN LINK / DESIGN OBJECT commands.
bool Parser::shapeClause(Cursor& c, ShapeDef& shape) {
  if (c.keyword("LINE")) {
    Point3 a, b;
    if (!c.point(a, "the LINE's first endpoint") || !c.point(b, "the LINE's second endpoint")) return false;
    Color color = color_;
    if (c.keyword("COLOR") && !c.color(color)) return false;
    shape.segments.push_back({a.v, b.v, color});
    shape.linePoints.push_back(a.v), shape.linePoints.push_back(b.v);
    return true;
  }
  if (c.keyword("BOX")) {
    double e[6];
    for (int k = 0; k < 6; ++k)
      if (!c.number(e[k], fmt::format("the BOX's {} edge", kBoxEdges[static_cast<std::size_t>(k)]))) return false;
    Color color = color_;
    if (c.keyword("COLOR") && !c.color(color)) return false;
    // x from left to right, y from bottom to top, z from back to front.
    const double xs[2] = {e[0], e[1]}, ys[2] = {e[3], e[2]}, zs[2] = {e[5], e[4]};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        shape.segments.push_back({{xs[0], ys[i], zs[j]}, {xs[1], ys[i], zs[j]}, color});
        shape.segments.push_back({{xs[i], ys[0], zs[j]}, {xs[i], ys[1], zs[j]}, color});
        shape.segments.push_back({{xs[i], ys[j], zs[0]}, {xs[i], ys[j], zs[1]}, color});
      }
    shape.boxes.push_back(boxPiece(e));
    return true;
  }
  if (c.keyword("COLLIDE")) {
    shape.collideGiven = true;
    if (c.keyword("NONE")) return true;
    if (!c.keyword("BOX")) return c.failOneOf("BOX or NONE");
    double e[6];
    for (int k = 0; k < 6; ++k)
      if (!c.number(e[k], fmt::format("the COLLIDE BOX's {} edge", kBoxEdges[static_cast<std::size_t>(k)]))) return false;
    shape.given.push_back(boxPiece(e));
    return true;
  }
  if (c.keyword("ROTATE")) {
    int axis = 0;
    double degrees = 0;
    if (!c.axis(axis) || !c.number(degrees, "an angle in degrees")) return false;
    const Eigen::Matrix3d r = axisRotation(axis, degrees);
    for (workcell::Segment& s : shape.segments) s.a = r * s.a, s.b = r * s.b;
    forEachPoint(shape, [&](Eigen::Vector3d& p) { p = r * p; });
    return true;
  }
  if (c.keyword("MOVE")) {
    Point3 d;
    if (!c.point(d, "a displacement")) return false;
    for (workcell::Segment& s : shape.segments) s.a += d.v, s.b += d.v;
    forEachPoint(shape, [&](Eigen::Vector3d& p) { p += d.v; });
    return true;
  }
  if (c.keyword("COLOR")) return c.color(color_);
  return c.failOneOf("LINE, BOX, ROTATE, MOVE, COLOR, COLLIDE or END");
}

// LETTER, PRECISION, RANGE, SPEED, ACCELERATION: shared by GRIPPER and JOINT.
bool Parser::motorClause(Cursor& c, char& letter, diag::Pos& letterPos, double& precision, std::int32_t& min,
                         std::int32_t& max, diag::Pos& rangePos, std::int32_t& speed, std::int32_t& acceleration,
                         diag::Pos& accelerationPos, bool* hasLetter, bool* hasPrecision, bool* hasRange) {
  // has* is set as soon as the keyword is seen: a bad value is reported
  // once, not again as "missing".
  if (c.keyword("LETTER")) return *hasLetter = true, c.letter(letter, letterPos);
  if (c.keyword("PRECISION")) {
    *hasPrecision = true;
    const diag::Pos at = c.pos();
    if (!c.number(precision, "a precision (degrees or length units per encoder unit)")) return false;
    if (precision <= 0) {
      diag_.error(at, "a precision must be greater than 0");
      return false;
    }
    return true;
  }
  if (c.keyword("RANGE")) {
    *hasRange = true;
    rangePos = c.pos();
    if (!c.integer(min, "the minimum encoder value") || !c.integer(max, "the maximum encoder value")) return false;
    if (min > max) {
      diag_.error(rangePos, fmt::format("range {}..{} is empty: the minimum is greater than the maximum", min, max));
      return false;
    }
    if (min > 0 || max < 0) {
      diag_.error(rangePos, fmt::format("range {}..{} must include 0: every motor starts at encoder 0 (home)", min, max));
      return false;
    }
    return true;
  }
  if (c.keyword("SPEED")) {
    const diag::Pos at = c.pos();
    if (!c.integer(speed, "a speed in encoder units per second")) return false;
    if (speed <= 0) {
      diag_.error(at, "a speed must be greater than 0");
      return false;
    }
    return true;
  }
  if (c.keyword("ACCELERATION")) {
    accelerationPos = c.pos();
    if (!c.integer(acceleration, "an acceleration in encoder units per second squared")) return false;
    if (acceleration <= 0 || acceleration > vm::kMaxAcceleration) {
      diag_.error(accelerationPos, fmt::format("an acceleration must be 1..{} encoder units per second squared "
                                               "(leave it out for a motor that starts and stops at full speed)",
                                               vm::kMaxAcceleration));
      acceleration = 0;
      return false;
    }
    return true;
  }
  return false;
}

bool Parser::gripperClause(Cursor& c, GripperDef& g) {
  if (c.keyword("BASE")) return c.name(g.base, "the gripper's base link");
  if (c.keyword("FINGERS")) return c.name(g.finger2, "the first finger link") && c.name(g.finger3, "the second finger link");
  const auto twoPoints = [&](Point3 (&p)[2], bool& has, std::string_view what) {
    has = true;
    return c.point(p[0], fmt::format("the {}'s start point", what)) && c.point(p[1], fmt::format("the {}'s end point", what));
  };
  if (c.keyword("AXIS2")) return twoPoints(g.axis2, g.hasAxis2, "axis r2");
  if (c.keyword("AXIS3")) return twoPoints(g.axis3, g.hasAxis3, "axis r3");
  if (c.keyword("NORMAL")) return twoPoints(g.normal, g.hasNormal, "normal vector");
  if (c.keyword("APPROACH")) return twoPoints(g.approach, g.hasApproach, "approach vector");
  if (c.keyword("ACTUATION")) {
    const diag::Pos at = c.pos();
    double seconds = 0;
    if (!c.number(seconds, "an actuation time in seconds")) return false;
    const double limit = vm::kMaxActuation / 1e6;
    if (!(seconds > 0 && seconds <= limit)) {
      diag_.error(at, fmt::format("an actuation time must be more than 0 and at most {} s", limit));
      return false;
    }
    g.actuation = static_cast<std::int32_t>(std::llround(seconds * 1e6));  // whole microseconds
    if (g.actuation == 0) g.actuation = 1;
    return true;
  }
  const std::size_t before = diag_.errorCount();
  if (motorClause(c, g.letter, g.letterPos, g.precision, g.min, g.max, g.rangePos, g.speed, g.acceleration,
                  g.accelerationPos, &g.hasLetter, &g.hasPrecision, &g.hasRange))
    return true;
  if (diag_.errorCount() > before) return false;
  return c.failOneOf(
      "BASE, FINGERS, LETTER, PRECISION, RANGE, SPEED, ACCELERATION, ACTUATION, AXIS2, AXIS3, NORMAL, APPROACH or END");
}

bool Parser::robotClause(Cursor& c, RobotDef& r) {
  if (c.keyword("LINK")) {
    robotItem_ = Item::Link;
    r.links.push_back({});
    return c.name(r.links.back().link, "a link name");
  }
  if (c.keyword("FRAME")) return true;  // introduces ORIGIN, XAXIS, ZAXIS
  for (auto [kw, member, has] : {std::tuple{"ORIGIN", &RobotLinkDef::origin, &RobotLinkDef::hasOrigin},
                                 std::tuple{"XAXIS", &RobotLinkDef::xPoint, &RobotLinkDef::hasX},
                                 std::tuple{"ZAXIS", &RobotLinkDef::zPoint, &RobotLinkDef::hasZ}}) {
    const diag::Pos at = c.pos();
    if (!c.keyword(kw)) continue;
    if (r.links.empty()) {
      diag_.error(at, fmt::format("{} before any LINK: a frame belongs to the LINK before it", kw));
      return false;
    }
    r.links.back().*has = true;
    return c.point(r.links.back().*member, fmt::format("the frame's {} point", kw));
  }
  if (c.keyword("JOINT")) {
    robotItem_ = Item::None;  // until the joint is added
    JointDef j;
    j.pos = c.pos();
    std::int32_t n = 0;
    if (!c.integer(n, "a joint number")) return false;
    j.number = n;
    if (c.keyword("REVOLUTE")) j.spec.type = kinematics::JointType::Revolute;
    else if (c.keyword("PRISMATIC")) j.spec.type = kinematics::JointType::Prismatic;
    else return c.failOneOf("REVOLUTE or PRISMATIC");
    r.joints.push_back(j);
    robotItem_ = Item::Joint;
    return true;
  }
  if (c.keyword("COUPLING")) {
    if (r.joints.empty()) return c.fail("a JOINT before COUPLING");
    return c.onOff(r.joints.back().spec.coupling);
  }
  if (c.keyword("GRIPPER")) return c.name(r.gripper, "a gripper name");
  if (r.joints.empty()) {
    for (std::string_view kw : {"LETTER", "PRECISION", "RANGE", "SPEED", "ACCELERATION"})
      if (!c.atEnd() && base::sameName(c.peek().text, kw)) {
        diag_.error(c.pos(), fmt::format("{} before any JOINT: motor settings belong to the JOINT before them", kw));
        return false;
      }
  } else {
    JointDef& j = r.joints.back();
    diag::Pos letterPos;
    const std::size_t before = diag_.errorCount();
    if (motorClause(c, j.spec.letter, letterPos, j.spec.precision, j.spec.min, j.spec.max, j.rangePos, j.spec.speed,
                    j.spec.acceleration, j.accelerationPos, &j.hasLetter, &j.hasPrecision, &j.hasRange))
      return true;
    if (diag_.errorCount() > before) return false;
  }
  return c.failOneOf(
      "LINK, FRAME, ORIGIN, XAXIS, ZAXIS, JOINT, LETTER, PRECISION, RANGE, COUPLING, SPEED, ACCELERATION, GRIPPER or END");
}

bool Parser::workcellClause(Cursor& c, WorkcellDef& w) {
  if (c.keyword("FLOOR")) {
    if (c.keyword("NONE")) return w.floor.reset(), true;
    double y = 0;
    if (!c.number(y, "the floor's height (y), or NONE")) return false;
    w.floor = y;
    return true;
  }
  const bool robot = c.keyword("ROBOT");
  if (robot || c.keyword("OBJECT")) {
    PlacementDef p;
    p.isRobot = robot;
    if (!c.name(p.what, robot ? "a robot name" : "an object name")) return false;
    w.placements.push_back(p);
    return true;
  }
  if (w.placements.empty()) return c.failOneOf("ROBOT, OBJECT, FLOOR or END");
  PlacementDef& p = w.placements.back();
  if (c.keyword("AT")) {
    Point3 at;
    if (!c.point(at, "a position")) return false;
    p.at = at.v;
    return true;
  }
  if (c.keyword("ROTATE")) {
    int axis = 0;
    double degrees = 0;
    if (!c.axis(axis) || !c.number(degrees, "an angle in degrees")) return false;
    p.rotation = axisRotation(axis, degrees) * p.rotation;
    return true;
  }
  return c.failOneOf("ROBOT, OBJECT, AT, ROTATE, FLOOR or END");
}

}  // namespace

std::vector<workcell::ConvexPiece> ShapeDef::collision() const {
  if (collideGiven) return given;
  std::vector<workcell::ConvexPiece> pieces = boxes;
  if (!linePoints.empty()) pieces.push_back({linePoints, false});
  return pieces;
}

std::optional<workcell::Color> colorByName(std::string_view word) {
  for (std::size_t i = 0; i < kColorNames.size(); ++i)
    if (base::sameName(word, kColorNames[i]) || word == std::to_string(i)) return static_cast<Color>(i);
  return std::nullopt;
}

std::string_view colorName(workcell::Color color) { return kColorNames[static_cast<std::size_t>(color)]; }

DescriptionFile parseDescription(std::unique_ptr<diag::SourceFile> source, diag::Diagnostics& diagnostics) {
  DescriptionFile file;
  file.source = std::move(source);
  if (auto bad = checkEncoding(*file.source, "descriptions")) {
    diagnostics.add(bad->pos, bad->severity, bad->message);
    return file;
  }
  antlr4::ANTLRInputStream input(file.source->text());
  rs_grammar::RobotModelLexer lexer(&input);
  lexer.removeErrorListeners();  // OTHER matches any character: no lexer errors
  antlr4::CommonTokenStream tokens(&lexer);
  MP parser(&tokens);
  parser.removeErrorListeners();  // the grammar accepts any words on a line
  MP::DescriptionContext* root = parser.description();
  Parser p(file, diagnostics);
  for (MP::LineContext* l : root->line()) {
    std::vector<Word> words;
    for (antlr4::tree::ParseTree* child : l->children) {
      const antlr4::Token* t = static_cast<antlr4::tree::TerminalNode*>(child)->getSymbol();
      words.push_back({t->getType(), t->getText(),
                       {static_cast<std::uint32_t>(t->getLine()), static_cast<std::uint32_t>(t->getCharPositionInLine() + 1)}});
    }
    const diag::Pos end = words.empty() ? diag::Pos{} : diag::Pos{words.back().pos.line,
                                              words.back().pos.col + static_cast<std::uint32_t>(words.back().text.size())};
    p.line(words, end);
  }
  p.finish();
  return file;
}

}  // namespace rs::compiler
