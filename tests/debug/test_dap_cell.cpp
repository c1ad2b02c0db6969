// Issue 36: the debug adapter on examples/two_robots/interlock.rsd, launched
// with `cell` and `programs`: one thread per robot, stopped events with
// allThreadsStopped and the robot that stopped, stack, scopes and
// variables per thread, stepBack for the whole cell. Served in-process
// over streams as `robotsim dap` serves stdin and stdout.
//
// The times and places are worked out by hand as in test_debug_cell.cpp:
// right reaches its first MOVE 300 (line 6) when its WAITFOR ends at 2 s
// (left's OUTSIG 1 ON at 2, no AFTER); that move takes 1 s (motor F at 300
// counts a second); left meanwhile waits at line 10 for its input 1.
#include <catch2/catch.hpp>

#include "tests/debug/cell_debug_util.h"
#include "tests/debug/dap_test_util.h"
#include "tests/debug/debug_test_util.h"
#include "tools/dap/serve.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace {

using rs::wire::Json;

const std::string kTwo = debugtest::kExamples + "two_robots/";

std::vector<Json> serveRequests(const std::vector<Json>& requests) { return debugtest::dapSession(requests); }

// The response to request number `seq`, and the events after it up to the next response.
const Json& responseTo(const std::vector<Json>& m, int seq) {
  for (const Json& j : m)
    if (j.value("type", "") == "response" && j.value("request_seq", 0) == seq) return j;
  FAIL("no response to request " << seq);
  return m.front();
}

std::vector<Json> stoppedEvents(const std::vector<Json>& m) {
  std::vector<Json> out;
  for (const Json& j : m)
    if (j.value("type", "") == "event" && j.value("event", "") == "stopped") out.push_back(j.at("body"));
  return out;
}

std::string valueOf(const Json& variables, const std::string& name) {
  for (const Json& v : variables.at("body").at("variables"))
    if (v.at("name") == name) return v.at("value").get<std::string>();
  return "(none)";
}

Json request(const std::string& command, Json args = Json::object()) {
  return {{"command", command}, {"arguments", std::move(args)}};
}

}  // namespace

TEST_CASE("dap cell: a thread per robot, stops of the whole cell, variables per thread, step back",
          "[debug][dap][cell-debug]") {
  const std::vector<Json> m = serveRequests({
      request("initialize"),                                                                           // 1
      request("launch", {{"cell", kTwo + "interlock.rsd"},
                         {"programs", {{"left", kTwo + "left.rsp"}, {"right", kTwo + "right.rsp"}}}}),  // 2
      request("setBreakpoints", {{"source", {{"path", kTwo + "right.rsp"}}}, {"breakpoints", {{{"line", 6}}}}}),  // 3
      request("threads"),                                                                              // 4
      request("configurationDone"),                                                                    // 5
      request("stackTrace", {{"threadId", 2}}),                                                        // 6
      request("stackTrace", {{"threadId", 1}}),                                                        // 7
      request("scopes", {{"frameId", 2000}}),                                                          // 8
      request("variables", {{"variablesReference", 2004}}),                                            // 9: right's clock
      request("stepIn", {{"threadId", 2}}),                                                            // 10
      request("variables", {{"variablesReference", 2002}}),                                            // 11: right's motors
      request("variables", {{"variablesReference", 1002}}),                                            // 12: left's motors
      request("stepBack", {{"threadId", 2}}),                                                          // 13
      request("variables", {{"variablesReference", 2004}}),                                            // 14
      request("evaluate", {{"expression", "TURNS"}, {"frameId", 1000}}),                               // 15
      request("stackTrace", {{"threadId", 9}}),                                                        // 16
      request("disconnect"),                                                                           // 17
  });
  const Json& launched = responseTo(m, 2);
  INFO(launched.dump());
  REQUIRE(launched.at("success") == true);
  const Json& bp = responseTo(m, 3).at("body").at("breakpoints");
  REQUIRE(bp.size() == 1);
  CHECK(bp[0].at("verified") == true);
  CHECK(bp[0].at("line") == 6);
  const Json& threads = responseTo(m, 4).at("body").at("threads");
  REQUIRE(threads.size() == 2);
  CHECK(threads[0] == Json{{"id", 1}, {"name", "left"}});
  CHECK(threads[1] == Json{{"id", 2}, {"name", "right"}});

  const std::vector<Json> stops = stoppedEvents(m);
  REQUIRE(stops.size() == 3);
  // configurationDone runs to right's breakpoint: right stopped it, and with it every robot.
  CHECK(stops[0].at("reason") == "breakpoint");
  CHECK(stops[0].at("threadId") == 2);
  CHECK(stops[0].at("allThreadsStopped") == true);
  CHECK(stops[0].at("hitBreakpointIds") == Json::array({bp[0].at("id")}));
  const Json& rightFrames = responseTo(m, 6).at("body").at("stackFrames");
  REQUIRE(rightFrames.size() == 1);
  CHECK(rightFrames[0].at("line") == 6);
  CHECK(rightFrames[0].at("source").at("name") == "right.rsp");
  const Json& leftFrames = responseTo(m, 7).at("body").at("stackFrames");
  REQUIRE(leftFrames.size() == 1);
  CHECK(leftFrames[0].at("line") == 10);  // left waits in its WAITFOR 1 ON
  CHECK(leftFrames[0].at("source").at("name") == "left.rsp");
  const Json& scopes = responseTo(m, 8).at("body").at("scopes");
  REQUIRE(scopes.size() == 4);
  CHECK(scopes[0].at("name") == "Variables");
  CHECK(scopes[3].at("variablesReference") == 2004);
  CHECK(valueOf(responseTo(m, 9), "time") == "2.000 s");
  // stepIn on right: its 1 s move; left does not move.
  CHECK(stops[1].at("reason") == "step");
  CHECK(stops[1].at("threadId") == 2);
  CHECK(stops[1].at("allThreadsStopped") == true);
  CHECK(valueOf(responseTo(m, 11), "F") == "300");
  CHECK(valueOf(responseTo(m, 12), "F") == "0");
  // stepBack puts the whole cell back at 2 s.
  CHECK(stops[2].at("threadId") == 2);
  CHECK(stops[2].at("allThreadsStopped") == true);
  CHECK(valueOf(responseTo(m, 14), "time") == "2.000 s");
  CHECK(responseTo(m, 15).at("body").at("result") == "0");  // left's TURNS: its first pass
  CHECK(responseTo(m, 16).at("success") == false);
}

