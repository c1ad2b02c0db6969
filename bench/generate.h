// Deterministic generators for the benchmark inputs: ROBOTSIM programs of a
// given size (every instruction kind, labels, comments, a POINTS section)
// and Lua files of a given line count. No randomness: the same arguments
// give the same bytes on every run and machine.
#pragma once

#include <cstddef>
#include <string>

namespace rs::bench {

struct GeneratedProgram {
  std::string text;
  std::size_t instructions = 0;
  std::size_t lines = 0;
};

/// A program of exactly `instructions` instructions for the default robot
/// (the Rhino SCARA's five motors). It compiles without errors and runs to
/// END in simulation with no stimuli (every input stays OFF): blocks of a
/// counted loop, motion, I/O handshakes and a subroutine call, then the
/// POINTS section. `instructions` must be at least 1.
GeneratedProgram robotProgram(std::size_t instructions);

/// The largest such program with at most `lines` lines, padded with comment
/// lines to exactly `lines`.
GeneratedProgram robotProgramOfLines(std::size_t lines);

/// A program of exactly `lines` lines, each with one or two compile errors
/// of the kinds people make (an unknown instruction, a bad operand, a stray
/// character, a value out of range, an undefined label, a wrong operand
/// count), and no line without one; `errors` is how many the compiler
/// reports.
struct ErrorProgram {
  std::string text;
  std::size_t lines = 0;
  std::size_t errors = 0;
};
ErrorProgram errorProgram(std::size_t lines);

/// One line of `errors` * 100 + 4 bytes: END, then `errors` stray
/// characters ('@', and '+' without digits), each padded to 100 bytes.
ErrorProgram oneLineOfStrayCharacters(std::size_t errors);

/// One line of `bytes` bytes or a little more: MOVE and " x" words; the
/// lexer reports the 64th operand and skips the rest of the line, so the
/// compiler reports 64 errors.
ErrorProgram oneLineOfWords(std::size_t bytes);

/// A Lua chunk of exactly `lines` lines of simple statements (globals and a
/// table, so no limit on locals applies), for `luac5.4 -p`.
std::string luaChunk(std::size_t lines);

/// The Lua counterpart of the VM dispatch benchmark: a local counted to
/// `iterations` in a while loop.
std::string luaCountedLoop(long iterations);

}  // namespace rs::bench
