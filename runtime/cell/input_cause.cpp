#include "runtime/cell/input_cause.h"

#include <fmt/format.h>

namespace rs::runtime {

const char* inputCauseWord(InputCause::Kind kind) {
  switch (kind) {
    case InputCause::Kind::Stimulus: return "stimulus";
    case InputCause::Kind::Rule: return "rule";
    case InputCause::Kind::Wire: return "wire";
    case InputCause::Kind::Set: return "set";
  }
  return "stimulus";
}

std::string inputCauseText(const InputCause& c) {
  const std::string line = c.line ? fmt::format("line {}", c.line) : std::string();
  switch (c.kind) {
    case InputCause::Kind::Stimulus: return c.line ? "stimulus, " + line : "stimulus";
    case InputCause::Kind::Rule: return c.line ? "rule of " + line : "rule";
    case InputCause::Kind::Wire: return "wire from " + c.source;
    case InputCause::Kind::Set: return "set by the debugger";
  }
  return {};
}

std::string inputChangeText(const InputCause& c) {
  return fmt::format("input {} {}: {}", c.input, c.on ? "ON" : "OFF", inputCauseText(c));
}

std::string inputSinceText(std::string_view seconds, const InputCause& c) {
  return fmt::format("since {} s: {}", seconds, inputCauseText(c));
}

}  // namespace rs::runtime
