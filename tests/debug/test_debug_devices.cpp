// The debugger and the cell's devices (issue 35): breakpoints at a
// sensor's edge, a part fed and a part taken; `print devices`; going back
// restores the devices and the parts; the adapter's Devices scope and its
// device function breakpoints; and docs/debugging.md's worked session on
// the conveyor cell, run as the doc shows it.
//
// The expected values, worked out from stdlib/workcells/adept-cell.rsd and
// examples/adept_production.rsp: the cell's objects are the infeed (1),
// two blocks at x 0..40 (2) and 150..190 (3), the outfeed (4); the feeder
// puts a block at x -740..-700 at 0 s (object 5, the first number after
// the cell's four), 6 s (6), 12 s (7), ... The program's OUTSIG 1 ON runs
// the infeed at 100 mm/s from 0 s: block 3's front (x 190) reaches the
// beam at x 300 after 110 / 100 = 1.1 s, when the WAITFOR (instruction 3)
// ends; by then block 2 is at x 110, block 5 at -630.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "tests/cli/cli_support.h"
#include "tests/debug/dap_test_util.h"
#include "tests/debug/debug_test_util.h"
#include "tools/dap/serve.h"
#include "tools/debug/console.h"
#include "tools/debug/debug_session.h"
#include "tools/debug/device_points.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace {

using rs::debug::DebugSession;
using rs::debug::DevicePoint;

rs::runtime::RunSpec adeptProduction() { return debugtest::specOnCell("adept_production.rsp", "adept-cell"); }

std::string devicesConsole(DebugSession& s, const std::string& commands) {
  std::ostringstream out;
  rs::debug::Console console(s, nullptr, out);
  std::istringstream lines(commands);
  for (std::string line; std::getline(lines, line);) console.execute(line);
  return out.str();
}

// print devices at 1.1 s, when block 3 breaks the beam (see the top).
const std::string kDevicesAtBeam =
    "sensor eye         ON, turned ON 1 time\n"
    "conveyor infeed    running, carried 3 parts\n"
    "conveyor outfeed   running, carried 0 parts\n"
    "feeder parts       fed 1 part\n"
    "sink done          took 0 parts\n"
    "block (object 2)   at (110.000, 500.000, 620.000), riding infeed\n"
    "block (object 3)   at (260.000, 500.000, 620.000), riding infeed\n"
    "block (object 5)   at (-630.000, 500.000, 620.000), riding infeed\n";

// Before the first instruction's end nothing has moved: the parts where
// the cell and the feeder put them, the infeed stopped (output 1 is off).
const std::string kDevicesAtStart =
    "sensor eye         OFF, turned ON 0 times\n"
    "conveyor infeed    stopped, carried 0 parts\n"
    "conveyor outfeed   running, carried 0 parts\n"
    "feeder parts       fed 1 part\n"
    "sink done          took 0 parts\n"
    "block (object 2)   at (0.000, 500.000, 620.000)\n"
    "block (object 3)   at (150.000, 500.000, 620.000)\n"
    "block (object 5)   at (-740.000, 500.000, 620.000)\n";

}  // namespace

TEST_CASE("debug: break sensor eye on stops when a block breaks the beam, and print devices shows the cell",
          "[debug][devices]") {
  DebugSession s(adeptProduction());
  const std::string out = devicesConsole(s, "break sensor eye on\ncontinue\nprint devices\n");
  CHECK(out.find("breakpoint 1: sensor eye ON\n") != std::string::npos);
  CHECK(out.find("breakpoint 1 (sensor eye ON): sensor eye ON at 1.100 s\n") != std::string::npos);
  CHECK(s.view().clock == 1'100'000);
  CHECK(s.view().steps == 3);  // SET, OUTSIG, WAITFOR
  CHECK(out.find(kDevicesAtBeam) != std::string::npos);
}

