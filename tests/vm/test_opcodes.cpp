// opByName: the mnemonic lookup every instruction goes through, in any
// letter case, and nothing that merely resembles a mnemonic.
#include <catch2/catch.hpp>

#include <string>

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
