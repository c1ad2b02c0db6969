#include "tools/debug/expression.h"

#include <fmt/format.h>

#include <charconv>
#include <vector>

#include "base/ascii.h"
#include "base/text.h"
#include "runtime/sim/input_schedule.h"
#include "compiler/stimuli/stimuli_text.h"
#include "vm/io_lines.h"

namespace rs::debug {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

std::string ioWords(std::string_view text) {
  std::vector<std::string_view> w;
  for (std::size_t i = 0; i < text.size();) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
    if (i > start) w.push_back(text.substr(start, i - start));
  }
  const bool io = !w.empty() && (base::sameName(w[0], "output") || base::sameName(w[0], "input"));
  const std::string_view short_ = io && base::sameName(w[0], "output") ? "out" : "in";
  if (io && w.size() == 2) return fmt::format("{} {}", short_, w[1]);
  if (io && w.size() == 3 && (base::sameName(w[2], "on") || base::sameName(w[2], "off")))
    return fmt::format("{} {} = {}", short_, w[1], base::sameName(w[2], "on") ? 1 : 0);
  return std::string(text);
}

diag::Result<vm::Micros> parseSeconds(std::string_view text) { return stimuli::text::parseSeconds(trimmed(text)); }

namespace {

std::optional<std::int64_t> integer(std::string_view text) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string shown(std::string_view text) { return base::safeText(text.substr(0, 60)); }

}  // namespace

diag::Result<Expression> parseExpression(const vm::Image& image, std::string_view text) {
  text = trimmed(text);
  if (text.empty()) return diag::refusal("an expression is a variable, a motor letter, 'in N', 'out N' or 'clock'");
  for (std::size_t s = 0; s < image.variables.size(); ++s)
    if (base::sameName(image.variables[s], text))
      return Expression{Expression::Kind::Variable, static_cast<std::uint32_t>(s), image.variables[s]};
  for (std::size_t m = 0; m < image.motors.size(); ++m)
    if (text.size() == 1 && base::sameName(std::string_view(&image.motors[m].letter, 1), text))
      return Expression{Expression::Kind::Motor, static_cast<std::uint32_t>(m), std::string(1, image.motors[m].letter)};
  if (base::sameName(text, "clock")) return Expression{Expression::Kind::Clock, 0, "clock"};
  for (const auto& [word, kind] : {std::pair{std::string_view("in"), Expression::Kind::Input},
                                   std::pair{std::string_view("out"), Expression::Kind::Output}}) {
    if (text.size() <= word.size() || !base::sameName(text.substr(0, word.size()), word)) continue;
    const std::string_view rest = trimmed(text.substr(word.size()));
    if (rest.size() == text.size() - word.size() && !rest.empty() && rest.front() != ' ') continue;  // "input"
    const auto n = integer(rest);
    if (!n || *n < 1 || *n > vm::kIoCount)
      return diag::refusal(fmt::format("'{}': {} takes a line number 1..{}", shown(text), word, vm::kIoCount));
    return Expression{kind, static_cast<std::uint32_t>(*n), fmt::format("{} {}", word, *n)};
  }
  return diag::refusal(
      fmt::format("'{}' is not a variable of the program, a motor letter, 'in N', 'out N' or 'clock'", shown(text)));
}

std::int64_t valueOf(const runtime::Run& run, const Expression& e) {
  switch (e.kind) {
    case Expression::Kind::Variable:
      return run.interpreter().variables()[e.index];
    case Expression::Kind::Motor:
      return run.rig().motors()[e.index];
    case Expression::Kind::Input:
      return (run.rig().machine().inputs() & runtime::lineBit(static_cast<int>(e.index))) != 0;
    case Expression::Kind::Output:
      return (run.rig().machine().outputs() & runtime::lineBit(static_cast<int>(e.index))) != 0;
    case Expression::Kind::Clock:
      return run.rig().clock();
  }
  return 0;
}

std::int64_t valueIn(const runtime::RunView& view, const Expression& e) {
  switch (e.kind) {
    case Expression::Kind::Variable:
      return e.index < view.variables.size() ? view.variables[e.index].second : 0;
    case Expression::Kind::Motor:
      return e.index < view.motors.size() ? view.motors[e.index] : 0;
    case Expression::Kind::Input:
      return (view.inputs & runtime::lineBit(static_cast<int>(e.index))) != 0;
    case Expression::Kind::Output:
      return (view.outputs & runtime::lineBit(static_cast<int>(e.index))) != 0;
    case Expression::Kind::Clock:
      return view.clock;
  }
  return 0;
}

