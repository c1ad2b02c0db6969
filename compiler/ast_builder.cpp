#include "compiler/ast_builder.h"

#include "base/near_names.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <fmt/format.h>

#include "RobotProgramParser.h"
#include "base/ascii.h"

namespace rs::compiler {

namespace {

// Every operand is checked, even after one fails, so a line reports all its
// mistakes at once (a braced list evaluates its elements in order).
bool all(std::initializer_list<bool> checks) {
  for (bool ok : checks)
    if (!ok) return false;
  return true;
}

using P = rs_grammar::RobotProgramParser;

using base::asciiUpper;
using base::sameName;

diag::Pos posOf(const antlr4::Token* t) {
  return {static_cast<std::uint32_t>(t->getLine()), static_cast<std::uint32_t>(t->getCharPositionInLine() + 1)};
}

// The written text of a token: a view into the source, not a copy.
std::string_view textOf(const diag::SourceFile& src, const antlr4::Token* t) {
  return std::string_view(src.text()).substr(t->getStartIndex(), t->getStopIndex() + 1 - t->getStartIndex());
}

struct Word {  // one operand as written
  size_t type;
  std::string_view text;
  diag::Pos pos;
};

using vm::isReservedWord;
using vm::kMaxNameLength;  // as the image format allows

class Builder {
 public:
  Builder(const diag::SourceFile& src, std::span<const vm::MotorSpec> motors, diag::Diagnostics& d, AstSink& sink)
      : src_(src), motors_(motors), diag_(d), sink_(sink) {}

  /// `recovered`: the parser met syntax errors on this line (already reported).
  void line(P::LineContext* line, bool recovered);
  void finish();

 private:
  void instruction(const antlr4::Token* head, const std::vector<Word>& words);
  void point(const antlr4::Token* head, const std::vector<Word>& words);
  bool operands(Instruction& in, std::string_view mnemonic, const std::vector<Word>& w);
  bool looksLikePoint(std::string_view head, const std::vector<Word>& words) const;
  bool pose(PointDef& p, const std::vector<Word>& words);
  bool poseVector(const std::vector<Word>& w, std::size_t& i, std::string_view what, PoseVector& out);
  bool coordinate(const Word& w, std::string_view what, double& out);
  bool delayWithUnit(const std::vector<Word>& w);
  bool twoWordComparison(const std::vector<Word>& w);
  bool checkName(std::string_view what, std::string_view name, diag::Pos pos);

  // Operand readers: each reports what it expected and returns false.
  bool integer(const Word& w, std::string_view what, Value& out);
  /// Every word as an integer (each bad one reported); on any error `out`
  /// is left empty, so later checks skip the operand list.
  bool integers(const std::vector<Word>& words, std::string_view what, std::vector<Value>& out);
  bool seconds(const Word& w, Value& out);
  bool name(const Word& w, std::string_view what, std::string_view& out, diag::Pos& pos);
  bool onOff(const Word& w, bool& out);
  bool compare(const Word& w, vm::Compare& out);
  bool jump(const Word& w, JumpRef& out);
  std::string motorLetters() const;

  const diag::SourceFile& src_;
  std::span<const vm::MotorSpec> motors_;
  diag::Diagnostics& diag_;
  AstSink& sink_;
  Instruction in_;  // the one being built (kept for its vector's capacity)
  PointDef point_;  // the same
  std::uint32_t instructions_ = 0;
  diag::Pos pointsHeader_;
  std::vector<const antlr4::Token*> tokens_;  // of the current line (kept for its capacity)
  std::vector<Word> words_;
  bool inPoints_ = false;
  std::uint32_t endLine_ = 0;  // the last END instruction's line, 0 before any
  std::string_view pendingLabel_;
  diag::Pos pendingLabelPos_;
};

void Builder::finish() {
  if (!pendingLabel_.empty())
    diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_),
                "label-without-instruction");
}

