// `robotsim help WORD` for a word that is no instruction: the suggestion
// (tools/cli/lib/help.h), and the message with the word made printable.
#include <catch2/catch.hpp>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/help.h"

using rs::cli::instructionsLike;
using rs::testing::runCli;

namespace {

std::vector<std::string> likeNames(std::string_view word) {
  std::vector<std::string> out;
  for (const std::string_view n : instructionsLike(word)) out.emplace_back(n);
  return out;
}

}  // namespace

TEST_CASE("help WAIT suggests WAITFOR, the instruction that holds the word", "[cli][help]") {
  const auto r = runCli({"help", "WAIT"});
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "robotsim: error: no instruction named 'WAIT'; did you mean 'WAITFOR'? (robotsim help lists them)\n");
  CHECK(runCli({"help", "wait"}).err.find("did you mean 'WAITFOR'?") != std::string::npos);
}

TEST_CASE("help suggests the names that hold the word first, then the nearest by a typo", "[cli][help]") {
  CHECK(likeNames("MOVTO") == std::vector<std::string>{"MOVETO"});      // one letter left out
  CHECK(likeNames("gosb") == std::vector<std::string>{"GOSUB"});        // any case
  CHECK(likeNames("WAITFORR") == std::vector<std::string>{"WAITFOR"});  // one too many
  CHECK(likeNames("SOFT") == std::vector<std::string>{"SETSOFT", "GOSOFT"});
  CHECK(likeNames("JMP") == std::vector<std::string>{"JMPIN", "JMPVAR"});
  CHECK(likeNames("HOME") == std::vector<std::string>{"HRDHOME"});  // not MOVE, two letters away
  CHECK(likeNames("MOV") == std::vector<std::string>{"MOVE", "MOVETO", "MOVEP"});
  CHECK(likeNames("SIG") == std::vector<std::string>{"OUTSIG"});
  CHECK(runCli({"help", "JMP"}).err.find("did you mean 'JMPIN' or 'JMPVAR'?") != std::string::npos);
  // Nothing near: the message as before; two letters hold too little to guess from.
  CHECK(likeNames("XYZZY").empty());
  CHECK(likeNames("NOPE") == std::vector<std::string>{"MOVE"});  // two letters off, as the compiler suggests
  CHECK(likeNames("MO").empty());
  CHECK(runCli({"help", "XYZZY"}).err == "robotsim: error: no instruction named 'XYZZY' (robotsim help lists them)\n");
}

TEST_CASE("help prints an unknown word's control bytes escaped and a long one cut", "[cli][help]") {
  const auto r = runCli({"help", "WA\x1b[2JIT"});
  CHECK(r.code == 2);
  CHECK(r.err.find('\x1b') == std::string::npos);
  const auto longer = runCli({"help", std::string(100000, 'W')});
  CHECK(longer.code == 2);
  CHECK(longer.err.size() < 200);
}