TEST_CASE("debug: break feeder and break sink stop at a part fed and a part taken", "[debug][devices]") {
  DebugSession s(adeptProduction());
  std::string out = devicesConsole(s, "break feeder parts\ncontinue\n");
  // The first part is fed at 0 s, before the first instruction ends.
  CHECK(out.find("breakpoint 1 (feeder parts): feeder parts: block (object 5) at (-740, 500, 620) at 0.000 s\n") !=
        std::string::npos);
  CHECK(s.view().steps == 1);
  out = devicesConsole(s, "continue\n");
  CHECK(out.find("feeder parts: block (object 6) at (-740, 500, 620) at 6.000 s") != std::string::npos);
  CHECK(s.view().clock >= 6'000'000);
  // The sink: blocks 3 and 2 are put on the outfeed in the first two
  // cycles (let go at about 2.0 and 4.7 s, x = 280); the outfeed carries
  // each at 100 mm/s into the sink's zone (x from 640): 3.6 s later, at
  // about 5.6 and 8.3 s, both during the third cycle's WAITFOR (4.8 to
  // 12.2 s, while the infeed brings block 5 to the beam). The stop comes
  // after that instruction and names both takes, each with its time.
  DebugSession t(adeptProduction());
  out = devicesConsole(t, "break sink done\ncontinue\nprint devices\n");
  const std::string said = "breakpoint 1 (sink done): sink done: takes block (object 3) at 5.6";
  CHECK(out.find(said) != std::string::npos);
  CHECK(out.find(" s, sink done: takes block (object 2) at 8.3") != std::string::npos);
  CHECK(t.view().steps == 29);  // 1 + 2 cycles of 13 + OUTSIG and WAITFOR
  CHECK(out.find("sink done          took 2 parts\n") != std::string::npos);
}

TEST_CASE("debug: a sensor's OFF edge, and device points the cell does not have", "[debug][devices]") {
  DebugSession s(adeptProduction());
  std::string out = devicesConsole(s, "break sensor eye off\ncontinue\n");
  CHECK(out.find("breakpoint 1 (sensor eye OFF): sensor eye OFF at ") != std::string::npos);
  CHECK(s.view().clock > 1'100'000);  // after the ON edge at 1.1 s
  out = devicesConsole(s, "print devices\n");
  CHECK(out.find("sensor eye         OFF, turned ON 1 time\n") != std::string::npos);
  out = devicesConsole(s, "break sensor eyes\nbreak feeder eye\nbreak sink done twice\nbreak sensor eye up\n");
  CHECK(out.find("error: the cell has no sensor 'eyes' (did you mean 'eye'?): its sensors are eye\n") != std::string::npos);
  CHECK(out.find("error: the cell has no feeder 'eye': its feeders are parts\n") != std::string::npos);
  CHECK(out.find("error: break sink takes a sink's name: break sink NAME\n") != std::string::npos);
  CHECK(out.find("error: 'up': a sensor's edge is on or off\n") != std::string::npos);
  // Without a workcell there are no devices.
  DebugSession lone(debugtest::specOf("        DELAY 1\n        END\n"));
  out = devicesConsole(lone, "break sensor eye\nprint devices\n");
  CHECK(out.find("error: the cell has no devices") != std::string::npos);
  CHECK(out.find("no devices: ") != std::string::npos);
}

