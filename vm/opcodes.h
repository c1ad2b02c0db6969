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
};

inline constexpr std::size_t kOpCount = static_cast<std::size_t>(Op::End) + 1;

/// Operand format: which fields an opcode uses and what they mean. The
/// verifier checks and the disassembler prints by format, never by opcode.
enum class Format : std::uint8_t {
  None,          // no operands
  MotorVector,   // b = motor count, c = first constant
  Point,         // b = point index
  Target,        // d = instruction index
  InputJump,     // a = input 1..8, b = 0 OFF / 1 ON, d = instruction index
  Output,        // a = output 1..8, b = 0 OFF / 1 ON
  Input,         // a = input 1..8, b = 0 OFF / 1 ON
  VarCompare,    // a = comparison, b = variable slot, c = value, d = index
  VarValue,      // b = variable slot, c = value
  Triple,        // c = first of three constants
  Millis,        // c = milliseconds, 0 .. kMaxDelayMillis
};

/// Flags: how an opcode affects control flow.
enum OpFlag : std::uint8_t {
  kFallsThrough = 1 << 0,  // the next instruction may run after this one
                           // (for GOSUB: once the subroutine returns)
  kJumps = 1 << 1,         // d is a jump target
};

struct OpInfo {
  Op op;
  std::string_view name;  // upper-case mnemonic as written in programs
  Format format;
  std::uint8_t flags;
  std::string_view meaning;  // one line, for `robotsim help` and listings
};

inline constexpr std::uint8_t kFT = kFallsThrough;

inline constexpr std::array<OpInfo, kOpCount> kOps{{
    {Op::Move, "MOVE", Format::MotorVector, kFT, "move every motor by a relative number of encoder units"},
    {Op::MoveTo, "MOVETO", Format::MotorVector, kFT, "move every motor to an absolute encoder position"},
    {Op::MoveP, "MOVEP", Format::Point, kFT, "move every motor to a taught point"},
    {Op::Goto, "GOTO", Format::Target, kJumps, "jump unconditionally"},
    {Op::JmpIn, "JMPIN", Format::InputJump, kFT | kJumps, "jump if an input is ON (or OFF)"},
    {Op::OutSig, "OUTSIG", Format::Output, kFT, "switch an output ON or OFF"},
    {Op::JmpVar, "JMPVAR", Format::VarCompare, kFT | kJumps, "jump if a variable compares true with a value"},
    {Op::Gosub, "GOSUB", Format::Target, kFT | kJumps, "call a subroutine"},
    {Op::Return, "RETURN", Format::None, 0, "return from a subroutine"},
    {Op::WaitFor, "WAITFOR", Format::Input, kFT, "wait until an input is ON (or OFF)"},
    {Op::Add, "ADD", Format::VarValue, kFT, "add a value to a variable"},
    {Op::Reset, "RESET", Format::None, kFT, "put the workcell back where it started"},
    {Op::Window, "WINDOW", Format::Triple, kFT, "shift the view of the workcell in x, y, z"},
    {Op::View, "VIEW", Format::Triple, kFT, "rotate the view of the workcell about x, y, z"},
    {Op::Delay, "DELAY", Format::Millis, kFT, "wait a number of seconds"},
    {Op::HrdHome, "HRDHOME", Format::None, kFT, "move every motor to encoder position 0"},
    {Op::SetSoft, "SETSOFT", Format::MotorVector, kFT, "set the software home position"},
    {Op::GoSoft, "GOSOFT", Format::None, kFT, "move every motor to the software home position"},
    {Op::Set, "SET", Format::VarValue, kFT, "assign a value to a variable"},
    {Op::End, "END", Format::None, 0, "end the program"},
}};

// The table is indexed by opcode: keep it in enum order.
consteval bool opTableInOrder() {
  for (std::size_t i = 0; i < kOps.size(); ++i)
    if (static_cast<std::size_t>(kOps[i].op) != i) return false;
  return true;
}
static_assert(opTableInOrder(), "kOps must list opcodes in enum order");

constexpr const OpInfo& info(Op op) { return kOps[static_cast<std::size_t>(op)]; }

/// Finds an opcode by mnemonic, ignoring case ("moveto", "MoveTo").
std::optional<Op> opByName(std::string_view name);

/// Comparisons of JMPVAR, in operand-a order.
enum class Compare : std::uint8_t { Less = 0, Greater = 1, Equal = 2 };
inline constexpr std::array<std::string_view, 3> kCompareSymbols{"<", ">", "="};

inline constexpr int kIoCount = 8;                        // inputs and outputs 1..8
inline constexpr std::int32_t kMaxDelayMillis = 86'400'000;  // one day

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