// Splits a line's tokens into label, head word and operands. Every child of
// a LineContext is a token node; after error recovery some are error nodes
// for tokens the parser skipped (already reported), which are left out.
void Builder::line(P::LineContext* l, bool recovered) {
  std::vector<const antlr4::Token*>& tokens = tokens_;
  tokens.clear();
  for (antlr4::tree::ParseTree* child : l->children) {
    if (recovered && dynamic_cast<antlr4::tree::ErrorNode*>(child)) continue;
    tokens.push_back(static_cast<antlr4::tree::TerminalNode*>(child)->getSymbol());
  }
  if (tokens.empty()) return;  // blank line
  if (tokens[0]->getType() != P::IDENT)
    return diag_.error(posOf(tokens[0]), fmt::format("unexpected '{}': a line starts with an instruction, a label "
                                                     "or a point name",
                                                     diag::excerpt(textOf(src_, tokens[0]))),
                       "syntax");
  const bool labelled = tokens.size() >= 2 && tokens[1]->getType() == P::COLON;
  std::size_t next = labelled ? 2 : 0;
  const antlr4::Token* headToken = nullptr;
  if (next < tokens.size() && tokens[next]->getType() == P::IDENT) headToken = tokens[next++];
  std::vector<Word>& words = words_;
  words.clear();
  for (; next < tokens.size(); ++next) {
    if (tokens[next]->getType() == P::COLON)
      return diag_.error(posOf(tokens[next]),
                         "unexpected ':': a label is a name followed by ':' at the start of a line", "syntax");
    words.push_back({tokens[next]->getType(), textOf(src_, tokens[next]), posOf(tokens[next])});
  }
  if (labelled) {
    const std::string_view label = textOf(src_, tokens[0]);
    const diag::Pos pos = posOf(tokens[0]);
    if (inPoints_) {
      diag_.error(pos, "points cannot have labels: labels name instructions", "label-on-point");
    } else if (!pendingLabel_.empty()) {
      diag_.error(pos, fmt::format("label '{}' follows label '{}': an instruction can have only one label",
                                   diag::excerpt(label), pendingLabel_),
                  "two-labels", {diag_.relatedAt(pendingLabelPos_, fmt::format("label '{}' is here", pendingLabel_))});
    } else if (checkName("a label", label, pos)) {
      pendingLabel_ = label;
      pendingLabelPos_ = pos;
    }
  }
  if (!headToken) {
    if (labelled && !words.empty()) {
      diag_.error(words[0].pos,
                  fmt::format("expected an instruction after the label, found '{}'", diag::excerpt(words[0].text)),
                  "syntax");
      pendingLabel_ = {};
    }
    return;
  }
  const std::string_view head = textOf(src_, headToken);
  if (sameName(head, "POINTS") && words.empty()) {
    if (inPoints_)
      return diag_.error(posOf(headToken),
                         fmt::format("POINTS appears twice (the section began on line {})", pointsHeader_.line),
                         "duplicate-points-section", {diag_.relatedAt(pointsHeader_, "the POINTS section begins here")});
    if (!pendingLabel_.empty()) {
      diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_),
                  "label-without-instruction");
      pendingLabel_ = {};
    }
    inPoints_ = true;
    pointsHeader_ = posOf(headToken);
    sink_.pointsHeader(pointsHeader_);
    return;
  }
  if (inPoints_) return point(headToken, words);
  if (looksLikePoint(head, words)) {
    // A point row after the program's END without a POINTS line: say so
    // once, then read this row and the rest as the points they are.
    const diag::Pos pos = posOf(headToken);
    diag_.error(pos,
                fmt::format("'{}' is not an instruction: it looks like a taught point, but no POINTS line comes "
                            "before it",
                            diag::excerpt(head)),
                diag::Hint{fmt::format("points follow a line POINTS after the instructions: add POINTS on a line "
                                       "of its own after the END on line {}, before line {}",
                                       endLine_, pos.line)},
                "missing-points-line");
    if (!pendingLabel_.empty()) {
      diag_.error(pendingLabelPos_, fmt::format("label '{}' is not followed by an instruction", pendingLabel_));
      pendingLabel_ = {};
    }
    inPoints_ = true;
    pointsHeader_ = pos;
    sink_.pointsHeader(pointsHeader_);
    return point(headToken, words);
  }
  instruction(headToken, words);
}

