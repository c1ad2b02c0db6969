// `robotsim help [INSTRUCTION]`: the instruction set, from the opcode table.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rs::cli {

/// One line per instruction: usage and meaning.
std::string instructionSummary();

/// Usage, meaning, details and an example of one instruction; nullopt if
/// there is no such instruction.
std::optional<std::string> instructionHelp(std::string_view name);

}  // namespace rs::cli
