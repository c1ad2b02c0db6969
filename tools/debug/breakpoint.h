// Where and when a debugging session stops: breakpoints (before an
// instruction, a line or a label; when the clock passes a time; when a
// condition on an output, an input or a variable becomes true; at a
// collision; at a warning: a gripper closing on nothing; at a device's
// event: a sensor's edge, a part fed or taken), each with
// an optional condition and hit count, and watches (stop when a value
// changes). Breakpoints and watches share one numbering, as in gdb.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "diag/result.h"
#include "tools/debug/device_points.h"
#include "tools/debug/expression.h"

namespace rs::debug {

struct Breakpoint {
  enum class Kind : std::uint8_t { Line, Label, Instruction, Time, When, Collision, Warning, Device };
  int id = 0;
  Kind kind = Kind::Line;
  std::uint32_t line = 0;       ///< Line: where it stands (the first line with code at or after the one asked)
  std::string label;            ///< Label: as the program spells it
  std::uint32_t instruction = 0;  ///< Instruction: 0-based; Label: the label's
  /// Line, Label, Instruction: it stops before any of these runs.
  std::vector<std::uint32_t> instructions;
  vm::Micros time = 0;  ///< Time: it stops right after the clock passes this
  Condition when;       ///< When: it stops as this becomes true
  DevicePoint device;   ///< Device: which device, which of its events
  std::optional<Condition> condition;
  std::optional<HitCondition> hits;
  std::uint64_t hitCount = 0;  ///< times reached (with the condition true) running forwards

  /// "line 12", "label LOOP, line 3", "@7, line 5" (instructions numbered
  /// from 1, as robotsim disasm lists them), "at 1.500 s", "when out 2 = 1",
  /// "collision", "warning", "sensor eye ON", "feeder parts".
  std::string where() const;
  /// where() with " if N = 3" and " hits >= 2" when set.
  std::string describe() const;
  /// It stands at a place in the program (a line, a label, an instruction).
  bool inProgram() const { return kind == Kind::Line || kind == Kind::Label || kind == Kind::Instruction; }
};

struct Watch {
  int id = 0;
  Expression what;
};

/// What stopped a run, one line: "breakpoint 1 (line 6), watch 2: N changed
/// from 0 to 1: sensor eye ON at 1.100 s". `ids`: the breakpoints' and
/// watches' ids, in the order they were found; `describe(id)`: a
/// breakpoint's description (nullopt: a watch, whose `notes` say in turn
/// what changed); `happened`: what the devices did, after them.
std::string stopText(const std::vector<int>& ids, const std::function<std::optional<std::string>(int)>& describe,
                     const std::vector<std::string>& notes, const std::vector<std::string>& happened);

/// A breakpoint before label `label` of `image`'s program (any case; its
/// kind, place and instructions set, no id yet), or why there is none.
diag::Result<Breakpoint> labelBreakpoint(const vm::Image& image, std::string_view label);
/// Before instruction `index` (0-based; messages number from 1, as disasm).
diag::Result<Breakpoint> instructionBreakpoint(const vm::Image& image, std::uint32_t index);

/// Erases the item of `items` (breakpoints or watches) whose id is `id`; false when there is none.
template <class T>
bool eraseId(std::vector<T>& items, int id) {
  const auto at = std::find_if(items.begin(), items.end(), [id](const T& x) { return x.id == id; });
  if (at == items.end()) return false;
  items.erase(at);
  return true;
}

}  // namespace rs::debug
