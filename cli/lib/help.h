// `robotsim help [INSTRUCTION]`: the instruction set, from the opcode table.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs::cli {

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