TEST_CASE("dap cell: a launch whose programs name no robot of the cell is refused with the labels",
          "[debug][dap][cell-debug]") {
  const std::vector<Json> m = serveRequests({
      request("initialize"),
      request("launch", {{"cell", kTwo + "interlock.rsd"}, {"programs", {{"middle", kTwo + "left.rsp"}}}}),
      request("launch", {{"cell", kTwo + "interlock.rsd"}, {"programs", 7}}),
      request("disconnect"),
  });
  const Json& bad = responseTo(m, 2);
  CHECK(bad.at("success") == false);
  INFO(bad.dump());
  CHECK(bad.at("message").get<std::string>().find("cannot debug cell") != std::string::npos);
  CHECK(responseTo(m, 3).at("message").get<std::string>().find("programs is") != std::string::npos);
}

// gotoTime 2.5: right half way through its 2-3 s move (F at 150); a
// breakpoint at left.rsp line 11 (left's WAITFOR ends at 4.25: right's
// OUT 1 at 4 plus the wire's AFTER 0.25), then reverseContinue back to
// right's line 6 at 2 s. The cell's PROGRAMs run without `programs`.
TEST_CASE("dap cell: gotoTime and reverseContinue put the whole cell back", "[debug][dap][cell-debug]") {
  const std::vector<Json> m = serveRequests({
      request("initialize"),                                                                         // 1
      request("launch", {{"cell", kTwo + "interlock.rsd"}, {"stopOnEntry", true}}),                  // 2
      request("setBreakpoints", {{"source", {{"path", kTwo + "right.rsp"}}}, {"breakpoints", {{{"line", 6}}}}}),  // 3
      request("setBreakpoints", {{"source", {{"path", kTwo + "left.rsp"}}}, {"breakpoints", {{{"line", 11}}}}}),  // 4
      request("configurationDone"),                                                                  // 5
      request("gotoTime", {{"time", 2.5}}),                                                          // 6
      request("variables", {{"variablesReference", 2002}}),                                          // 7
      request("continue", {{"threadId", 1}}),                                                        // 8
      request("continue", {{"threadId", 1}}),                                                        // 9
      request("reverseContinue", {{"threadId", 1}}),                                                 // 10
      request("variables", {{"variablesReference", 2004}}),                                          // 11
      request("disconnect"),                                                                         // 12
  });
  REQUIRE(responseTo(m, 2).at("success") == true);
  const std::vector<Json> stops = stoppedEvents(m);
  REQUIRE(stops.size() == 5);
  CHECK(stops[0].at("reason") == "entry");
  CHECK(stops[1].at("reason") == "goto");
  CHECK(valueOf(responseTo(m, 7), "F") == "150");
  // From 2.5 s on: left's breakpoint at 4.25 s comes first (right's at 2 s is behind).
  CHECK(stops[2].at("threadId") == 1);
  CHECK(stops[2].at("reason") == "breakpoint");
  // Then right's second pass reaches line 6 at 6.25 s.
  CHECK(stops[3].at("threadId") == 2);
  // Back: the last breakpoint before 6.25 s is left's at 4.25 s.
  CHECK(stops[4].at("threadId") == 1);
  CHECK(stops[4].at("reason") == "breakpoint");
  CHECK(stops[4].at("allThreadsStopped") == true);
  CHECK(valueOf(responseTo(m, 11), "time") == "4.250 s");  // right's clock: the cell's one
}

