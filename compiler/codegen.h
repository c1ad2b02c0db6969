// AST + resolution -> image. Runs only on programs without errors, so it
// never reports anything; the opcode table says which fields each op fills.
#pragma once

#include "compiler/ast.h"
#include "compiler/checks.h"
#include "vm/image.h"

namespace rs::compiler {

struct Target {
  std::string robotName;
  std::vector<vm::MotorSpec> motors;
  std::uint16_t callDepthLimit = vm::kDefaultCallDepth;
};

vm::Image generate(const Program& program, const Resolution& resolution, const Target& target,
                   std::string sourceName);

}  // namespace rs::compiler
