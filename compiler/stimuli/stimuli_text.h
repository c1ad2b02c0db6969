// Word-level helpers of the stimuli reader: keywords, seconds, line numbers,
// and tokens quoted for messages. The other readers of the same words use
// them too (the command line's numbers, the debugger's expressions, the test
// expectations, a run request), so that a second reads the same everywhere.
#pragma once

#include <string>
#include <string_view>

#include "diag/result.h"
#include "vm/machine.h"

namespace rs::stimuli::text {

/// ASCII case-insensitive equality; keywords are ASCII, the locale plays no part.
bool equalsKeyword(std::string_view token, std::string_view keyword);

/// `token` in single quotes, safe to print: bytes outside printable ASCII
/// become \xNN and a long token is cut short with "...".
std::string quoted(std::string_view token);

/// Seconds as exact microseconds: parses `DIGITS [. DIGITS]` with at most
/// 6 decimals and at most 1e6 s, digit by digit: no floating point, no
/// overflow on any length. A failure has no place (diag::refusal): the
/// caller knows where the token stands.
diag::Result<vm::Micros> parseSeconds(std::string_view token);

/// An input or output line number 1..vm::kIoCount; `what` ("input", "output") names
/// it in the failure, which has no place either.
diag::Result<int> parseLineNumber(std::string_view token, std::string_view what);

/// A robot's label as a stimulus names it before the last '.': a name as
/// descriptions spell one (a letter or '_', then letters, digits, '_', '-'
/// or '.'; ASCII), at most 64 bytes.
bool isLabel(std::string_view token);

}  // namespace rs::stimuli::text