// After an END, a word that is no instruction (nor one letter away from
// one: "MOVX 1 2 3 4 5" is a slip of MOVE) followed only by numbers: a
// point row whose POINTS line is missing ("HOME 0 0 0 0 0").
bool Builder::looksLikePoint(std::string_view head, const std::vector<Word>& words) const {
  if (endLine_ == 0 || words.empty() || vm::opByName(head)) return false;
  for (const vm::OpInfo& op : vm::kOps)
    if (base::nameDistance(head, op.name) <= 1) return false;
  return std::all_of(words.begin(), words.end(), [](const Word& w) { return w.type == P::NUMBER; });
}

void Builder::instruction(const antlr4::Token* head, const std::vector<Word>& words) {
  Instruction& in = in_;
  std::vector<Value> values = std::move(in.values);
  values.clear();
  in = Instruction{};
  in.values = std::move(values);
  in.pos = posOf(head);
  in.number = ++instructions_;
  in.label = pendingLabel_;
  in.labelPos = pendingLabelPos_;
  pendingLabel_ = {};
  const std::string_view mnemonic = textOf(src_, head);
  if (const auto op = vm::opByName(mnemonic)) {
    in.op = *op;
    if (*op == vm::Op::End) endLine_ = in.pos.line;
    operands(in, vm::info(*op).name, words);
  } else {
    in.known = false;
    const std::string_view near = closestMnemonic(mnemonic);
    diag_.error(in.pos,
                near.empty() ? fmt::format("unknown instruction '{}'", diag::excerpt(mnemonic))
                             : fmt::format("unknown instruction '{}' (did you mean {}?)", diag::excerpt(mnemonic), near),
                "unknown-instruction");
  }
  sink_.instruction(in);
}

void Builder::point(const antlr4::Token* head, const std::vector<Word>& words) {
  PointDef& p = point_;
  std::vector<Value> values = std::move(p.values);
  values.clear();
  p = PointDef{};
  p.values = std::move(values);
  p.name = textOf(src_, head);
  p.pos = posOf(head);
  if (vm::opByName(p.name)) {
    diag_.error(p.pos, fmt::format("instruction {} after POINTS: instructions come before the POINTS line (line {})",
                                   p.name, pointsHeader_.line),
                "instruction-after-points");
    return;
  }
  if (!checkName("a point", p.name, p.pos)) return;
  if (!words.empty() && words[0].type == P::IDENT && sameName(words[0].text, "AT")) {
    p.isPose = true;
    if (pose(p, words)) sink_.point(p);
    return;
  }
  const bool ok = integers(words, "an encoder value", p.values);
  if (ok && p.values.size() != motors_.size())
    diag_.error(p.pos, fmt::format("point {} has {} values, expected {} (one per motor: {})", p.name, p.values.size(),
                                   motors_.size(), motorLetters()),
                "operand-count");
  sink_.point(p);
}

