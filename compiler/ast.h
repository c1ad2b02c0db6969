// The AST of a robot program: instructions with typed operands, and taught
// points. Names point into the SourceFile's text (string_view), so the
// source must outlive the AST; every node carries its position.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "diag/source_file.h"
#include "vm/opcodes.h"

namespace rs::compiler {

/// A value written in the source, with where it was written.
struct Value {
  std::int64_t number = 0;  // integers as written; DELAY seconds as milliseconds
  diag::Pos pos;
};

/// A reference to an instruction: a 1-based number or a label.
struct JumpRef {
  std::uint32_t number = 0;    // when label is empty
  std::string_view label;
  diag::Pos pos;
};

struct Instruction {
  diag::Pos pos;                     // of the mnemonic
  std::uint32_t number = 0;    // 1-based instruction number
  vm::Op op = vm::Op::End;
  bool known = true;           // false: unknown mnemonic (reported)
  std::string_view label;      // label defined on this instruction, if any
  diag::Pos labelPos;

  // Operands; which are meaningful follows the opcode's format.
  std::vector<Value> values;   // MotorVector, Triple
  Value io;                    // input or output number
  bool on = false;             // ON / OFF
  vm::Compare compare = vm::Compare::Equal;
  std::string_view name;       // variable (VarCompare, VarValue) or point
  diag::Pos namePos;
  Value value;                 // VarCompare, VarValue, Millis
  JumpRef target;              // Target, InputJump, VarCompare
};

struct PointDef {
  std::string_view name;
  diag::Pos pos;
  std::vector<Value> values;
};

struct Program {
  std::vector<Instruction> instructions;
  std::vector<PointDef> points;
  diag::Pos pointsHeader;            // line 0 when there is no POINTS section
};

}  // namespace rs::compiler
