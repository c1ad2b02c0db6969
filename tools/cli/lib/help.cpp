#include "tools/cli/lib/help.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "base/ascii.h"
#include "base/near_names.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"
#include "vm/opcodes.h"

namespace rs::cli {

namespace {

std::string usageLine(const vm::OpInfo& op) { return fmt::format("{}{}", op.name, vm::info(op.format).usage); }

// Whether `name` holds `word`, ignoring ASCII letter case.
bool nameHolds(std::string_view name, std::string_view word) {
  for (std::size_t at = 0; at + word.size() <= name.size(); ++at)
    if (base::sameName(name.substr(at, word.size()), word)) return true;
  return false;
}

// "'A'", "'A' or 'B'", "'A', 'B' or 'C'".
std::string alternatives(const std::vector<std::string_view>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += fmt::format("{}'{}'", i == 0 ? "" : i + 1 == names.size() ? " or " : ", ", names[i]);
  return s;
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

std::vector<std::string_view> instructionsLike(std::string_view word) {
  std::vector<std::string_view> names;
  for (const vm::OpInfo& op : vm::kOps) names.push_back(op.name);
  std::vector<std::string_view> found;
  if (word.size() >= 3 && word.size() <= base::kMaxNearWord)
    for (const std::string_view name : names)
      if (nameHolds(name, word) && found.size() < kMaxSuggestions) found.push_back(name);
  if (!found.empty()) return found;
  if (const std::string_view near = base::nearestName(word, names, base::typoDistance(word)); !near.empty())
    found.push_back(near);
  return found;
}

std::string unknownInstructionMessage(std::string_view word) {
  std::string shown = base::safeText(word.substr(0, 64));
  if (word.size() > 64) shown += "...";
  const std::vector<std::string_view> like = instructionsLike(word);
  return fmt::format("no instruction named '{}'{} (robotsim help lists them)", shown,
                     like.empty() ? "" : fmt::format("; did you mean {}?", alternatives(like)));
}

void addHelpOptions(CLI::App* cmd, std::string& topic) {
  cmd->add_option("instruction", topic, "Instruction name, e.g. JMPVAR");
}

int helpCommand(const std::string& topic, std::ostream& out, std::ostream& err) {
  if (topic.empty()) {
    out << instructionSummary();
    return kExitOk;
  }
  if (auto text = instructionHelp(topic)) {
    out << *text;
    return kExitOk;
  }
  err << "robotsim: error: " << unknownInstructionMessage(topic) << '\n';
  return kExitBadInput;
}

}  // namespace rs::cli