// "AT [WORLD|ROBOT] x y z [APPROACH ax ay az] [NORMAL nx ny nz] [GRIP g]":
// the clauses after the position in any order, each at most once.
bool Builder::pose(PointDef& p, const std::vector<Word>& w) {
  PointPose& pose = p.pose;
  const char* end = w.back().text.data() + w.back().text.size();
  pose.text = std::string_view(w[0].text.data(), static_cast<std::size_t>(end - w[0].text.data()));
  std::size_t i = 1;
  if (i < w.size() && w[i].type == P::IDENT && (sameName(w[i].text, "WORLD") || sameName(w[i].text, "ROBOT")))
    pose.robotFrame = sameName(w[i++].text, "ROBOT");
  bool ok = poseVector(w, i, "AT", pose.at);
  pose.at.pos = w[0].pos;
  while (ok && i < w.size()) {
    const Word& key = w[i];
    PoseVector* vector = nullptr;
    if (key.type == P::IDENT && sameName(key.text, "APPROACH")) vector = &pose.approach;
    if (key.type == P::IDENT && sameName(key.text, "NORMAL")) vector = &pose.normal;
    const bool grip = key.type == P::IDENT && sameName(key.text, "GRIP");
    if (!vector && !grip) {
      diag_.error(key.pos,
                  fmt::format("point {}: unexpected '{}' in a tool pose: after AT x y z come APPROACH ax ay az, "
                              "NORMAL nx ny nz and GRIP g",
                              p.name, diag::excerpt(key.text)),
                  "bad-operand");
      return false;
    }
    const std::string_view keyword = vector == &pose.approach ? "APPROACH" : vector ? "NORMAL" : "GRIP";
    if ((vector && vector->given) || (grip && pose.gripGiven)) {
      diag_.error(key.pos, fmt::format("point {}: {} is written twice", p.name, keyword), "bad-operand");
      return false;
    }
    ++i;
    if (vector) {
      ok = poseVector(w, i, keyword, *vector);
      vector->pos = key.pos;
    } else if (i >= w.size()) {
      diag_.error(key.pos, fmt::format("point {}: GRIP needs the gripper's encoder value", p.name), "operand-count");
      return false;
    } else {
      ok = integer(w[i++], "the gripper's encoder value", pose.grip);
      pose.gripGiven = ok;
    }
  }
  return ok;
}

// Three numbers after a keyword, each a decimal coordinate.
bool Builder::poseVector(const std::vector<Word>& w, std::size_t& i, std::string_view what, PoseVector& out) {
  const diag::Pos keyPos = w[i - 1].pos;
  std::size_t have = 0;
  while (have < 3 && i + have < w.size() && w[i + have].type == P::NUMBER) ++have;
  if (have < 3) {
    const diag::Pos at = i + have < w.size() ? w[i + have].pos : keyPos;
    diag_.error(at,
                have < w.size() - i ? fmt::format("{} expects three numbers (x y z), found '{}'", what,
                                                  diag::excerpt(w[i + have].text))
                                    : fmt::format("{} expects three numbers (x y z), found {}", what, have),
                "operand-count");
    return false;
  }
  bool ok = true;
  for (std::size_t k = 0; k < 3; ++k) ok = coordinate(w[i + k], what, out.v[k]) && ok;
  i += 3;
  out.given = ok;
  return ok;
}

bool Builder::coordinate(const Word& w, std::string_view what, double& out) {
  const std::string_view digits = w.text[0] == '+' ? w.text.substr(1) : w.text;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
  if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(out) || std::abs(out) > 1e9) {
    diag_.error(w.pos, fmt::format("{}: '{}' is not a coordinate (a number up to 1e9)", what, diag::excerpt(w.text)),
                "number-out-of-range");
    return false;
  }
  return true;
}

// Reads the operands of one instruction by its opcode's format.
bool Builder::operands(Instruction& in, std::string_view mnemonic, const std::vector<Word>& w) {
  const vm::Format f = vm::info(in.op).format;
  if (f == vm::Format::MotorVector) {
    const bool ok = integers(w, "an encoder value", in.values);
    if (ok && w.size() != motors_.size())
      diag_.error(in.pos, fmt::format("{} expects {} values (one per motor: {}), found {}", mnemonic, motors_.size(),
                                      motorLetters(), w.size()),
                  "operand-count");
    return ok;
  }
  const std::size_t want = vm::info(f).operands;
  if (f == vm::Format::Millis && delayWithUnit(w)) return false;
  if (f == vm::Format::VarCompare && twoWordComparison(w)) return false;
  if (w.size() != want) {
    const diag::Pos at = w.size() > want ? w[want].pos : in.pos;
    diag_.error(at, want == 0 ? fmt::format("{} takes no operands, found {}", mnemonic, w.size())
                              : fmt::format("{} expects {} operand{} ({}{}), found {}", mnemonic, want,
                                            want == 1 ? "" : "s", mnemonic, vm::info(f).usage, w.size()),
                "operand-count");
    return false;
  }
  switch (f) {
    case vm::Format::None: case vm::Format::MotorVector: return true;
    case vm::Format::Point: return name(w[0], "a point name", in.name, in.namePos);
    case vm::Format::Target: return jump(w[0], in.target);
    case vm::Format::InputJump:
      return all({integer(w[0], "an input number", in.io), onOff(w[1], in.on), jump(w[2], in.target)});
    case vm::Format::Output:
      return all({integer(w[0], "an output number", in.io), onOff(w[1], in.on)});
    case vm::Format::Input:
      return all({integer(w[0], "an input number", in.io), onOff(w[1], in.on)});
    case vm::Format::VarCompare:
      return all({name(w[0], "a variable name", in.name, in.namePos), compare(w[1], in.compare),
                  integer(w[2], "a value", in.value), jump(w[3], in.target)});
    case vm::Format::VarValue:
      return all({name(w[0], "a variable name", in.name, in.namePos), integer(w[1], "a value", in.value)});
    case vm::Format::Triple: return integers(w, "a number", in.values);
    case vm::Format::Millis: return seconds(w[0], in.value);
  }
  return false;
}

