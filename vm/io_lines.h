// The program's inputs and outputs: how many lines there are (the paper's
// eight: inputs 1..8, outputs 1..8) and a set of them as bits. Whatever
// means the number of lines says kIoCount and every set of lines is an
// IoMask, so that a cell with more lines changes this constant's users,
// not literals scattered through the layers.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

namespace rs::vm {

/// Inputs are numbered 1..kIoCount, and so are outputs.
inline constexpr int kIoCount = 8;

/// A set of lines, bit 0 = line 1: the narrowest unsigned integer with
/// kIoCount bits. An integer rather than a std::bitset: masks are compared,
/// handed to listeners, stored in snapshots and written as numbers.
using IoMask = std::conditional_t<
    kIoCount <= 8, std::uint8_t,
    std::conditional_t<kIoCount <= 16, std::uint16_t, std::conditional_t<kIoCount <= 32, std::uint32_t, std::uint64_t>>>;
static_assert(kIoCount >= 1 && kIoCount <= std::numeric_limits<IoMask>::digits, "an IoMask holds every line");

/// True for a line number 1..kIoCount.
constexpr bool isIoLine(int line) { return line >= 1 && line <= kIoCount; }

/// The bit of line `line` in a mask; 0 outside 1..kIoCount.
constexpr IoMask lineBit(int line) { return isIoLine(line) ? static_cast<IoMask>(IoMask{1} << (line - 1)) : IoMask{0}; }

/// Whether line `line` is on in `mask` (false outside 1..kIoCount).
constexpr bool lineIsOn(IoMask mask, int line) { return (mask & lineBit(line)) != 0; }

/// `mask` with line `line` switched on or off (unchanged outside 1..kIoCount).
constexpr IoMask withLine(IoMask mask, int line, bool on) {
  const IoMask bit = lineBit(line);
  return on ? static_cast<IoMask>(mask | bit) : static_cast<IoMask>(mask & ~bit);
}

static_assert(lineBit(1) == 1 && lineBit(kIoCount) != 0 && lineBit(0) == 0 && lineBit(kIoCount + 1) == 0);
static_assert(withLine(withLine(0, 3, true), 3, false) == 0 && lineIsOn(withLine(0, kIoCount, true), kIoCount));

}  // namespace rs::vm
