#include "tools/debug/breakpoint.h"

#include <fmt/format.h>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"

namespace rs::debug {

std::string Breakpoint::where() const {
  switch (kind) {
    case Kind::Line: return fmt::format("line {}", line);
    case Kind::Label: return fmt::format("label {}, line {}", base::safeText(label), line);
    case Kind::Instruction: return fmt::format("@{}, line {}", instruction + 1, line);
    case Kind::Time: return fmt::format("at {} s", base::formatSeconds(time));
    case Kind::When: return fmt::format("when {}", when.text);
    case Kind::Collision: return "collision";
    case Kind::Warning: return "warning: a gripper closing on nothing";
    case Kind::Device: return device.text();
  }
  return {};
}

std::string Breakpoint::describe() const {
  std::string text = where();
  if (condition) text += fmt::format(" if {}", condition->text);
  if (hits) text += fmt::format(" hits {}", hits->text());
  return text;
}

std::string stopText(const std::vector<int>& ids, const std::function<std::optional<std::string>(int)>& describe,
                     const std::vector<std::string>& notes, const std::vector<std::string>& happened) {
  std::string text;
  for (std::size_t i = 0, w = 0; i < ids.size(); ++i) {
    std::string part;
    if (const std::optional<std::string> d = describe(ids[i])) part = fmt::format("breakpoint {} ({})", ids[i], *d);
    else if (w < notes.size()) part = fmt::format("watch {}: {}", ids[i], notes[w++]);
    else continue;
    text += (text.empty() ? "" : ", ") + part;
  }
  for (std::size_t h = 0; h < happened.size(); ++h) text += (h == 0 ? ": " : ", ") + happened[h];
  return text;
}

diag::Result<Breakpoint> labelBreakpoint(const vm::Image& image, std::string_view label) {
  const std::optional<std::uint32_t> at = runtime::labelInstruction(image, label);
  if (!at) return diag::refusal(fmt::format("the program has no label '{}'", base::safeText(label.substr(0, 60))));
  Breakpoint b;
  b.kind = Breakpoint::Kind::Label;
  for (const vm::Label& l : image.labels)
    if (base::sameName(image.labelName(l), label)) b.label = image.labelName(l);
  b.instruction = *at;
  b.line = image.lines[*at];
  b.instructions = {*at};
  return b;
}

diag::Result<Breakpoint> instructionBreakpoint(const vm::Image& image, std::uint32_t index) {
  const std::size_t size = image.code.size();
  if (index >= size) return diag::refusal(fmt::format("no instruction @{}: the program has @1 to @{}", index + 1, size));
  Breakpoint b;
  b.kind = Breakpoint::Kind::Instruction;
  b.instruction = index;
  b.line = image.lines[index];
  b.instructions = {index};
  return b;
}

}  // namespace rs::debug
