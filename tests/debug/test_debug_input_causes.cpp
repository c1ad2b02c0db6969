// What drives an input, in the debugger (issue 35): `set input` on an input
// a WIRE drives is refused in both consoles and the adapter, with the same
// words, and `print in N`, `print io`, a watch, the adapter's Inputs scope,
// its evaluate and its data breakpoints say what set the input last and
// when, in the trace's words (runtime/cell/input_cause.h).
//
// The expected values, by hand: on stdlib/workcells/adept-cell.rsd the
// beam `eye` is wired to input 1 on line 32 (`WIRE eye TO IN 1`);
// examples/adept_production.rsp's first block breaks it at 1.1 s (worked
// out at the top of test_debug_devices.cpp), when its WAITFOR 1 ON (the
// third step) ends, with output 1 ON (its OUTSIG, the second step).
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "tests/debug/cell_debug_util.h"
#include "tests/debug/dap_test_util.h"
#include "tests/debug/debug_test_util.h"
#include "tools/debug/console.h"
#include "tools/debug/debug_session.h"

namespace {

using rs::debug::DebugSession;

std::string console(DebugSession& s, const std::string& commands) {
  std::ostringstream out;
  rs::debug::Console c(s, nullptr, out);
  std::istringstream lines(commands);
  for (std::string line; std::getline(lines, line);) c.execute(line);
  return out.str();
}

const std::string kEyeRefusal =
    "input 1 is wired from sensor eye (line 32 of adept-cell): the sensor turns it as what it sees comes and goes; "
    "to set it by hand, remove the WIRE";

}  // namespace

TEST_CASE("debug: set input on a wired input is refused, saying what drives it", "[debug][input-causes]") {
  DebugSession s(debugtest::specOnCell("adept_production.rsp", "adept-cell"));
  CHECK(console(s, "set input 1 on\n") == "error: " + kEyeRefusal + "\n");
  CHECK(s.setInput(1, true) == kEyeRefusal);
  // An input no wire drives is set as before.
  CHECK(console(s, "set input 2 on\n") == "input 2 is on from step 0 (clock 0.000 s) on\n");
}

TEST_CASE("debug: print in N and print io say what set an input last and when", "[debug][input-causes]") {
  DebugSession s(debugtest::specOnCell("adept_production.rsp", "adept-cell"));
  // Nothing has changed input 1 yet: its value alone.
  CHECK(console(s, "print in 1\n") == "in 1 = 0\n");
  console(s, "break sensor eye on\ncontinue\n");
  REQUIRE(s.view().clock == 1'100'000);
  CHECK(console(s, "print in 1\n") == "in 1 = 1 (since 1.100 s: wire from sensor eye)\n");
  CHECK(console(s, "print io\n") ==
        "inputs  1-8: 1 0 0 0 0 0 0 0\noutputs 1-8: 1 0 0 0 0 0 0 0\ninput 1 ON since 1.100 s: wire from sensor eye\n");
  // Going back to the start forgets it; forwards again, the same.
  s.reverseStep(s.view().steps);
  CHECK(console(s, "print in 1\n") == "in 1 = 0\n");
  s.gotoTime(1'100'000);
  CHECK(console(s, "print in 1\n") == "in 1 = 1 (since 1.100 s: wire from sensor eye)\n");
}

TEST_CASE("debug: a watch on an input and a break when on one say what changed it", "[debug][input-causes]") {
  DebugSession s(debugtest::specOnCell("adept_production.rsp", "adept-cell"));
  CHECK(console(s, "watch in 1\n") == "watch 1: in 1 (now 0)\n");
  std::string out = console(s, "continue\n");
  CHECK(out.find("in 1 changed from 0 to 1 (since 1.100 s: wire from sensor eye)") != std::string::npos);
  DebugSession t(debugtest::specOnCell("adept_production.rsp", "adept-cell"));
  out = console(t, "break when input 1 on\ncontinue\n");
  CHECK(out.find("): input 1 ON since 1.100 s: wire from sensor eye\n") != std::string::npos);
}

