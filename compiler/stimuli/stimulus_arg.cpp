// The command-line form of one timed input change:
//
//   arg := [ LABEL '.' ] N '=' STATE [ '@' SECONDS ]      e.g. 3=ON@1.5, 2=off, right.3=ON@2
//
// No blanks inside; STATE in any case; without '@' the change is at time 0.
#include <fmt/format.h>

#include <climits>

#include "compiler/stimuli/stimuli.h"
#include "compiler/stimuli/stimuli_text.h"
#include "vm/io_lines.h"

namespace rs::stimuli {
namespace {

constexpr std::string_view kForm = "(the form is N=ON@T or N=OFF@T, e.g. 3=ON@1.5)";

diag::Diagnostic failAt(std::string_view origin, std::size_t offset, std::string message) {
  const std::uint32_t column = offset >= UINT32_MAX ? UINT32_MAX : static_cast<std::uint32_t>(offset) + 1;
  return {std::string(origin), {1, column}, diag::Severity::Error, std::move(message)};
}

}  // namespace

diag::Result<InputChange> parseStimulusArg(std::string_view arg, std::string_view origin) {
  const auto equals = arg.find('=');
  if (equals == std::string_view::npos)
    return failAt(origin, arg.size(), fmt::format("expected '=' after the input number {}", kForm));
  if (equals == 0)
    return failAt(origin, 0, fmt::format("expected an input number 1..{} before '=' {}", vm::kIoCount, kForm));
  std::string_view line = arg.substr(0, equals);
  std::string robot;
  std::size_t numberOffset = 0;
  if (const auto dot = line.rfind('.'); dot != std::string_view::npos && dot > 0 && !(line[0] >= '0' && line[0] <= '9')) {
    if (!text::isLabel(line.substr(0, dot)))
      return failAt(origin, 0, fmt::format("expected a robot's label before '.', got {}", text::quoted(line.substr(0, dot))));
    robot = std::string(line.substr(0, dot));
    numberOffset = dot + 1;
    line.remove_prefix(dot + 1);
  }
  const auto number = text::parseLineNumber(line, "input");
  if (!number) return failAt(origin, numberOffset, number.failure().message);
  const auto change = [&](vm::Micros at, bool on) {
    InputChange c{at, *number, on};
    c.robot = robot;
    return c;
  };

  const auto at = arg.find('@', equals);
  const auto state = arg.substr(equals + 1, at == std::string_view::npos ? at : at - equals - 1);
  const bool on = text::equalsKeyword(state, "on");
  if (!on && !text::equalsKeyword(state, "off"))
    return failAt(origin, equals + 1,
                  state.empty()
                      ? fmt::format("expected ON or OFF after '=' {}", kForm)
                      : fmt::format("expected ON or OFF after '=', got {}", text::quoted(state)));
  if (at == std::string_view::npos) return change(0, on);

  const auto time = arg.substr(at + 1);
  if (time.empty()) return failAt(origin, at + 1, "expected a time in seconds after '@'");
  const auto seconds = text::parseSeconds(time);
  if (!seconds) return failAt(origin, at + 1, seconds.failure().message);
  return change(*seconds, on);
}

}  // namespace rs::stimuli
