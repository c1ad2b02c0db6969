// What a debugger can ask a run for by name, and compare: a variable, a
// motor by its letter, `in N`, `out N`, `clock` (microseconds). The
// terminal's `print` and `break ... if`, and the debug adapter's `evaluate`
// and conditional breakpoints, all read them here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "diag/result.h"
#include "runtime/run/run.h"

namespace rs::debug {

struct Expression {
  enum class Kind : std::uint8_t { Variable, Motor, Input, Output, Clock };
  Kind kind = Kind::Variable;
  std::uint32_t index = 0;  ///< variable slot, motor index, or line 1..vm::kIoCount
  std::string name;         ///< as the program spells it ("N", "A", "in 3", "clock")
};

/// `text` as an expression of `image`'s program: a variable (any case;
/// variables come before motor letters), a motor letter, `in N`, `out N`,
/// `clock`. A message saying what is wrong otherwise.
diag::Result<Expression> parseExpression(const vm::Image& image, std::string_view text);

/// The value at the run's moment (inputs and outputs 0 or 1).
std::int64_t valueOf(const runtime::Run& run, const Expression& e);
/// The same in a view of the run (the session's moment: inside a move
/// after goto-time, DebugSession::view()).
std::int64_t valueIn(const runtime::RunView& view, const Expression& e);

/// EXPRESSION OP NUMBER, with OP one of = == <> != < <= > >=; `on` and `off`
/// are 1 and 0.
struct Condition {
  enum class Op : std::uint8_t { Eq, Ne, Lt, Le, Gt, Ge };
  Expression left;
  Op op = Op::Eq;
  std::int64_t right = 0;
  std::string text;  ///< as written, normalised ("N = 3")
  bool holds(const runtime::Run& run) const;
};

diag::Result<Condition> parseCondition(const vm::Image& image, std::string_view text);

/// When a breakpoint stops, counting the times its place was reached (with
/// its condition true): from the Nth on, only the Nth, or every Nth.
struct HitCondition {
  enum class Op : std::uint8_t { AtLeast, Exactly, Every };
  Op op = Op::AtLeast;
  std::uint64_t n = 1;
  bool stopsAt(std::uint64_t hits) const;
  std::string text() const;
};

/// "N", ">= N", "== N", "% N" (DAP's hitCondition; the terminal's `hits`).
diag::Result<HitCondition> parseHitCondition(std::string_view text);

/// The words people type for inputs and outputs, as expressions:
/// "output 2" -> "out 2", "input 1 on" -> "in 1 = 1", "output 3 off" ->
/// "out 3 = 0"; anything else as written.
std::string ioWords(std::string_view text);

/// A time as the debugger's commands take it ("2.5", seconds with at most
/// six decimals): microseconds, or what is wrong with it.
diag::Result<vm::Micros> parseSeconds(std::string_view text);

/// Whitespace trimmed.
std::string_view trimmed(std::string_view s);

}  // namespace rs::debug
