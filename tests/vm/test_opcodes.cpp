// opByName: the mnemonic lookup every instruction goes through, in any
// letter case, and nothing that merely resembles a mnemonic.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "vm/opcodes.h"

TEST_CASE("opByName finds every mnemonic in any letter case", "[vm][opcodes]") {
  for (const rs::vm::OpInfo& op : rs::vm::kOps) {
    std::string lower(op.name), mixed(op.name);
    for (std::size_t i = 0; i < lower.size(); ++i) {
      lower[i] = static_cast<char>(lower[i] - 'A' + 'a');
      if (i % 2) mixed[i] = lower[i];
    }
    INFO(op.name);
    CHECK(rs::vm::opByName(op.name) == op.op);
    CHECK(rs::vm::opByName(lower) == op.op);
    CHECK(rs::vm::opByName(mixed) == op.op);
  }
}

TEST_CASE("opByName refuses near misses", "[vm][opcodes]") {
  using namespace std::string_literals;
  for (const std::string& name : {""s, "MOV"s, "MOVEX"s, "MOVE "s, " MOVE"s, "MOVE\0"s, "MOVETOMOVETO"s,
                                  "GOSUBGOSUB"s, "END_"s, "EN"s, "\xC3\x89ND"s, "POINTS"s, "ON"s})
    CHECK_FALSE(rs::vm::opByName(name).has_value());
}

// docs/bytecode.md's opcode table is written by hand for readers; this
// keeps it true to kOps: every row's number, hex, mnemonic, format and
// flag letters, and no row more or less.
TEST_CASE("docs/bytecode.md's opcode table agrees with kOps", "[vm][opcodes][docs]") {
  std::ifstream in(std::string(ROBOTSIM_SOURCE_DIR) + "/docs/bytecode.md");
  REQUIRE(in);
  const auto cells = [](const std::string& row) {
    std::vector<std::string> out;
    std::istringstream s(row.substr(1));
    for (std::string cell; std::getline(s, cell, '|');) {
      const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
      out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    }
    return out;
  };
  bool inTable = false;
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| Op | Hex | Mnemonic | Format | Flags |", 0) == 0) inTable = true;
    if (!inTable || line.rfind("| ", 0) != 0 || line[2] < '0' || line[2] > '9') {
      if (inTable && rows > 0 && line.empty()) break;
      continue;
    }
    const std::vector<std::string> c = cells(line);
    REQUIRE(c.size() >= 5);
    INFO(line);
    REQUIRE(rows < rs::vm::kOps.size());
    const rs::vm::OpInfo& op = rs::vm::kOps[rows];
    CHECK(c[0] == std::to_string(rows));
    CHECK(c[1] == fmt::format("{:02X}", rows));
    CHECK(c[2] == op.name);
    CHECK(c[3] == rs::vm::info(op.format).name);
    std::string flags;
    const std::pair<rs::vm::OpFlag, char> letters[] = {
        {rs::vm::kFallsThrough, 'F'}, {rs::vm::kJumps, 'J'},          {rs::vm::kMovesMotors, 'M'},
        {rs::vm::kRelative, 'R'},     {rs::vm::kWritesVariable, 'W'}, {rs::vm::kUsesMachine, 'X'},
        {rs::vm::kCalls, 'C'},        {rs::vm::kReturns, 'P'},        {rs::vm::kBranches, 'B'},
        {rs::vm::kWaits, 'A'},        {rs::vm::kEnds, 'E'},           {rs::vm::kStraight, 'L'},
        {rs::vm::kStraightBack, 'K'}};
    for (const auto& [flag, letter] : letters)
      if (rs::vm::has(op.op, flag)) flags += flags.empty() ? std::string(1, letter) : std::string(" ") + letter;
    CHECK(c[4] == (flags.empty() ? "–" : flags));
    ++rows;
  }
  CHECK(rows == rs::vm::kOps.size());
}