// A cell of several robots with devices (tests/debug/programs/belt_pair.rsd,
// worked out at the top of tests/debug/test_debug_cell_devices.cpp): the
// beam's ON edge at 1.5 s stops the cell with left's second MOVE at 2 s,
// as a function breakpoint; left's TURNS changes with its ADD at 4.25 s, a
// data breakpoint; reverseContinue goes back to the beam's stop, where
// the Devices scope shows what it showed going forwards.
TEST_CASE("dap cell: device function breakpoints, data breakpoints and the Devices scope", "[debug][dap][cell-debug]") {
  const std::string cell = rendertest::kSourceDir + "/tests/debug/programs/belt_pair.rsd";
  const std::vector<Json> m = serveRequests({
      request("initialize"),                                                                           // 1
      request("launch", {{"cell", cell},
                         {"programs", {{"left", kTwo + "left.rsp"}, {"right", kTwo + "right.rsp"}}}}),  // 2
      request("setFunctionBreakpoints",
              {{"breakpoints", {{{"name", "sensor eye on"}}, {{"name", "again"}, {"condition", "TURNS = 5"}},
                                {{"name", "sensor nope"}}}}}),  // 3: left's again never with TURNS 5
      request("dataBreakpointInfo", {{"name", "TURNS"}, {"variablesReference", 1001}}),                // 4
      request("dataBreakpointInfo", {{"name", "time"}, {"variablesReference", 1004}}),                 // 5
      request("setDataBreakpoints", {{"breakpoints", {{{"dataId", "1:TURNS"}}, {{"dataId", "9:TURNS"}}}}}),  // 6
      request("configurationDone"),                                                                    // 7
      request("scopes", {{"frameId", 1000}}),                                                          // 8
      request("variables", {{"variablesReference", 1005}}),                                            // 9
      request("continue", {{"threadId", 1}}),                                                          // 10
      request("stepOut", {{"threadId", 1}}),                                                           // 11
      request("reverseContinue", {{"threadId", 1}}),                                                   // 12
      request("variables", {{"variablesReference", 2005}}),                                            // 13
      request("evaluate", {{"expression", "devices"}, {"frameId", 2000}}),                             // 14
      request("evaluate", {{"expression", "objects"}, {"frameId", 2000}}),                             // 15
      request("setVariable", {{"variablesReference", 1003}, {"name", "in 2"}, {"value", "on"}}),      // 16
      request("setVariable", {{"variablesReference", 1003}, {"name", "in 5"}, {"value", "on"}}),      // 17
      request("setVariable", {{"variablesReference", 1001}, {"name", "TURNS"}, {"value", "3"}}),      // 18
      request("variables", {{"variablesReference", 1003}}),                                            // 19
      request("disconnect"),                                                                           // 20
  });
  REQUIRE(responseTo(m, 2).at("success") == true);
  const Json& fb = responseTo(m, 3).at("body").at("breakpoints");
  REQUIRE(fb.size() == 3);
  CHECK(fb[0].at("verified") == true);
  CHECK(fb[1].at("verified") == true);  // a label of the current thread's robot, left: line 7 of left.rsp
  CHECK(fb[1].at("line") == 7);
  CHECK(fb[1].at("source").at("name") == "left.rsp");
  CHECK(fb[2].at("verified") == false);
  CHECK(fb[2].at("message").get<std::string>().find("its sensors are eye") != std::string::npos);
  CHECK(responseTo(m, 4).at("body").at("dataId") == "1:TURNS");
  CHECK(responseTo(m, 5).at("body").at("dataId").is_null());  // the clock cannot be watched
  const Json& db = responseTo(m, 6).at("body").at("breakpoints");
  REQUIRE(db.size() == 2);
  CHECK(db[0].at("verified") == true);
  CHECK(db[1].at("verified") == false);  // no thread 9
  const std::vector<Json> stops = stoppedEvents(m);
  REQUIRE(stops.size() == 3);
  CHECK(stops[0].at("reason") == "function breakpoint");
  CHECK(stops[0].at("threadId") == 1);
  CHECK(stops[0].at("description") == "breakpoint 1 (sensor eye ON): sensor eye ON at 1.500 s");
  const Json& scopes = responseTo(m, 8).at("body").at("scopes");
  REQUIRE(scopes.size() == 5);
  CHECK(scopes[4].at("name") == "Devices");
  CHECK(valueOf(responseTo(m, 9), "sensor eye") == "OFF, turned ON 1 time");
  CHECK(valueOf(responseTo(m, 9), "block (object 2)") == "at (-540.000, 500.000, 2870.000), riding belt");
  CHECK(stops[1].at("reason") == "data breakpoint");
  CHECK(stops[1].at("description") == "watch 3: TURNS of left changed from 0 to 1");  // ids 1 and 2: the function breakpoints
  CHECK(responseTo(m, 11).at("success") == false);  // left is in no subroutine
  CHECK(stops[2].at("reason") == "function breakpoint");
  // Right's view of the same devices, back at 2 s.
  CHECK(valueOf(responseTo(m, 13), "block (object 2)") == "at (-540.000, 500.000, 2870.000), riding belt");
  // evaluate answers a whole scope as for one robot, with the thread's Devices scope to open (no Objects scope here).
  const Json& devices = responseTo(m, 14).at("body");
  CHECK(devices.at("result").get<std::string>().starts_with("sensor eye = OFF, turned ON 1 time, conveyor belt = "));
  CHECK(devices.at("variablesReference") == 2005);
  CHECK(responseTo(m, 15).at("body").at("result") == "1 conveyor, 2 block");
  CHECK(responseTo(m, 15).at("body").at("variablesReference") == 0);
  // setVariable: an input as the terminal's set input (set by the debugger, from now on); left's input 2 is the beam's wire: refused.
  CHECK(responseTo(m, 16).at("success") == false);
  CHECK(responseTo(m, 16).at("message").get<std::string>().find("is wired") != std::string::npos);
  CHECK(responseTo(m, 17).at("body").at("value") == "on");
  CHECK(responseTo(m, 18).at("success") == false);
  // At the cell's present instant, the beam's stop at 2 s (the run stands there), with its cause: the
  // cell's set input is a stimulus of no file.
  CHECK(valueOf(responseTo(m, 19), "in 5") == "on (since 2.000 s: set by the debugger)");
}