// "DELAY 1.5s", "DELAY 2 seconds", "DELAY 500ms": a unit after the number.
bool Builder::delayWithUnit(const std::vector<Word>& w) {
  if (w.size() != 2 || w[0].type != P::NUMBER || w[1].type != P::IDENT) return false;
  const std::string_view unit = w[1].text;
  const bool seconds = sameName(unit, "s") || sameName(unit, "sec") || sameName(unit, "secs") ||
                       sameName(unit, "second") || sameName(unit, "seconds");
  const bool millis = sameName(unit, "ms");
  if (!seconds && !millis) return false;
  std::string bare(w[0].text[0] == '+' ? w[0].text.substr(1) : w[0].text);
  if (millis) {
    // Milliseconds to seconds, exactly, by moving the decimal point.
    std::int64_t ms = 0;
    const auto [end, ec] = std::from_chars(bare.data(), bare.data() + bare.size(), ms);
    if (ec != std::errc() || end != bare.data() + bare.size() || ms < 0)
      bare.clear();
    else if (ms % 1000 == 0)
      bare = std::to_string(ms / 1000);
    else
      bare = fmt::format("{}.{:03}", ms / 1000, ms % 1000), bare.erase(bare.find_last_not_of('0') + 1);
  }
  diag_.error(w[1].pos,
              fmt::format("'{}' after DELAY's number: DELAY takes seconds as a bare number, without a unit",
                          diag::excerpt(unit)),
              diag::Hint{bare.empty() ? std::string("write the seconds alone, e.g. DELAY 1.5")
                                      : fmt::format("write DELAY {}{}", bare, millis ? " (seconds)" : "")},
              "delay-unit");
  return true;
}

// "JMPVAR N <= 3 L": two comparison signs together. The grammar's
// comparisons are <, > and = (CMP in grammar/RobotProgram.g4), one sign each.
bool Builder::twoWordComparison(const std::vector<Word>& w) {
  if (w.size() != 5 || w[1].type != P::CMP || w[2].type != P::CMP || w[2].pos.line != w[1].pos.line ||
      w[2].pos.col != w[1].pos.col + 1)
    return false;
  const std::string op = std::string(w[1].text) + std::string(w[2].text);
  const std::string_view var = w[0].text;
  std::string hint;
  std::int64_t v = 0;
  const std::string_view value = w[3].text[0] == '+' ? w[3].text.substr(1) : w[3].text;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  const bool number = w[3].type == P::NUMBER && ec == std::errc() && end == value.data() + value.size();
  if ((op == "<=" || op == "=<") && number)
    hint = fmt::format("values are whole numbers: {} <= {} is JMPVAR {} < {} {}", var, v, var, v + 1, w[4].text);
  else if ((op == ">=" || op == "=>") && number)
    hint = fmt::format("values are whole numbers: {} >= {} is JMPVAR {} > {} {}", var, v, var, v - 1, w[4].text);
  else if (op == "==")
    hint = fmt::format("equality is one '=': JMPVAR {} = {} {}", var, w[3].text, w[4].text);
  else if (op == "<>")
    hint = "there is no not-equal: jump with = past the instructions for the other case";
  diag_.error(w[1].pos,
              fmt::format("'{}' is not a comparison: JMPVAR compares with <, > or = (one sign)", op),
              diag::Hint{std::move(hint)}, "bad-comparison");
  return true;
}

