// The stimuli file parser and the command-line form: exact microseconds,
// every bad line reported with its position, no crash on any bytes.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "compiler/stimuli/stimuli.h"

namespace {

using rs::stimuli::InputChange;
using rs::stimuli::parseStimuli;
using rs::stimuli::parseStimulusArg;
using rs::stimuli::ReactiveRule;
using rs::diag::Diagnostic;

// What a stimuli error must say, compared with the diagnostic the parser gave.
struct StimuliError {
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string message;
};

bool operator==(const Diagnostic& d, const StimuliError& e) {
  return d.file == e.file && d.pos.line == e.line && d.pos.col == e.column && d.message == e.message &&
         d.severity == rs::diag::Severity::Error;
}

// The one error of a one-line file.
Diagnostic onlyError(std::string_view text) {
  const auto result = parseStimuli(text, "s.stim");
  REQUIRE(result.failures().size() == 1);
  return result.failure();
}

rs::vm::Micros timeOf(std::string_view seconds) {
  const auto result = parseStimuli("at " + std::string(seconds) + " input 1 on", "s.stim");
  REQUIRE(result.ok());
  REQUIRE(result->changes.size() == 1);
  return result->changes[0].at;
}

}  // namespace

TEST_CASE("a good stimuli file becomes the model", "[stimuli]") {
  const auto result = parseStimuli(
      "; conveyor cell\n"
      "\n"
      "at 1.5 input 3 on\n"
      "AT 2 Input 3 OFF   ; part taken\r\n"
      "  when output 1 on then input 2 on after 0.5\n"
      "when OUTPUT 4 off THEN input 8 off\n"
      "\tat 0 input 1 on",  // last line without a newline
      "cell.stim");
  REQUIRE(result.ok());
  CHECK(result->changes ==
        std::vector<InputChange>{{1'500'000, 3, true, 3}, {2'000'000, 3, false, 4}, {0, 1, true, 7}});  // their lines
  CHECK(result->rules ==
        std::vector<ReactiveRule>{{1, true, 2, true, 500'000, 5}, {4, false, 8, false, 0, 6}});  // lines 5 and 6
}

TEST_CASE("an empty file or one of comments is an empty model", "[stimuli]") {
  CHECK(parseStimuli("", "e").ok());
  const auto result = parseStimuli("; nothing\n   \n;; at 1 input 9 on\n", "e");
  REQUIRE(result.ok());
  CHECK(*result == rs::stimuli::Stimuli{});
}

TEST_CASE("seconds convert exactly to microseconds", "[stimuli]") {
  CHECK(timeOf("0") == 0);
  CHECK(timeOf("1.5") == 1'500'000);
  CHECK(timeOf("4.35") == 4'350'000);  // 4.35 * 1e6 in double is 4349999.99...
  CHECK(timeOf("0.000001") == 1);
  CHECK(timeOf("0.1") == 100'000);
  CHECK(timeOf("007.250") == 7'250'000);
  CHECK(timeOf("1000000") == 1'000'000'000'000);
  CHECK(timeOf("1000000.000000") == 1'000'000'000'000);
  CHECK(timeOf("999999.999999") == 999'999'999'999);
}

TEST_CASE("every bad line is reported with its line, column and what was expected", "[stimuli]") {
  const auto result = parseStimuli(
      "at 1.5 input 3 on\n"                                 // 1 good
      "at 1.5.2 input 3 on\n"                               // 2
      "at 1.5 inptu 3 on\n"                                 // 3
      "at 1.5\n"                                            // 4
      "at 2 input 9 on\n"                                   // 5
      "at 2 input x on\n"                                   // 6
      "at 2 input 3 maybe\n"                                // 7
      "at -1 input 3 on\n"                                  // 8
      "at 1.1234567 input 3 on\n"                           // 9
      "at 99999999999999999999999 input 1 on\n"             // 10
      "at 1000000.000001 input 1 on\n"                      // 11
      "set input 3 on\n"                                    // 12
      "at 1 input 3 on now\n"                               // 13
      "when output 0 on then input 2 on\n"                  // 14
      "when output 1 on input 2 on\n"                       // 15
      "when output 1 on then input 2 on later 0.5\n"        // 16
      "when output 1 on then input 2 on after\n"            // 17
      "when output 1 on then input 2 on after 0.5 extra\n"  // 18
      "when output 1 on then input 2 on after 0.5 ; ok\n"   // 19 good
      "at\n"                                                // 20
      "when\n"                                              // 21
      "at 3 input 1 on ; ok\n",                             // 22 good
      "cell.stim");
  const std::vector<StimuliError> expected{
      {"cell.stim", 2, 4, "bad time '1.5.2': expected seconds such as 2 or 1.5"},
      {"cell.stim", 3, 8, "expected 'input' after the time, got 'inptu'"},
      {"cell.stim", 4, 7, "expected 'input' after the time"},
      {"cell.stim", 5, 12, "input number must be 1..8, got 9"},
      {"cell.stim", 6, 12, "expected an input number 1..8, got 'x'"},
      {"cell.stim", 7, 14, "expected 'on' or 'off' after the input number, got 'maybe'"},
      {"cell.stim", 8, 4, "time must not be negative, got '-1'"},
      {"cell.stim", 9, 4, "time '1.1234567' has more than 6 decimals"},
      {"cell.stim", 10, 4, "time '99999999999999999999999' is past the limit of 1000000 seconds"},
      {"cell.stim", 11, 4, "time '1000000.000001' is past the limit of 1000000 seconds"},
      {"cell.stim", 12, 1, "expected 'at' or 'when' at the start of a line, got 'set'"},
      {"cell.stim", 13, 17, "unexpected 'now' after the end of the statement"},
      {"cell.stim", 14, 13, "output number must be 1..8, got 0"},
      {"cell.stim", 15, 18, "expected 'then' after the output state, got 'input'"},
      {"cell.stim", 16, 34, "expected 'after' or the end of the line, got 'later'"},
      {"cell.stim", 17, 39, "expected a delay in seconds after 'after'"},
      {"cell.stim", 18, 44, "unexpected 'extra' after the end of the statement"},
      {"cell.stim", 20, 3, "expected a time in seconds after 'at'"},
      {"cell.stim", 21, 5, "expected 'output' after 'when'"},
  };
  REQUIRE_FALSE(result.ok());
  REQUIRE(result.failures().size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("error " << i);
    CHECK(result.failures()[i] == expected[i]);
  }
  // A file with a bad line gives no model (nothing runs on half a file);
  // its good lines alone give theirs.
  const auto good = parseStimuli(
      "at 1.5 input 3 on\nwhen output 1 on then input 2 on after 0.5 ; ok\nat 3 input 1 on ; ok\n", "cell.stim");
  REQUIRE(good.ok());
  CHECK(good->changes == std::vector<InputChange>{{1'500'000, 3, true, 1}, {3'000'000, 1, true, 3}});
  CHECK(good->rules == std::vector<ReactiveRule>{{1, true, 2, true, 500'000, 2}});  // line 2
}

TEST_CASE("more bad rules", "[stimuli]") {
  CHECK(onlyError("when output 1 on then output 2 on") ==
        StimuliError{"s.stim", 1, 23, "expected 'input' after 'then', got 'output'"});
  CHECK(onlyError("when output 1 on then input 2") ==
        StimuliError{"s.stim", 1, 30, "expected 'on' or 'off' after the input number"});
  CHECK(
      onlyError("when output 1 high then input 2 on") ==
      StimuliError{"s.stim", 1, 15, "expected 'on' or 'off' after the output number, got 'high'"});
  CHECK(onlyError("when output 1 on then input 2 on after -0.5") ==
        StimuliError{"s.stim", 1, 40, "time must not be negative, got '-0.5'"});
  CHECK(onlyError("at 1 input 99999999999999999999999 on") ==
        StimuliError{"s.stim", 1, 12, "input number must be 1..8, got 99999999999999999999999"});
  CHECK(onlyError("at 1. input 1 on").message ==
        "bad time '1.': expected seconds such as 2 or 1.5");
  CHECK(onlyError("at .5 input 1 on").message ==
        "bad time '.5': expected seconds such as 2 or 1.5");
  CHECK(onlyError("at 1e3 input 1 on").message ==
        "bad time '1e3': expected seconds such as 2 or 1.5");
}

TEST_CASE("strange bytes get an error, never a crash", "[stimuli]") {
  using namespace std::string_literals;
  CHECK(onlyError("at \0 input 1 on"s) ==
        StimuliError{"s.stim", 1, 4, "bad time '\\x00': expected seconds such as 2 or 1.5"});
  CHECK(onlyError("\xff\xfe at") ==
        StimuliError{"s.stim", 1, 1,
                     "expected 'at' or 'when' at the start of a line, got '\\xff\\xfe'"});
  CHECK(onlyError("at 1 input 1 \xc3\xb6n").message ==
        "expected 'on' or 'off' after the input number, got '\\xc3\\xb6n'");

  SECTION("a huge line is cut short in the message") {
    const auto error = onlyError("at 1 input 1 " + std::string(1'000'000, 'x'));
    CHECK(error.pos.col == 14);
    CHECK(error.message ==
          "expected 'on' or 'off' after the input number, got '" + std::string(40, 'x') + "...'");
  }
  SECTION("random bytes") {
    std::mt19937 random(12345);  // seeded: the same bytes on every run
    std::uniform_int_distribution<int> byte(0, 255);
    const std::string alphabet = "at when output input then after on off 0123456789.;-\n\t\r ";
    for (int round = 0; round < 2000; ++round) {
      std::string text;
      for (int i = 0; i < 64; ++i) {
        const int b = byte(random);
        text += b < 128 ? alphabet[static_cast<std::size_t>(b) % alphabet.size()]
                        : static_cast<char>(b);
      }
      const auto result = parseStimuli(text, "fuzz");
      for (const auto& e : result.failures()) {
        CHECK(e.pos.line >= 1);
        CHECK(e.pos.col >= 1);
        CHECK_FALSE(e.message.empty());
      }
    }
  }
}

TEST_CASE("the command-line form N=ON@T", "[stimuli][cli]") {
  CHECK(parseStimulusArg("3=ON@1.5").value() == InputChange{1'500'000, 3, true});
  CHECK(parseStimulusArg("2=off").value() == InputChange{0, 2, false});
  CHECK(parseStimulusArg("8=On@0.000001").value() == InputChange{1, 8, true});
  CHECK(parseStimulusArg("3=ON@1.5").failures().empty());
}

TEST_CASE("bad command-line stimuli say where and what", "[stimuli][cli]") {
  const auto errorOf = [](std::string_view arg) {
    const auto parsed = parseStimulusArg(arg, "--input");
    REQUIRE_FALSE(parsed.ok());
    REQUIRE(parsed.failures().size() == 1);
    return parsed.failure();
  };
  CHECK(errorOf("9=ON") == StimuliError{"--input", 1, 1, "input number must be 1..8, got 9"});
  CHECK(errorOf("3=MAYBE@1") ==
        StimuliError{"--input", 1, 3, "expected ON or OFF after '=', got 'MAYBE'"});
  CHECK(errorOf("3=ON@") == StimuliError{"--input", 1, 6, "expected a time in seconds after '@'"});
  CHECK(errorOf("3=ON@1.5.2") ==
        StimuliError{"--input", 1, 6, "bad time '1.5.2': expected seconds such as 2 or 1.5"});
  CHECK(errorOf("3") ==
        StimuliError{
            "--input", 1, 2,
            "expected '=' after the input number (the form is N=ON@T or N=OFF@T, e.g. 3=ON@1.5)"});
  CHECK(errorOf("=ON") == StimuliError{"--input", 1, 1,
                                       "expected an input number 1..8 before '=' (the form is "
                                       "N=ON@T or N=OFF@T, e.g. 3=ON@1.5)"});
  CHECK(errorOf("3=@1").pos.col == 3);
  CHECK(errorOf("").pos.col == 1);
}

TEST_CASE("an unreadable stimuli file is one error", "[stimuli]") {
  const auto missing = rs::stimuli::loadStimuliFile("/nonexistent/dir/cell.stim");
  REQUIRE(missing.failures().size() == 1);
  CHECK(missing.failure() ==
        StimuliError{"/nonexistent/dir/cell.stim", 0, 0, "cannot read the stimuli file: No such file or directory"});
  const auto dir = rs::stimuli::loadStimuliFile("/");
  REQUIRE(dir.failures().size() == 1);
  CHECK(dir.failure().message == "cannot read the stimuli file: is a directory");
}
