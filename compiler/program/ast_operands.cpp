// An instruction's operands, read by its opcode's format (vm::kFormats),
// and the readers of one operand each: integers, seconds, names, ON/OFF,
// comparisons, jump targets. Each reader reports what it expected.
#include <charconv>
#include <initializer_list>
#include <fmt/format.h>

#include "compiler/program/ast_builder_detail.h"

namespace rs::compiler::detail {

namespace {

// Every operand is checked, even after one fails, so a line reports all its
// mistakes at once (a braced list evaluates its elements in order).
bool all(std::initializer_list<bool> checks) {
  for (bool ok : checks)
    if (!ok) return false;
  return true;
}

}  // namespace

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
    case vm::Format::Distance: return integer(w[0], "a distance in length units", in.value);
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

}  // namespace rs::compiler::detail
