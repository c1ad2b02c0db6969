// The instruction set of the robotsim VM: the one table that the code
// generator, the verifier, the interpreter and the disassembler all read.
//
// Every instruction is one fixed-size record of 12 bytes (little-endian in
// an image file):
//
//   byte   0      1      2..3       4..7         8..11
//        +------+------+----------+------------+------------+
//        |  op  |  a   |    b     |     c      |     d      |
//        +------+------+----------+------------+------------+
//          u8     u8      u16          i32          i32
//
// Fixed width keeps the verifier simple (a jump target is an index, never a
// byte offset into the middle of an instruction) and the dispatch loop fast.
// Fields an opcode does not use must be zero; the verifier checks that too.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "vm/io_lines.h"

namespace rs::vm {

/// One opcode per ROBOTSIM instruction, in the paper's order.
/// K = constants, P = points, V = variable slots, T = instruction index.
enum class Op : std::uint8_t {
  Move,     // b=n c=K        motors += K[c..c+n)                 (relative move)
  MoveTo,   // b=n c=K        motors := K[c..c+n)                 (absolute move)
  MoveP,    // b=P            motors := points[P]
  Goto,     // d=T            pc := T
  JmpIn,    // a=I b=S d=T    if input I is S: pc := T
  OutSig,   // a=O b=S        output O := S
  JmpVar,   // a=C b=V c=N d=T if V[b] C N: pc := T   (C: 0 '<', 1 '>', 2 '=')
  Gosub,    // d=T            push pc+1; pc := T
  Return,   //                pc := pop
  WaitFor,  // a=I b=S        wait until input I is S
  Add,      // b=V c=N        V[b] += N
  Reset,    //                robot and objects back to their start
  Window,   // c=K            camera shifted by K[c], K[c+1], K[c+2]
  View,     // c=K            camera rotated by K[c], K[c+1], K[c+2] degrees
  Delay,    // c=MS           clock += MS milliseconds
  HrdHome,  //                motors := 0
  SetSoft,  // b=n c=K        soft home := K[c..c+n)
  GoSoft,   //                motors := soft home
  Set,      // b=V c=N        V[b] := N
  End,      //                stop
  // After the paper (docs/language.md, "After the paper"): the tool moved
  // along a straight line, worked out from the robot's kinematics.
  MoveS,    // b=P            tool centre point along a line to points[P]
  Appro,    // c=L            tool centre point L length units along its approach axis
  Depart,   // c=L            tool centre point L length units back along its approach axis
};

inline constexpr std::size_t kOpCount = static_cast<std::size_t>(Op::Depart) + 1;

/// Operand format: which fields an opcode uses and what they mean. The
/// verifier checks and the disassembler prints by format, never by opcode.
enum class Format : std::uint8_t {
  None,          // no operands
  MotorVector,   // b = motor count, c = first constant
  Point,         // b = point index, a = 0 or kPointKeepsGripper
  Target,        // d = instruction index
  InputJump,     // a = input 1..kIoCount, b = 0 OFF / 1 ON, d = instruction index
  Output,        // a = output 1..kIoCount, b = 0 OFF / 1 ON
  Input,         // a = input 1..kIoCount, b = 0 OFF / 1 ON
  VarCompare,    // a = comparison, b = variable slot, c = value, d = index
  VarValue,      // b = variable slot, c = value
  Triple,        // c = first of three constants
  Millis,        // c = milliseconds, 0 .. kMaxDelayMillis
  Distance,      // c = length units, 1 .. kMaxToolDistance
};

/// Format::Point's `a`: the point leaves the gripper motor(s) as they are
/// when the move starts (a point written as a tool pose without GRIP,
/// docs/language.md), instead of moving them to its value.
inline constexpr std::uint8_t kPointKeepsGripper = 1;

/// What a format looks like in source: how many operands it takes and the
/// usage text of `robotsim help` and the compiler's arity messages.
struct FormatInfo {
  Format format;
  std::string_view name;  ///< as docs/bytecode.md names it
  std::uint8_t operands;  ///< written operands; a MotorVector takes one per motor instead
  std::string_view usage;  ///< after the mnemonic, e.g. " <input> ON|OFF <line>"
};

inline constexpr std::size_t kFormatCount = static_cast<std::size_t>(Format::Distance) + 1;

inline constexpr std::array<FormatInfo, kFormatCount> kFormats{{
    {Format::None, "None", 0, ""},
    {Format::MotorVector, "MotorVector", 0, " <value per motor>"},
    {Format::Point, "Point", 1, " <point>"},
    {Format::Target, "Target", 1, " <line>"},
    {Format::InputJump, "InputJump", 3, " <input> ON|OFF <line>"},
    {Format::Output, "Output", 2, " <output> ON|OFF"},
    {Format::Input, "Input", 2, " <input> ON|OFF"},
    {Format::VarCompare, "VarCompare", 4, " <variable> <|>|= <value> <line>"},
    {Format::VarValue, "VarValue", 2, " <variable> <value>"},
    {Format::Triple, "Triple", 3, " <x> <y> <z>"},
    {Format::Millis, "Millis", 1, " <seconds>"},
    {Format::Distance, "Distance", 1, " <length>"},
}};

constexpr const FormatInfo& info(Format f) { return kFormats[static_cast<std::size_t>(f)]; }

/// Flags: how an opcode affects control flow, the motors and the variables.
/// Every layer outside vm/ asks these (and the format), never an opcode by
/// name (docs/architecture.md, "Instruction facts"; the layers test checks).
enum OpFlag : std::uint16_t {
  kFallsThrough = 1 << 0,  // the next instruction may run after this one
                           // (for GOSUB: once the subroutine returns)
  kJumps = 1 << 1,         // d is a jump target
  kMovesMotors = 1 << 2,   // may change motor positions (a move, a homing, RESET)
  kRelative = 1 << 3,      // its motor values are offsets from where the motors are, not targets
  kWritesVariable = 1 << 4,  // writes variable slot b
  kUsesMachine = 1 << 5,   // acts on the machine: may fail, may take time
  kCalls = 1 << 6,         // pushes the return point and jumps to subroutine d (GOSUB)
  kReturns = 1 << 7,       // pops the return point and goes there (RETURN)
  kBranches = 1 << 8,      // jumps to d or falls through, on a condition
  kWaits = 1 << 9,         // its time is spent waiting (for an input or the clock), not moving
  kEnds = 1 << 10,         // stops the run (END)
  kStraight = 1 << 11,     // moves the tool along a straight line: needs the robot's kinematics
  kStraightBack = 1 << 12, // with a distance: back along the tool's approach axis (DEPART)
};

struct OpInfo {
  Op op;
  std::string_view name;  // upper-case mnemonic as written in programs
  Format format;
  std::uint16_t flags;
  std::string_view meaning;  // one line, for `robotsim help` and listings
  std::string_view detail;   // `robotsim help NAME`: what the paper leaves open, as robotsim decides it
  std::string_view example;  // one line of source
};

inline constexpr std::uint16_t kFT = kFallsThrough;

// The help texts of JMPIN and OUTSIG below number the lines 1..8.
static_assert(kIoCount == 8, "say the new number of lines in kOps' help texts");
inline constexpr std::uint16_t kMach = kUsesMachine;

inline constexpr std::array<OpInfo, kOpCount> kOps{{
    {Op::Move, "MOVE", Format::MotorVector, kFT | kMach | kMovesMotors | kRelative,
     "move every motor by a relative number of encoder units",
     "Values are encoder units, one per motor in the robot's order (E D C B A on the default Rhino SCARA). "
     "Each motor moves at its own speed; the instruction ends when the last one arrives.",
     "MOVE 100 -50 0 0 0"},
    {Op::MoveTo, "MOVETO", Format::MotorVector, kFT | kMach | kMovesMotors,
     "move every motor to an absolute encoder position",
     "Targets are absolute encoder positions; each must lie in its motor's range.", "MOVETO 0 200 -100 0 120"},
    {Op::MoveP, "MOVEP", Format::Point, kFT | kMach | kMovesMotors, "move every motor to a taught point",
     "The point is defined after the POINTS line of the same file.", "MOVEP PICK"},
    {Op::Goto, "GOTO", Format::Target, kJumps, "jump unconditionally",
     "The line is an instruction number (1 = first instruction) or a label.", "GOTO loop"},
    {Op::JmpIn, "JMPIN", Format::InputJump, kFT | kJumps | kBranches, "jump if an input is ON (or OFF)",
     "Reads input 1..8 now; jumps if it is in the given state, else continues.", "JMPIN 3 ON done"},
    {Op::OutSig, "OUTSIG", Format::Output, kFT | kMach, "switch an output ON or OFF",
     "Outputs are numbered 1..8 and start OFF.", "OUTSIG 1 ON"},
    {Op::JmpVar, "JMPVAR", Format::VarCompare, kFT | kJumps | kBranches,
     "jump if a variable compares true with a value",
     "Variables are 32-bit integers that start at 0; compares with <, > or =.", "JMPVAR N < 10 loop"},
    {Op::Gosub, "GOSUB", Format::Target, kFT | kJumps | kCalls, "call a subroutine",
     "Calls nest up to 64 deep; deeper is a runtime error.", "GOSUB pick"},
    {Op::Return, "RETURN", Format::None, kReturns, "return from a subroutine",
     "Returns to the instruction after the last GOSUB.", "RETURN"},
    {Op::WaitFor, "WAITFOR", Format::Input, kFT | kMach | kWaits, "wait until an input is ON (or OFF)",
     "Waits (in simulated time) until the input is in the state; a wait nothing can end is a deadlock error.",
     "WAITFOR 2 ON"},
    {Op::Add, "ADD", Format::VarValue, kFT | kWritesVariable, "add a value to a variable",
     "A negative value subtracts; overflowing 32 bits is a runtime error.", "ADD N -1"},
    {Op::Reset, "RESET", Format::None, kFT | kMach | kMovesMotors, "put the workcell back where it started",
     "Every motor goes back to where the run started, instantly; outputs and variables are kept.", "RESET"},
    {Op::Window, "WINDOW", Format::Triple, kFT | kMach, "shift the view of the workcell in x, y, z",
     "Shifts the view of the workcell by x, y, z (whole numbers).", "WINDOW 0 -100 0"},
    {Op::View, "VIEW", Format::Triple, kFT | kMach, "rotate the view of the workcell about x, y, z",
     "Rotates the view of the workcell by x, y, z degrees (whole numbers).", "VIEW 30 0 45"},
    {Op::Delay, "DELAY", Format::Millis, kFT | kMach | kWaits, "wait a number of seconds",
     "Seconds, with up to three decimals (milliseconds); at most one day.", "DELAY 0.25"},
    {Op::HrdHome, "HRDHOME", Format::None, kFT | kMach | kMovesMotors, "move every motor to encoder position 0",
     "Every motor moves to encoder position 0 at its speed.", "HRDHOME"},
    {Op::SetSoft, "SETSOFT", Format::MotorVector, kFT, "set the software home position",
     "One value per motor, each within its range; takes no time.", "SETSOFT 0 100 0 0 0"},
    {Op::GoSoft, "GOSOFT", Format::None, kFT | kMach | kMovesMotors,
     "move every motor to the software home position",
     "Moves to the SETSOFT position (all zeros before any SETSOFT).", "GOSOFT"},
    {Op::Set, "SET", Format::VarValue, kFT | kWritesVariable, "assign a value to a variable",
     "Assigns a whole number to a variable.", "SET N 0"},
    {Op::End, "END", Format::None, kEnds, "end the program",
     "Ends the run. Running past the last instruction ends it too.",
     "END"},
    {Op::MoveS, "MOVES", Format::Point, kFT | kMach | kMovesMotors | kStraight,
     "move the tool centre point along a straight line to a taught point",
     "After the paper (VAL's MOVES). The tool centre point runs along the straight line to the point's position "
     "while the orientation the arm controls turns evenly to the point's; the gripper keeps its opening. The arm "
     "stays in one configuration and within 0.1 length units of the line, plus its encoders' resolution. Each small "
     "move of the motors takes as long as its slowest motor needs at full speed. Needs the robot's kinematics "
     "(--cell); a path that leaves the reach, a motor's range or its configuration, or passes near a singular "
     "pose, is an error at the instruction (at compile time where the start is known).",
     "MOVES ABOVE"},
    {Op::Appro, "APPRO", Format::Distance, kFT | kMach | kMovesMotors | kStraight,
     "move the tool straight along its approach axis by a distance",
     "After the paper (VAL's APPRO). The tool centre point moves the whole number of length units along the "
     "tool's approach axis (z, towards what the gripper points at), keeping its orientation, as MOVES does.",
     "APPRO 50"},
    {Op::Depart, "DEPART", Format::Distance, kFT | kMach | kMovesMotors | kStraight | kStraightBack,
     "move the tool straight back along its approach axis by a distance",
     "After the paper (VAL's DEPART). The tool centre point moves the whole number of length units against the "
     "tool's approach axis (away from what the gripper points at), keeping its orientation, as MOVES does.",
     "DEPART 50"},
}};

// The tables are indexed by opcode and by format: keep them in enum order.
consteval bool tablesInOrder() {
  for (std::size_t i = 0; i < kOps.size(); ++i)
    if (static_cast<std::size_t>(kOps[i].op) != i) return false;
  for (std::size_t i = 0; i < kFormats.size(); ++i)
    if (static_cast<std::size_t>(kFormats[i].format) != i) return false;
  return true;
}
static_assert(tablesInOrder(), "kOps and kFormats must list their entries in enum order");

// The flags must agree with the formats: a relative opcode moves motors by a
// motor vector; only a VarValue writes a variable; every help text is there.
consteval bool flagsAgree() {
  for (const OpInfo& op : kOps) {
    if ((op.flags & kRelative) && (!(op.flags & kMovesMotors) || op.format != Format::MotorVector)) return false;
    if (((op.flags & kWritesVariable) != 0) != (op.format == Format::VarValue)) return false;
    if (((op.flags & kJumps) != 0) != (op.format == Format::Target || op.format == Format::InputJump ||
                                       op.format == Format::VarCompare))
      return false;
    if ((op.flags & kMovesMotors) && !(op.flags & kUsesMachine)) return false;
    if ((op.flags & kStraight) &&
        (!(op.flags & kMovesMotors) || (op.format != Format::Point && op.format != Format::Distance)))
      return false;
    if ((op.flags & kStraightBack) && (!(op.flags & kStraight) || op.format != Format::Distance)) return false;
    if (op.meaning.empty() || op.detail.empty() || op.example.empty()) return false;
  }
  return true;
}
static_assert(flagsAgree(), "an opcode's flags contradict its format, or it lacks a help text");

// The control-flow flags say one thing each: a call jumps to a subroutine
// by line and comes back (falls through); a branch is every other jump
// that may fall through; a return and an end neither fall through nor
// jump; a wait takes time on the machine without moving; a program that
// can call can return.
consteval bool controlFlagsAgree() {
  int calls = 0, returns = 0, ends = 0;
  for (const OpInfo& op : kOps) {
    const bool jumps = op.flags & kJumps, fallsThrough = op.flags & kFallsThrough;
    if ((op.flags & kCalls) && (!jumps || !fallsThrough || op.format != Format::Target)) return false;
    if (((op.flags & kBranches) != 0) != (jumps && fallsThrough && !(op.flags & kCalls))) return false;
    if ((op.flags & (kReturns | kEnds)) && (jumps || fallsThrough || op.format != Format::None)) return false;
    if ((op.flags & kReturns) && (op.flags & kEnds)) return false;
    if (!jumps && !fallsThrough && !(op.flags & (kReturns | kEnds))) return false;  // where would it go?
    if ((op.flags & kWaits) && (!(op.flags & kUsesMachine) || (op.flags & kMovesMotors))) return false;
    calls += (op.flags & kCalls) ? 1 : 0;
    returns += (op.flags & kReturns) ? 1 : 0;
    ends += (op.flags & kEnds) ? 1 : 0;
  }
  return (calls > 0) == (returns > 0) && ends > 0;
}
static_assert(controlFlagsAgree(), "an opcode's call, return, branch, wait or end flag contradicts its others");

constexpr const OpInfo& info(Op op) { return kOps[static_cast<std::size_t>(op)]; }
constexpr bool has(Op op, OpFlag flag) { return (info(op).flags & flag) != 0; }

/// Finds an opcode by mnemonic, ignoring case ("moveto", "MoveTo").
std::optional<Op> opByName(std::string_view name);

/// Labels, points and variables have at most this many characters (the
/// compiler and the image loader hold them to it).
inline constexpr std::size_t kMaxNameLength = 64;

/// True for a word no label, point or variable may be called, in any case:
/// every mnemonic, ON, OFF and POINTS.
bool isReservedWord(std::string_view word);

/// Comparisons of JMPVAR, in operand-a order.
enum class Compare : std::uint8_t { Less = 0, Greater = 1, Equal = 2 };
inline constexpr std::array<std::string_view, 3> kCompareSymbols{"<", ">", "="};

inline constexpr std::int32_t kMaxDelayMillis = 86'400'000;  // one day
inline constexpr std::int32_t kMaxToolDistance = 100'000;    // APPRO, DEPART: length units

/// One decoded instruction.
struct Instr {
  Op op = Op::End;
  std::uint8_t a = 0;
  std::uint16_t b = 0;
  std::int32_t c = 0;
  std::int32_t d = 0;
  bool operator==(const Instr&) const = default;
};

inline constexpr std::size_t kInstrBytes = 12;

}  // namespace rs::vm
