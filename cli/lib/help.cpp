#include "cli/lib/help.h"

#include <fmt/format.h>

#include "vm/opcodes.h"

namespace rs::cli {

namespace {

std::string usageLine(const vm::OpInfo& op) {
  return fmt::format("{}{}", op.name, vm::info(op.format).usage);
}

}  // namespace

std::string instructionSummary() {
  std::string out = "ROBOTSIM instructions (robotsim help INSTRUCTION for details):\n";
  for (const vm::OpInfo& op : vm::kOps) out += fmt::format("  {:<44} {}\n", usageLine(op), op.meaning);
  return out;
}

std::optional<std::string> instructionHelp(std::string_view name) {
  const auto op = vm::opByName(name);
  if (!op) return std::nullopt;
  const vm::OpInfo& info = vm::info(*op);
  return fmt::format("{}\n  {}.\n  {}\nExample:\n  {}\n", usageLine(info), info.meaning, info.detail, info.example);
}

}  // namespace rs::cli
