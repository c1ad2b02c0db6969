// The programs and checks the CLI tests share (tests/cli/test_cli*.cpp):
// a good program, one that fails at run time, one that does not compile,
// and what makes printed text safe and JSON parseable.
#pragma once

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <string>

#include "diag/source_file.h"

namespace rs::testing {

inline constexpr const char* kGood =
    "; a good program\n"
    "SET N 0\n"
    "loop: ADD N 1\n"
    "MOVE 100 0 0 0 0\n"
    "JMPVAR N < 3 loop\n"
    "OUTSIG 2 ON\n"
    "END\n";
// Six instructions. Final state: E=300 after three 0.25 s moves, N=3,
// output 2 ON, 1 + 3 * 3 + 2 = 12 instructions executed.

inline constexpr const char* kRuntimeError =
    "SET N 1\n"
    "  MOVE 600 0 0 0 0\n"
    "  MOVE 600 0 0 0 0\n"
    "END\n";

inline constexpr const char* kBadProgram = "END\nGOTO 9\n";

// True if `s` is valid UTF-8 and has no control characters except newline
// and tab: safe to print on a terminal.
inline bool cleanText(const std::string& s) {
  if (rs::diag::findInvalidUtf8(s).found) return false;
  for (char c : s)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7F) return false;
  return true;
}

inline nlohmann::json parseJson(const std::string& text) {
  INFO(text);
  REQUIRE(nlohmann::json::accept(text));
  return nlohmann::json::parse(text);
}

}  // namespace rs::testing