TEST_CASE("debug: going back restores the devices and the parts as they were", "[debug][devices]") {
  // Forwards past sensor edges, feeds (0, 6, 12 s) and takes: what print
  // devices and the objects are after every step, the first time.
  DebugSession s(adeptProduction());
  std::vector<std::string> devicesAt{devicesConsole(s, "print devices\n")};
  std::vector<std::string> objectsAt{devicesConsole(s, "print objects\n")};
  for (int i = 0; i < 60; ++i) {
    s.step();
    devicesAt.push_back(devicesConsole(s, "print devices\n"));
    objectsAt.push_back(devicesConsole(s, "print objects\n"));
  }
  REQUIRE(s.view().clock > 12'000'000);
  CHECK(devicesAt[60] != devicesAt[1]);
  CHECK(devicesAt[1] == kDevicesAtStart);
  CHECK(devicesAt[3] == kDevicesAtBeam);
  // Back to every one of them, in a shuffled order, by reverse-step and goto-time.
  for (std::uint64_t step : {50u, 3u, 41u, 1u, 17u, 0u, 29u, 2u}) {
    CAPTURE(step);
    s.reverseStep(s.view().steps - step);
    REQUIRE(s.view().steps == step);
    CHECK(devicesConsole(s, "print devices\n") == devicesAt[step]);
    CHECK(devicesConsole(s, "print objects\n") == objectsAt[step]);
    s.step(60 - step);  // forwards again: the same future
    CHECK(devicesConsole(s, "print devices\n") == devicesAt[60]);
  }
  // The beam's moment: the WAITFOR ends then, and OUTSIG 1 OFF runs at
  // once (an instruction that takes no time), stopping the infeed.
  s.gotoTime(1'100'000);
  CHECK(s.view().steps == 4);
  CHECK(devicesConsole(s, "print devices\n") == devicesAt[4]);
  CHECK(devicesAt[4].find("conveyor infeed    stopped, carried 3 parts\n") != std::string::npos);
  CHECK(devicesAt[4].find("block (object 3)   at (260.000, 500.000, 620.000)\n") != std::string::npos);
  // Inside the move to the block (MOVEP PICK, 1.100 to 1.227 s, see
  // the trace of robotsim run): the devices as that move leaves them, said so.
  s.gotoTime(1'200'000);
  const std::string inside = devicesConsole(s, "print devices\n");
  CHECK(inside == devicesAt[5] + "(the devices and the parts as they are at 1.227 s, when the instruction under way ends)\n");
  // reverse-continue to a device breakpoint: the feed at 0 s, during step 1.
  s.step(40);
  const std::string out = devicesConsole(s, "break feeder parts\nreverse-continue\nprint devices\n");
  CHECK(out.find("feeder parts: block (object 5) at (-740, 500, 620) at 0.000 s") == std::string::npos);  // 6 or 12 s first
  CHECK(out.find("breakpoint 1 (feeder parts): feeder parts: block (object ") != std::string::npos);
  const std::uint64_t back = s.view().steps;
  CHECK(devicesConsole(s, "print devices\n") == devicesAt[back]);
  // Again: the feed at 0 s, during the first step (the cell's first
  // instant, before any instruction: what a snapshot at the start keeps).
  const std::string first = devicesConsole(s, "reverse-continue\n");
  CHECK(first.find("breakpoint 1 (feeder parts): feeder parts: block (object 5) at (-740, 500, 620) at 0.000 s\n") !=
        std::string::npos);
  CHECK(s.view().steps == 1);
  CHECK(devicesConsole(s, "print devices\n") == kDevicesAtStart);
}

using debugtest::dapResponse;
using debugtest::dapSession;

TEST_CASE("dap: device function breakpoints and the Devices scope", "[debug][dap][devices]") {
  using rs::wire::Json;
  const std::string program = debugtest::kExamples + "adept_production.rsp";
  const auto messages = dapSession({
      {{"command", "initialize"}, {"arguments", {{"adapterID", "robotsim"}}}},
      {{"command", "launch"}, {"arguments", {{"program", program}, {"cell", "adept-cell"}}}},
      {{"command", "setFunctionBreakpoints"},
       {"arguments", {{"breakpoints", Json::array({{{"name", "sensor eye on"}}, {{"name", "sink nowhere"}}, {{"name", "next"}}})}}}},
      {{"command", "configurationDone"}, {"arguments", Json::object()}},
      {{"command", "scopes"}, {"arguments", {{"frameId", 0}}}},
      {{"command", "variables"}, {"arguments", {{"variablesReference", 6}}}},
      {{"command", "evaluate"}, {"arguments", {{"expression", "devices"}}}},
      {{"command", "setVariable"}, {"arguments", {{"variablesReference", 6}, {"name", "sink done"}, {"value", "3"}}}},
      {{"command", "disconnect"}, {"arguments", Json::object()}},
  });
  const Json* set = dapResponse(messages, 3);
  REQUIRE(set);
  const Json& answers = (*set)["body"]["breakpoints"];
  REQUIRE(answers.size() == 3);
  CHECK(answers[0]["verified"] == true);
  CHECK(answers[1]["verified"] == false);
  CHECK(answers[1]["message"] == "the cell has no sink 'nowhere': its sinks are done");
  CHECK(answers[2]["verified"] == true);  // the label next, line 15
  CHECK(answers[2]["line"] == 15);
  // The label next comes first (before instruction 2, at 0 s), then the beam.
  std::vector<Json> stops;
  for (const Json& m : messages)
    if (m.value("event", "") == "stopped") stops.push_back(m["body"]);
  REQUIRE(stops.size() == 1);
  CHECK(stops[0]["reason"] == "function breakpoint");
  const Json* scopes = dapResponse(messages, 5);
  REQUIRE(scopes);
  const Json& list = (*scopes)["body"]["scopes"];
  REQUIRE(list.size() == 6);
  CHECK(list[5]["name"] == "Devices");
  CHECK(list[5]["variablesReference"] == 6);
  CHECK(list[5]["namedVariables"] == 8);  // 5 devices, 3 parts
  const Json* vars = dapResponse(messages, 6);
  REQUIRE(vars);
  const Json& rows = (*vars)["body"]["variables"];
  REQUIRE(rows.size() == 8);
  // At the label next, step 1: the infeed not yet running.
  CHECK(rows[0]["name"] == "sensor eye");
  CHECK(rows[0]["value"] == "OFF, turned ON 0 times");
  CHECK(rows[1]["value"] == "stopped, carried 0 parts");
  CHECK(rows[7]["name"] == "block (object 5)");
  CHECK(rows[7]["value"] == "at (-740.000, 500.000, 620.000)");
  // evaluate devices: the same rows on one line, and the scope to open.
  const Json* evaluated = dapResponse(messages, 7);
  REQUIRE(evaluated);
  CHECK((*evaluated)["body"]["variablesReference"] == 6);
  const std::string result = (*evaluated)["body"]["result"].get<std::string>();
  CHECK(result.rfind("sensor eye = OFF, turned ON 0 times, conveyor infeed = stopped, carried 0 parts, ", 0) == 0);
  CHECK(result.find("block (object 5) = at (-740.000, 500.000, 620.000)") != std::string::npos);
  // The devices are the run's: they cannot be set.
  const Json* set2 = dapResponse(messages, 8);
  REQUIRE(set2);
  CHECK((*set2)["success"] == false);
  CHECK((*set2)["message"] == "only variables and inputs can be set: the motors, objects, clock and devices are the run's");
}