namespace {

constexpr std::pair<std::string_view, Condition::Op> kOps[] = {
    {"==", Condition::Op::Eq}, {"<>", Condition::Op::Ne}, {"!=", Condition::Op::Ne}, {"<=", Condition::Op::Le},
    {">=", Condition::Op::Ge}, {"=", Condition::Op::Eq},  {"<", Condition::Op::Lt},  {">", Condition::Op::Gt},
};

std::string_view opText(Condition::Op op) {
  switch (op) {
    case Condition::Op::Eq: return "=";
    case Condition::Op::Ne: return "<>";
    case Condition::Op::Lt: return "<";
    case Condition::Op::Le: return "<=";
    case Condition::Op::Gt: return ">";
    case Condition::Op::Ge: return ">=";
  }
  return "=";
}

}  // namespace

bool Condition::holds(const runtime::Run& run) const {
  const std::int64_t v = valueOf(run, left);
  switch (op) {
    case Op::Eq: return v == right;
    case Op::Ne: return v != right;
    case Op::Lt: return v < right;
    case Op::Le: return v <= right;
    case Op::Gt: return v > right;
    case Op::Ge: return v >= right;
  }
  return false;
}

diag::Result<Condition> parseCondition(const vm::Image& image, std::string_view text) {
  text = trimmed(text);
  if (text.empty()) return diag::refusal("a condition is missing: NAME OP VALUE, with OP one of = <> < <= > >=");
  std::size_t at = std::string_view::npos;
  Condition c;
  std::size_t opLength = 0;
  for (std::size_t i = 0; i < text.size() && at == std::string_view::npos; ++i)
    for (const auto& [word, op] : kOps)
      if (text.substr(i, word.size()) == word) {
        at = i, c.op = op, opLength = word.size();
        break;
      }
  if (at == std::string_view::npos)
    return diag::refusal(fmt::format("'{}': a condition is NAME OP VALUE, with OP one of = <> < <= > >=", shown(text)));
  auto left = parseExpression(image, text.substr(0, at));
  if (!left) return left.failure();
  c.left = *left;
  const std::string_view right = trimmed(text.substr(at + opLength));
  if (base::sameName(right, "on")) c.right = 1;
  else if (base::sameName(right, "off")) c.right = 0;
  else if (const auto n = integer(right)) c.right = *n;
  else if (c.left.kind == Expression::Kind::Clock) {
    const diag::Result<vm::Micros> s = stimuli::text::parseSeconds(right);
    if (!s) return diag::refusal(fmt::format("'{}': {}", shown(right), s.failure().message));
    c.right = *s;
  } else {
    return diag::refusal(fmt::format("'{}' is not a whole number (or on, off)", shown(right)));
  }
  c.text = fmt::format("{} {} {}", base::safeText(c.left.name), opText(c.op), c.right);
  return c;
}

bool HitCondition::stopsAt(std::uint64_t hits) const {
  switch (op) {
    case Op::AtLeast: return hits >= n;
    case Op::Exactly: return hits == n;
    case Op::Every: return n > 0 && hits % n == 0;
  }
  return true;
}

std::string HitCondition::text() const {
  switch (op) {
    case Op::AtLeast: return fmt::format(">= {}", n);
    case Op::Exactly: return fmt::format("== {}", n);
    case Op::Every: return fmt::format("% {}", n);
  }
  return {};
}

diag::Result<HitCondition> parseHitCondition(std::string_view text) {
  text = trimmed(text);
  HitCondition h;
  if (text.starts_with(">=")) text.remove_prefix(2);
  else if (text.starts_with("==")) h.op = HitCondition::Op::Exactly, text.remove_prefix(2);
  else if (text.starts_with("%")) h.op = HitCondition::Op::Every, text.remove_prefix(1);
  const auto n = integer(trimmed(text));
  if (!n || *n < 1)
    return diag::refusal(
        fmt::format("'{}': a hit count is N, >= N, == N or % N, with N a whole number from 1", shown(text)));
  h.n = static_cast<std::uint64_t>(*n);
  return h;
}

}  // namespace rs::debug
