// A workcell as bytes, so a compiled image can carry the cell it was
// compiled for (`robotsim compile PROG --cell CELL`) and run without any
// description file. Layout: docs/bytecode.md, section "cell".
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/workcell/model.h"

namespace rs::workcell {

std::vector<std::uint8_t> encodeCell(const Workcell& cell);

struct CellDecode {
  std::optional<Workcell> cell;
  std::string error;  // set when cell is empty
};

/// Decodes and re-derives every robot's chain; a malformed or hostile blob
/// gets an error, never undefined behaviour.
CellDecode decodeCell(std::span<const std::uint8_t> bytes);

}  // namespace rs::workcell