bool Builder::checkName(std::string_view what, std::string_view name, diag::Pos pos) {
  if (name.size() > kMaxNameLength) {
    diag_.error(pos, fmt::format("'{}...' is too long for {}: names have at most {} characters", name.substr(0, 16),
                                 what, kMaxNameLength),
                "name-too-long");
    return false;
  }
  if (!isReservedWord(name)) return true;
  diag_.error(pos, fmt::format("'{}' is a reserved word and cannot name {}", name, what), "reserved-word");
  return false;
}

// Sets out.pos only on success: later checks skip operands without one.
bool Builder::integer(const Word& w, std::string_view what, Value& out) {
  if (w.type != P::NUMBER) {
    diag_.error(w.pos, fmt::format("expected {}, found '{}'", what, diag::excerpt(w.text)), "bad-operand");
    return false;
  }
  if (w.text.find('.') != std::string_view::npos) {
    diag_.error(w.pos, fmt::format("expected {} (a whole number), found '{}'", what, diag::excerpt(w.text)),
                "bad-operand");
    return false;
  }
  const std::string_view digits = w.text[0] == '+' ? w.text.substr(1) : w.text;
  std::int32_t v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    diag_.error(w.pos,
                fmt::format("'{}' does not fit in a 32-bit integer (-2147483648..2147483647)", diag::excerpt(w.text)),
                "number-out-of-range");
    return false;
  }
  out.number = v;
  out.pos = w.pos;
  return true;
}

bool Builder::integers(const std::vector<Word>& words, std::string_view what, std::vector<Value>& out) {
  bool ok = true;
  out.reserve(words.size());
  for (const Word& w : words) {
    Value v;
    ok = integer(w, what, v) && ok;
    out.push_back(v);
  }
  if (!ok) out.clear();
  return ok;
}

// Seconds with at most three decimals, converted exactly to milliseconds.
bool Builder::seconds(const Word& w, Value& out) {
  out.pos = w.pos;
  if (w.type != P::NUMBER) {
    diag_.error(w.pos, fmt::format("expected a number of seconds, found '{}'", diag::excerpt(w.text)), "bad-operand");
    return false;
  }
  if (w.text[0] == '-') {
    diag_.error(w.pos, fmt::format("DELAY cannot be negative, found '{}'", diag::excerpt(w.text)), "bad-delay");
    return false;
  }
  const std::string_view t = w.text[0] == '+' ? w.text.substr(1) : w.text;
  const std::size_t dot = t.find('.');
  const std::string_view whole = t.substr(0, dot);
  const std::string_view frac = dot == std::string_view::npos ? std::string_view() : t.substr(dot + 1);
  if (frac.size() > 3) {
    diag_.error(w.pos, fmt::format("DELAY counts milliseconds: at most 3 decimals, found '{}'", diag::excerpt(w.text)),
                "bad-delay");
    return false;
  }
  std::int64_t s = 0;
  const auto r = std::from_chars(whole.data(), whole.data() + whole.size(), s);
  if (r.ec != std::errc() || s > vm::kMaxDelayMillis / 1000) {
    diag_.error(w.pos, fmt::format("DELAY is at most {} seconds, found '{}'", vm::kMaxDelayMillis / 1000,
                                   diag::excerpt(w.text)),
                "bad-delay");
    return false;
  }
  std::int64_t ms = s * 1000;
  for (std::size_t i = 0, scale = 100; i < frac.size(); ++i, scale /= 10) ms += (frac[i] - '0') * static_cast<std::int64_t>(scale);
  if (ms > vm::kMaxDelayMillis) {
    diag_.error(w.pos, fmt::format("DELAY is at most {} seconds, found '{}'", vm::kMaxDelayMillis / 1000,
                                   diag::excerpt(w.text)),
                "bad-delay");
    return false;
  }
  out.number = ms;
  return true;
}