// A program with no cell: input 3 by a stimulus of the stimuli's line 4
// at 0.5 s, input 4 by one of line 2 at 0 s (applied as the machine is
// made, before the first step), input 5 by the debugger.
TEST_CASE("debug: the causes of stimuli, of the start and of set input", "[debug][input-causes]") {
  rs::stimuli::Stimuli stimuli;
  stimuli.changes.push_back({500'000, 3, true, 4});
  stimuli.changes.push_back({0, 4, true, 2});
  DebugSession s(debugtest::specOf("        WAITFOR 3 ON\n        DELAY 1\n        END\n", stimuli));
  CHECK(console(s, "print in 4\n") == "in 4 = 1 (since 0.000 s: stimulus, line 2)\n");
  console(s, "step\n");
  REQUIRE(s.view().clock == 500'000);
  CHECK(console(s, "print in 3\n") == "in 3 = 1 (since 0.500 s: stimulus, line 4)\n");
  console(s, "set input 5 on\nstep\n");
  CHECK(console(s, "print in 5\n") == "in 5 = 1 (since 0.500 s: set by the debugger)\n");
}

// tests/debug/programs/belt_pair.rsd: left's input 2 is wired from the beam
// (line 20), its input 1 from right's output 1 0.25 s later (line 23); the
// block's back leaves the beam at 1.9 s (the top of
// test_debug_cell_devices.cpp), before left's MOVE ends at 2 s.
TEST_CASE("debug cell: set input on a wired input is refused, print says what set it", "[debug][cell-debug][input-causes]") {
  const std::string two = debugtest::kExamples + "two_robots/";
  const auto r = debugtest::runCellDebugger(rendertest::kSourceDir + "/tests/debug/programs/belt_pair.rsd",
                                            "set input 1 on\nset input 2 off\nuntil 2\nprint in 2\n",
                                            {"left=" + two + "left.rsp", "right=" + two + "right.rsp"});
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK(debugtest::afterCommand(r.out, "set input 1 on") ==
        "error: input 1 of left is wired from right.OUT 1, 0.250 s later (line 23 of belt-pair): right's OUTSIG 1 "
        "turns it; to set it by hand, remove the WIRE\n");
  CHECK(debugtest::afterCommand(r.out, "set input 2 off") ==
        "error: input 2 of left is wired from sensor eye (line 20 of belt-pair): the sensor turns it as what it sees "
        "comes and goes; to set it by hand, remove the WIRE\n");
  CHECK(debugtest::afterCommand(r.out, "print in 2").find("in 2 = 0 (since 1.900 s: wire from sensor eye)") != std::string::npos);
}

TEST_CASE("dap: setVariable on a wired input is refused, and Inputs, evaluate and a data breakpoint give the cause",
          "[debug][dap][input-causes]") {
  using rs::wire::Json;
  const std::string program = debugtest::kExamples + "adept_production.rsp";
  const auto messages = debugtest::dapSession({
      {{"command", "initialize"}, {"arguments", {{"adapterID", "robotsim"}}}},
      {{"command", "launch"}, {"arguments", {{"program", program}, {"cell", "adept-cell"}}}},
      {{"command", "setFunctionBreakpoints"}, {"arguments", {{"breakpoints", Json::array({{{"name", "sensor eye on"}}})}}}},
      {{"command", "configurationDone"}, {"arguments", Json::object()}},
      {{"command", "variables"}, {"arguments", {{"variablesReference", 3}}}},
      {{"command", "setVariable"}, {"arguments", {{"variablesReference", 3}, {"name", "in 1"}, {"value", "off"}}}},
      {{"command", "evaluate"}, {"arguments", {{"expression", "in 1"}}}},
      {{"command", "disconnect"}, {"arguments", Json::object()}},
  });
  const Json* vars = debugtest::dapResponse(messages, 5);
  REQUIRE(vars);
  const Json& rows = (*vars)["body"]["variables"];
  REQUIRE(rows.size() == 16);
  CHECK(rows[0]["name"] == "in 1");
  CHECK(rows[0]["value"] == "on (since 1.100 s: wire from sensor eye)");
  CHECK(rows[1]["value"] == "off");  // nothing changed input 2
  const Json* set = debugtest::dapResponse(messages, 6);
  REQUIRE(set);
  CHECK((*set)["success"] == false);
  CHECK((*set)["message"] == kEyeRefusal);
  // The adapter keeps going: the next request is answered, the input as it was.
  const Json* evaluated = debugtest::dapResponse(messages, 7);
  REQUIRE(evaluated);
  CHECK((*evaluated)["body"]["result"] == "on (since 1.100 s: wire from sensor eye)");

  const auto watched = debugtest::dapSession({
      {{"command", "initialize"}, {"arguments", {{"adapterID", "robotsim"}}}},
      {{"command", "launch"}, {"arguments", {{"program", program}, {"cell", "adept-cell"}}}},
      {{"command", "setDataBreakpoints"}, {"arguments", {{"breakpoints", Json::array({{{"dataId", "in 1"}}})}}}},
      {{"command", "configurationDone"}, {"arguments", Json::object()}},
      {{"command", "disconnect"}, {"arguments", Json::object()}},
  });
  std::vector<Json> stops;
  for (const Json& m : watched)
    if (m.value("event", "") == "stopped") stops.push_back(m["body"]);
  REQUIRE(stops.size() == 1);
  CHECK(stops[0]["reason"] == "data breakpoint");
  CHECK(stops[0]["description"].get<std::string>().find("in 1 changed from 0 to 1 (since 1.100 s: wire from sensor eye)") !=
        std::string::npos);
}
