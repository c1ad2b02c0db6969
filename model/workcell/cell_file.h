// A workcell as bytes, so a compiled image can carry the cell it was
// compiled for (`robotsim compile PROG --cell CELL`) and run without any
// description file. Layout: docs/bytecode.md, section "cell".
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "diag/result.h"
#include "model/workcell/model.h"

namespace rs::workcell {

std::vector<std::uint8_t> encodeCell(const Workcell& cell);

/// Decodes and re-derives every robot's chain; a malformed or hostile blob
/// gets a failure ("cell section: ..."), never undefined behaviour. The
/// failure has no place: the image's reader names the file.
diag::Result<Workcell> decodeCell(std::span<const std::uint8_t> bytes);

}  // namespace rs::workcell