TEST_CASE("dap: a device function breakpoint stops with what happened", "[debug][dap][devices]") {
  using rs::wire::Json;
  const std::string program = debugtest::kExamples + "adept_production.rsp";
  const auto messages = dapSession({
      {{"command", "initialize"}, {"arguments", {{"adapterID", "robotsim"}}}},
      {{"command", "launch"}, {"arguments", {{"program", program}, {"cell", "adept-cell"}}}},
      {{"command", "setFunctionBreakpoints"}, {"arguments", {{"breakpoints", Json::array({{{"name", "sensor eye on"}}})}}}},
      {{"command", "configurationDone"}, {"arguments", Json::object()}},
      {{"command", "disconnect"}, {"arguments", Json::object()}},
  });
  std::vector<Json> stops;
  for (const Json& m : messages)
    if (m.value("event", "") == "stopped") stops.push_back(m["body"]);
  REQUIRE(stops.size() == 1);
  CHECK(stops[0]["reason"] == "function breakpoint");
  CHECK(stops[0]["description"] == "breakpoint 1 (sensor eye ON): sensor eye ON at 1.100 s");
}

namespace {

// docs/debugging.md's session on the conveyor cell: the fenced block that
// starts with `$ robotsim debug examples/adept_production.rsp`; its
// commands are the lines after `(rsdb) `, and the rest of the block is
// what robotsim debug prints for them.
std::string devicesDocBlock() {
  std::ifstream in(rendertest::kSourceDir + "/docs/debugging.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string start = "```\n$ robotsim debug examples/adept_production.rsp --cell adept-cell\n";
  const std::size_t at = doc.find(start);
  if (at == std::string::npos) return {};
  const std::size_t body = at + start.size();
  return doc.substr(body, doc.find("```\n", body) - body);
}

}  // namespace

TEST_CASE("docs/debugging.md's session on the conveyor cell is what robotsim debug prints", "[debug][devices][docs]") {
  const std::string block = devicesDocBlock();
  REQUIRE(!block.empty());
  std::string commands;
  std::istringstream lines(block);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("(rsdb) ", 0) == 0) commands += line.substr(7) + "\n";
  const rs::testing::TempDir dir;
  const rs::testing::CliResult r =
      rs::testing::runCli({"debug", debugtest::kExamples + "adept_production.rsp", "--cell", "adept-cell", "-x",
                           dir.write("session.cmds", commands)});
  CHECK(r.code == 0);
  std::string out = r.out;
  for (std::size_t p; (p = out.find(rendertest::kSourceDir + "/")) != std::string::npos;)
    out.erase(p, rendertest::kSourceDir.size() + 1);
  CHECK(out == block);
}
