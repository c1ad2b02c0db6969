// Text that came from a file, made safe to print. A name read from a file
// (a source name recorded in an image, a variable, label or point, a robot,
// object or cell name) may hold any bytes; printed raw, an ESC or a BEL
// would reach the terminal as a command ("\x1b]0;title\x07" sets its
// title). Every text printer passes such names through safeText().
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rs::base {

/// Length of the valid UTF-8 sequence starting at text[i], or 0 if the
/// bytes there are not valid UTF-8 (bad lead or continuation byte,
/// overlong form, surrogate, beyond U+10FFFF).
std::size_t utf8SequenceLength(std::string_view text, std::size_t i);

/// True if `text` holds a C0 control character (bytes 0x00..0x1F, tab and
/// newline included) or DEL (0x7F).
bool hasControlCharacter(std::string_view text);

/// `text` as it may be printed on a terminal: every byte of a control
/// character (C0 including tab and newline, DEL, C1 U+0080..U+009F), of a
/// bidirectional formatting character (U+200E, U+200F, U+202A..U+202E,
/// U+2066..U+2069) and every byte that is not UTF-8 becomes `\xNN` (two
/// lowercase hex digits); everything else is kept as it is. The result is
/// valid UTF-8 without control characters.
std::string safeText(std::string_view text);

/// The words of `text`, separated by spaces and tabs (a debugger's command
/// and a DAP function breakpoint are read alike).
std::vector<std::string_view> splitWords(std::string_view text);

}  // namespace rs::base
