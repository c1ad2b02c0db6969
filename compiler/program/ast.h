// The AST of a robot program: instructions with typed operands, and taught
// points. Names point into the SourceFile's text (string_view), so the
// source must outlive the AST; every node carries its position.
#pragma once

#include <array>
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

/// Three numbers written after a pose keyword ("AT 300 120 50").
struct PoseVector {
  std::array<double, 3> v{};
  diag::Pos pos;  // of the keyword
  bool given = false;
};

/// A point written as a tool pose: "AT [WORLD|ROBOT] x y z [APPROACH ax ay az]
/// [NORMAL nx ny nz] [GRIP g]" (docs/language.md, "Points as tool poses").
struct PointPose {
  bool robotFrame = false;  // ROBOT: the robot's design coordinates; else the cell's world
  PoseVector at, approach, normal;
  Value grip;               // the gripper's encoder count
  bool gripGiven = false;
  std::string_view text;    // as written, from AT to the line's last word
};

struct PointDef {
  std::string_view name;
  diag::Pos pos;
  /// One encoder value per motor; for a pose, the resolved values (set by
  /// the checker before an observer sees the point; empty when it failed).
  std::vector<Value> values;
  bool isPose = false;
  PointPose pose;
};

struct Program {
  std::vector<Instruction> instructions;
  std::vector<PointDef> points;
  diag::Pos pointsHeader;            // line 0 when there is no POINTS section
};

}  // namespace rs::compiler
