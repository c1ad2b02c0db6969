// `robotsim help [INSTRUCTION]`: the instruction set, from the opcode table.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace rs::cli {

/// `robotsim help`'s argument, and the command: the summary without a
/// topic, one instruction's help with one, exit 2 for an unknown one.
void addHelpOptions(CLI::App* cmd, std::string& topic);
int helpCommand(const std::string& topic, std::ostream& out, std::ostream& err);

/// One line per instruction: usage and meaning.
std::string instructionSummary();

/// Usage, meaning, details and an example of one instruction; nullopt if
/// there is no such instruction.
std::optional<std::string> instructionHelp(std::string_view name);

/// The instructions someone who typed `word` may have meant, at most
/// kMaxSuggestions, in the table's order: those whose name holds the word
/// (of at least 3 letters: WAIT -> WAITFOR, SOFT -> SETSOFT and GOSOFT,
/// HOME -> HRDHOME rather than MOVE, two letters away); failing that, the
/// nearest by a typo (base/near_names.h: MOVTO -> MOVETO).
inline constexpr std::size_t kMaxSuggestions = 3;
std::vector<std::string_view> instructionsLike(std::string_view word);

/// The error for an unknown topic: "no instruction named 'WAIT'; did you
/// mean WAITFOR? (robotsim help lists them)", the word made printable.
std::string unknownInstructionMessage(std::string_view word);

}  // namespace rs::cli
