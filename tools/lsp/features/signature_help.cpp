// textDocument/signatureHelp: an instruction's operands, the one the
// cursor is in highlighted; for a motor vector, which motor each value
// moves (letter, kind, range, speed).
#include <fmt/format.h>

#include "tools/lsp/features/features.h"

namespace rs::lsp {

Json signatureHelp(const ProgramContext& p, Position at) {
  const LineContext c = lineContext(p, at);
  if (!c.usable || !c.op) return nullptr;
  const vm::OpInfo& op = vm::info(*c.op);
  std::string label(op.name);
  Json parameters = Json::array();
  const auto add = [&](std::string_view name, std::string doc) {
    label += ' ';
    const std::size_t start = label.size();
    label += name;
    parameters.push_back({{"label", {start, label.size()}}, {"documentation", std::move(doc)}});
  };
  if (op.format == vm::Format::MotorVector) {
    const bool relative = op.flags & vm::kRelative;
    for (const vm::MotorSpec& m : p.analysis.cell().target.motors) {
      const char* kind = m.kind == vm::JointKind::Revolute    ? "revolute"
                         : m.kind == vm::JointKind::Prismatic ? "prismatic"
                                                              : "gripper";
      add(std::string(1, m.letter), fmt::format("motor {} ({}): {} encoder units, range {}..{}, {} units/s", m.letter,
                                                kind, relative ? "by" : "to", m.min, m.max, m.speed));
    }
  } else {
    // " <input> ON|OFF <line>" -> its words
    const std::string_view usage = vm::info(op.format).usage;
    for (std::size_t i = 0; i < usage.size();) {
      while (i < usage.size() && usage[i] == ' ') ++i;
      std::size_t end = usage.find(' ', i);
      if (end == std::string_view::npos) end = usage.size();
      if (end > i) add(usage.substr(i, end - i), std::string(op.meaning));
      i = end;
    }
  }
  if (parameters.empty()) return nullptr;
  Json signature = {{"label", label}, {"documentation", std::string(op.meaning)}, {"parameters", parameters}};
  const std::size_t active = std::min(c.operand, parameters.size() - 1);
  return {{"signatures", Json::array({signature})}, {"activeSignature", 0}, {"activeParameter", active}};
}

}  // namespace rs::lsp