bool Builder::name(const Word& w, std::string_view what, std::string_view& out, diag::Pos& pos) {
  pos = w.pos;
  if (w.type != P::IDENT) {
    diag_.error(w.pos, fmt::format("expected {}, found '{}'", what, diag::excerpt(w.text)), "bad-operand");
    return false;
  }
  // "a variable name" -> "a variable" for checkName's "cannot name ..."
  const std::string_view noun = what.substr(0, what.size() - (what.ends_with(" name") ? 5 : 0));
  if (!checkName(noun, w.text, w.pos)) return false;
  out = w.text;
  return true;
}

bool Builder::onOff(const Word& w, bool& out) {
  if (w.type == P::IDENT && (sameName(w.text, "ON") || sameName(w.text, "OFF"))) {
    out = sameName(w.text, "ON");
    return true;
  }
  diag_.error(w.pos, fmt::format("expected ON or OFF, found '{}'", diag::excerpt(w.text)), "bad-operand");
  return false;
}

bool Builder::compare(const Word& w, vm::Compare& out) {
  if (w.type == P::CMP) {
    out = w.text == "<" ? vm::Compare::Less : w.text == ">" ? vm::Compare::Greater : vm::Compare::Equal;
    return true;
  }
  diag_.error(w.pos, fmt::format("expected a comparison <, > or =, found '{}'", diag::excerpt(w.text)),
                "bad-operand");
  return false;
}

bool Builder::jump(const Word& w, JumpRef& out) {
  out.pos = w.pos;
  if (w.type == P::IDENT) {
    if (!checkName("a label", w.text, w.pos)) return false;
    out.label = w.text;
    return true;
  }
  Value v;
  if (!integer(w, "a line number or label", v)) return false;
  if (v.number < 1) {
    diag_.error(w.pos, fmt::format("line numbers start at 1, found {}", v.number), "bad-line-number");
    return false;
  }
  out.number = static_cast<std::uint32_t>(v.number);
  return true;
}

std::string Builder::motorLetters() const {
  std::string s;
  for (const vm::MotorSpec& m : motors_) s += fmt::format("{}{}", s.empty() ? "" : " ", m.letter);
  return s;
}

}  // namespace


std::string_view closestMnemonic(std::string_view word) {
  std::vector<std::string_view> names;
  for (const vm::OpInfo& op : vm::kOps) names.push_back(op.name);
  return base::nearestName(word, names);
}

namespace {

// Collects what the builder hands on into a Program.
class Collect final : public AstSink {
 public:
  explicit Collect(const diag::SourceFile& source) {
    // One instruction per line at most: reserving for that touches no
    // memory the program does not use, and saves the copies of growth.
    program.instructions.reserve(source.lineCount());
  }
  void instruction(const Instruction& in) override { program.instructions.push_back(in); }
  void pointsHeader(diag::Pos pos) override { program.pointsHeader = pos; }
  void point(const PointDef& p) override { program.points.push_back(p); }
  Program program;
};

}  // namespace

void buildAst(const diag::SourceFile& source, LineParser& parser, std::span<const vm::MotorSpec> motors,
              diag::Diagnostics& diagnostics, AstSink& sink) {
  Builder b(source, motors, diagnostics, sink);
  while (antlr4::ParserRuleContext* l = parser.next()) b.line(static_cast<P::LineContext*>(l), parser.recovered());
  b.finish();
}

Program buildAst(ParseTree& tree, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics) {
  Collect collect(tree.source());
  Builder b(tree.source(), motors, diagnostics, collect);
  for (P::LineContext* l : static_cast<P::ProgramContext*>(tree.root())->line()) b.line(l, tree.recovered());
  b.finish();
  return std::move(collect.program);
}

Program buildAst(const diag::SourceFile& source, LineParser& parser, std::span<const vm::MotorSpec> motors,
                 diag::Diagnostics& diagnostics) {
  Collect collect(source);
  buildAst(source, parser, motors, diagnostics, collect);
  return std::move(collect.program);
}

}  // namespace rs::compiler
