// Why an input changed: a stimulus (a timed change of the stimuli), a
// reactive rule (an output's change, after the rule's delay), a wire from
// a device, or the debugger's `set input`. Every change of an input is
// reported with its cause in the same words, wherever it shows (the trace,
// the run log, the JSON trace, the debugger, the adapter, robotsim test).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rs::runtime {

struct InputCause {
  enum class Kind : std::uint8_t { Stimulus, Rule, Wire, Set };
  Kind kind = Kind::Stimulus;
  int input = 1;
  bool on = true;
  /// Stimulus or rule: its line in the stimuli file (0: given on the command
  /// line); wire: its line in the description.
  std::uint32_t line = 0;
  /// Wire: what drives it ("sensor eye", "OUT 2").
  std::string source;
  /// Wire: the label of the robot whose input it drives, as the WIRE line
  /// wrote it (`right.IN 2`; empty: `IN 2`).
  std::string robot = {};
  bool operator==(const InputCause&) const = default;
};

/// "stimulus", "rule", "wire", "set": the JSON trace's `cause`.
const char* inputCauseWord(InputCause::Kind kind);
/// "stimulus, line 3", "rule of line 2", "wire from sensor eye", "set by the debugger".
std::string inputCauseText(const InputCause& cause);
/// "input 3 ON: stimulus, line 3": the trace's words for one change.
std::string inputChangeText(const InputCause& cause);
/// "since 10.000 s: wire from sensor eye": what set an input last and when
/// (`seconds`, as the caller writes its times: "10.000", "0.0003"), as the
/// front ends show it beside the input's value.
std::string inputSinceText(std::string_view seconds, const InputCause& cause);

}  // namespace rs::runtime
