// One instruction of the AST to its bytecode record. The checker
// (translator.h) calls it for every instruction as the AST builder hands it
// on, with the slot and jump target it resolved (or 0 until they are
// known: a forward label or a point is patched at the end); it never
// reports anything. The opcode table says which fields each op fills.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compiler/program/ast.h"
#include "model/workcell/line_plan_cache.h"
#include "model/workcell/model.h"
#include "vm/image.h"

namespace rs::compiler {

struct Target {
  std::string robotName;
  std::vector<vm::MotorSpec> motors;
  std::uint16_t callDepthLimit = vm::kDefaultCallDepth;
  /// The robot as placed in the cell, when it has a kinematic model: points
  /// written as tool poses are resolved with it (none: they are refused).
  std::shared_ptr<const workcell::PlacedRobot> robot = nullptr;
  /// The straight lines planned by earlier compiles for this target
  /// (model/workcell/line_plan_cache.h; may be null: each compile plans
  /// its own, still once a line).
  std::shared_ptr<workcell::LinePlanCache> linePlans = nullptr;
  /// False: the compile leaves the straight lines' path check
  /// (line_check.h) to its caller, which makes it later (a language
  /// server, off its request thread); the image is then made before it.
  bool checkLines = true;
  /// A library workcell whose robot has exactly these motors and a
  /// kinematic model, named by the hints of what needs one ("": none known,
  /// and the hints name none).
  std::string cellHint = {};
};

/// The record of `in`; its motor vector or triple is appended to `constants`.
vm::Instr encode(const Instruction& in, std::uint16_t slot, std::uint32_t target, std::vector<std::int32_t>& constants);

}  // namespace rs::compiler
