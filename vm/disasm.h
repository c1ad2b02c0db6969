// The disassembler: a listing of an image in the spirit of `luac -l` and
// clox's debug.c, driven by each opcode's operand format. The execution
// trace prints instructions with the same functions. Every name an image
// holds (source, robot, labels, points, variables) is printed through
// base::safeText: a forged image cannot send control characters to a
// terminal.
#pragma once

#include <cstdint>
#include <string>

#include "vm/image.h"

namespace rs::vm {

/// Mnemonic and operands as a program would write them: "JMPIN 3 ON 7".
std::string instructionText(const Image& image, std::uint32_t index);

/// What the operands refer to, e.g. "-> 7 (line 12, loop)" or
/// "P1 = 100 0 0 0 0"; empty when there is nothing to resolve.
std::string instructionComment(const Image& image, std::uint32_t index);

/// The label of an instruction, or empty; as the image holds it (raw: print
/// it through base::safeText).
std::string_view labelAt(const Image& image, std::uint32_t index);

/// One instruction's row of the listing (without a line break): its
/// number (1-based), its source line ('|' when the instruction before is on
/// the same line), label, text and comment. The debugger's `disasm` prints
/// these rows.
std::string listingRow(const Image& image, std::uint32_t index);

/// The whole listing: a header, one line per instruction, then points.
std::string disassemble(const Image& image);

}  // namespace rs::vm