// The collision and warning filters on a cell of several robots: the
// gantry's close on nothing at 4.675 s and its fingers' collision, found in
// its step 4.675-5.425 s (worked out in test_debug_cell_points.cpp), each
// an exception stop of the whole cell; the cell goes on after them.
TEST_CASE("dap cell: the collision and warning filters stop the cell as exceptions", "[debug][dap][cell-debug]") {
  rs::testing::TempDir dir;
  const std::string cell = debugtest::writeGantryBeside(dir);
  const std::vector<Json> m = serveRequests({
      request("initialize"),                                                                 // 1
      request("launch", {{"cell", cell}, {"collisions", "warn"}}),                          // 2
      request("setExceptionBreakpoints", {{"filters", {"collision", "warning", "nope"}}}),   // 3
      request("configurationDone"),                                                          // 4
      request("continue", {{"threadId", 1}}),                                                // 5
      request("continue", {{"threadId", 1}}),                                                // 6
      request("disconnect"),                                                                 // 7
  });
  REQUIRE(responseTo(m, 2).at("success") == true);
  const Json& filters = responseTo(m, 3).at("body").at("breakpoints");
  REQUIRE(filters.size() == 3);
  CHECK(filters[0].at("verified") == true);
  CHECK(filters[1].at("verified") == true);
  CHECK(filters[2].at("verified") == false);
  const std::vector<Json> stops = stoppedEvents(m);
  REQUIRE(stops.size() == 2);
  CHECK(stops[0].at("reason") == "exception");
  CHECK(stops[0].at("text").get<std::string>().find("a gripper closed on nothing") != std::string::npos);
  CHECK(stops[1].at("reason") == "exception");
  CHECK(stops[1].at("text").get<std::string>().find("of robot 'arm' hits object 2 (block)") != std::string::npos);
  CHECK(stops[1].at("threadId") == 1);
}
