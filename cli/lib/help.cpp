#include "cli/lib/help.h"

#include <array>
#include <fmt/format.h>

#include "compiler/ast_builder.h"
#include "vm/opcodes.h"

namespace rs::cli {

namespace {

struct Detail {
  std::string_view text;     // what the paper leaves open, as robotsim decides it
  std::string_view example;
};

// In opcode order; the static_assert below keeps it in step with kOps.
constexpr std::array<Detail, vm::kOpCount> kDetails{{
    {"Values are encoder units, one per motor in the robot's order (E D C B A on the default Rhino SCARA). "
     "Each motor moves at its own speed; the instruction ends when the last one arrives.",
     "MOVE 100 -50 0 0 0"},
    {"Targets are absolute encoder positions; each must lie in its motor's range.", "MOVETO 0 200 -100 0 120"},
    {"The point is defined after the POINTS line of the same file.", "MOVEP PICK"},
    {"The line is an instruction number (1 = first instruction) or a label.", "GOTO loop"},
    {"Reads input 1..8 now; jumps if it is in the given state, else continues.", "JMPIN 3 ON done"},
    {"Outputs are numbered 1..8 and start OFF.", "OUTSIG 1 ON"},
    {"Variables are 32-bit integers that start at 0; compares with <, > or =.", "JMPVAR N < 10 loop"},
    {"Calls nest up to 64 deep; deeper is a runtime error.", "GOSUB pick"},
    {"Returns to the instruction after the last GOSUB.", "RETURN"},
    {"Waits (in simulated time) until the input is in the state; a wait nothing can end is a deadlock error.",
     "WAITFOR 2 ON"},
    {"A negative value subtracts; overflowing 32 bits is a runtime error.", "ADD N -1"},
    {"Every motor goes back to where the run started, instantly; outputs and variables are kept.", "RESET"},
    {"Shifts the view of the workcell by x, y, z (whole numbers).", "WINDOW 0 -100 0"},
    {"Rotates the view of the workcell by x, y, z degrees (whole numbers).", "VIEW 30 0 45"},
    {"Seconds, with up to three decimals (milliseconds); at most one day.", "DELAY 0.25"},
    {"Every motor moves to encoder position 0 at its speed.", "HRDHOME"},
    {"One value per motor, each within its range; takes no time.", "SETSOFT 0 100 0 0 0"},
    {"Moves to the SETSOFT position (all zeros before any SETSOFT).", "GOSOFT"},
    {"Assigns a whole number to a variable.", "SET N 0"},
    {"Ends the run. Running past the last instruction ends it too.", "END"},
}};

std::string usageLine(const vm::OpInfo& op) {
  return fmt::format("{}{}", op.name, compiler::operandUsage(op.format));
}

}  // namespace

std::string instructionSummary() {
  std::string out = "ROBOTSIM instructions (robotsim help INSTRUCTION for details):\n";
  for (const vm::OpInfo& op : vm::kOps) out += fmt::format("  {:<44} {}\n", usageLine(op), op.meaning);
  return out;
}

std::optional<std::string> instructionHelp(std::string_view name) {
  const auto op = vm::opByName(name);
  if (!op) return std::nullopt;
  const vm::OpInfo& info = vm::info(*op);
  const Detail& d = kDetails[static_cast<std::size_t>(*op)];
  return fmt::format("{}\n  {}.\n  {}\nExample:\n  {}\n", usageLine(info), info.meaning, d.text, d.example);
}

}  // namespace rs::cli
