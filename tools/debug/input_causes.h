// What the debugger says about what drives an input (issue 35): the
// refusal of `set input` on an input a WIRE drives, the same words in
// both consoles and the adapter, and what set an input last, beside its
// value (`print in N`, `print io`, a watch, the adapter's Inputs scope).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "runtime/run/run.h"
#include "tools/debug/expression.h"

namespace rs::debug {

/// Why input `input` of the cell's robot `robot` cannot be set by hand,
/// when one of `cell`'s wires drives it: "input 1 is wired from sensor eye
/// (line 7 of belt-cell): the sensor turns it ...; to set it by hand, remove
/// the WIRE". `label`: the robot's name in a cell of several ("input 1 of
/// left"), empty for the one robot a program runs on. nullopt: no wire
/// drives it.
std::optional<std::string> wiredInputRefusal(const workcell::Workcell& cell, std::size_t robot, int input,
                                             std::string_view label);

/// The same for the input of `run`'s robot (a run without a workcell has no wires).
std::optional<std::string> wiredInputRefusal(const runtime::Run& run, int input, std::string_view label);

/// What set input `input` of `run` last and when, in the trace's words
/// ("since 10.000 s: wire from sensor eye"), when it is what the input
/// shows now (`on`); empty when nothing changed it since the start.
std::string inputCauseNote(const runtime::Run& run, int input, bool on);
/// " (since 10.000 s: wire from sensor eye)" after an input's value
/// `value` (`in 1 = 1`, a watch's change); empty for any other expression
/// or an input nothing changed.
std::string causeAside(const runtime::Run& run, const Expression& e, std::int64_t value);
/// What a `when` breakpoint on an input says it saw: "input 1 ON since
/// 1.100 s: wire from sensor eye"; empty for another condition, or an
/// input nothing changed.
std::string conditionCause(const runtime::Run& run, const Condition& condition);

}  // namespace rs::debug
