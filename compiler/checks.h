// Semantic checks: names resolved (labels, points, variables), numbers in
// range, control flow analysed. Produces the resolution codegen needs.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "compiler/ast.h"
#include "diag/diagnostic.h"
#include "vm/image.h"

namespace rs::compiler {

struct Resolution {
  std::vector<std::uint32_t> target;          // per instruction: 0-based jump target
  std::vector<std::uint16_t> slot;            // per instruction: variable slot or point index
  std::vector<std::string_view> variables;    // slot -> name, first spelling
};

Resolution check(const Program& program, std::span<const vm::MotorSpec> motors, diag::Diagnostics& diagnostics);

}  // namespace rs::compiler
