// The debug adapter on a moving arm (issue 24): the exception filters
// `collision` and `warning` (announced in exceptionBreakpointFilters, set
// by setExceptionBreakpoints as the DAP specification has it) stop the
// run at a collision's first contact and after a close on nothing, with
// reason "exception"; a step over a close that took nothing says so on the
// debug console. Real protocol sessions, served in-process by dap::serve
// as `robotsim dap` serves stdin and stdout. The numbers are gantry-cell's,
// worked out in tests/debug/test_moving_arm.cpp.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tools/dap/serve.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace {

using rs::wire::Json;

std::string dapArmRequest(int seq, const std::string& command, Json arguments) {
  return rs::wire::frameMessage(
      Json{{"seq", seq}, {"type", "request"}, {"command", command}, {"arguments", std::move(arguments)}}.dump());
}

std::vector<Json> dapArmServe(const std::string& bytes) {
  std::istringstream in(bytes);
  std::ostringstream out, log;
  rs::wire::StreamInput input(in);
  rs::wire::StreamOutput output(out);
  rs::dap::serve(input, output, log);
  std::vector<Json> messages;
  for (const rs::wire::Frame& f : rs::wire::parseFrames(out.str())) messages.push_back(Json::parse(f.body));
  return messages;
}

std::string dapArmProgram(int y) {
  return "        MOVETO -2800 2800 0 0\n"
         "        MOVE 0 0 " + std::to_string(y) + " 0\n"
         "        MOVE 0 0 0 100\n"
         "        END\n";
}

std::vector<Json> dapArmEvents(const std::vector<Json>& messages, const std::string& name) {
  std::vector<Json> found;
  for (const Json& m : messages)
    if (m.value("type", "") == "event" && m.value("event", "") == name) found.push_back(m);
  return found;
}

const Json* dapArmResponseTo(const std::vector<Json>& messages, int seq) {
  for (const Json& m : messages)
    if (m.value("type", "") == "response" && m.value("request_seq", -1) == seq) return &m;
  return nullptr;
}

}  // namespace

TEST_CASE("dap: the collision and warning exception filters are announced, off by default", "[debug][dap][moving-arm]") {
  const std::vector<Json> messages = dapArmServe(dapArmRequest(1, "initialize", {{"adapterID", "robotsim"}}));
  const Json* init = dapArmResponseTo(messages, 1);
  REQUIRE(init);
  std::vector<std::string> names;
  for (const Json& f : init->at("body").at("exceptionBreakpointFilters")) {
    names.push_back(f.at("filter").get<std::string>());
    if (names.back() == "collision" || names.back() == "warning") CHECK(f.at("default") == false);
  }
  CHECK(names == std::vector<std::string>{"deadlock", "runtimeError", "limit", "collision", "warning"});
}

TEST_CASE("dap: the collision filter stops at the first contact, the scopes show the pose then", "[debug][dap][moving-arm]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("low.rsp", dapArmProgram(1700));
  const std::vector<Json> messages = dapArmServe(
      dapArmRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
      dapArmRequest(2, "launch", {{"program", program}, {"cell", "gantry-cell"}, {"collisions", "warn"}}) +
      dapArmRequest(3, "setExceptionBreakpoints", {{"filters", {"collision"}}}) +
      dapArmRequest(4, "configurationDone", Json::object()) +
      dapArmRequest(5, "evaluate", {{"expression", "Y"}}) +
      dapArmRequest(6, "evaluate", {{"expression", "clock"}}) +
      dapArmRequest(7, "continue", {{"threadId", 1}}) +
      dapArmRequest(8, "setExceptionBreakpoints", {{"filters", {"bogus"}}}) +
      dapArmRequest(9, "continue", {{"threadId", 1}}) + dapArmRequest(10, "continue", {{"threadId", 1}}) +
      dapArmRequest(11, "disconnect", Json::object()));
  const Json* set = dapArmResponseTo(messages, 3);
  REQUIRE(set);
  CHECK(set->at("success") == true);
  CHECK(set->at("body").at("breakpoints").size() == 1);
  const std::vector<Json> stops = dapArmEvents(messages, "stopped");
  REQUIRE(stops.size() >= 1);
  const Json& body = stops[0].at("body");
  CHECK(body.at("reason") == "exception");
  const std::string text = body.at("text").get<std::string>();
  INFO(text);
  CHECK(text.find("(collision): ") != std::string::npos);
  CHECK(text.find("hits object 1 (pallet) at 4.6") != std::string::npos);
  // At the contact the ram has come down about 1500 counts (the fingers'
  // ends at the deck), 1.875 s into line 2, which starts at 2.8 s.
  const Json* y = dapArmResponseTo(messages, 5);
  REQUIRE(y);
  const int counts = std::stoi(y->at("body").at("result").get<std::string>());
  CHECK(counts >= 1490);
  CHECK(counts <= 1510);
  const Json* clock = dapArmResponseTo(messages, 6);
  REQUIRE(clock);
  const double seconds = std::stod(clock->at("body").at("result").get<std::string>());
  CHECK(seconds == Approx(2.8 + counts / 800.0).margin(0.0015));
  // After it the run goes on (warn mode) to its end; any other stop on
  // the way is another collision's.
  CHECK(dapArmEvents(messages, "terminated").size() == 1);
  for (const Json& stop : stops) {
    CHECK(stop["body"]["reason"] == "exception");
    CHECK(stop["body"]["text"].get<std::string>().find("(collision): ") != std::string::npos);
  }
  // A filter the adapter does not offer is refused, and the adapter goes on.
  const Json* bogus = dapArmResponseTo(messages, 8);
  REQUIRE(bogus);
  CHECK(bogus->at("success") == false);
  CHECK(bogus->at("message").get<std::string>().find("no exception filter 'bogus'") != std::string::npos);
}

TEST_CASE("dap: in the default collision mode the collision filter and the runtimeError stop stand at the contact",
          "[debug][dap][moving-arm]") {
  // No "collisions" in the launch: error, the run ends at the collision,
  // the machine having made the whole move (Y 1700 at 4.925 s); the arm
  // never got past the contact (Y about 1500 at 2.8 + 1500/800 = 4.675 s,
  // tests/debug/test_moving_arm.cpp).
  const rs::testing::TempDir dir;
  const std::string program = dir.write("low.rsp", dapArmProgram(1700));
  const auto session = [&](const Json& filters) {
    return dapArmServe(dapArmRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
                       dapArmRequest(2, "launch", {{"program", program}, {"cell", "gantry-cell"}}) +
                       dapArmRequest(3, "setExceptionBreakpoints", {{"filters", filters}}) +
                       dapArmRequest(4, "configurationDone", Json::object()) +
                       dapArmRequest(5, "evaluate", {{"expression", "Y"}}) +
                       dapArmRequest(6, "evaluate", {{"expression", "clock"}}) +
                       dapArmRequest(7, "continue", {{"threadId", 1}}) +
                       dapArmRequest(8, "disconnect", Json::object()));
  };
  const auto atContact = [](const std::vector<Json>& messages) {
    const Json* y = dapArmResponseTo(messages, 5);
    const Json* clock = dapArmResponseTo(messages, 6);
    REQUIRE(y);
    REQUIRE(clock);
    INFO(y->dump() << clock->dump());
    const int counts = std::stoi(y->at("body").at("result").get<std::string>());
    CHECK(counts >= 1490);
    CHECK(counts <= 1510);  // not 1700, the end of the move
    const double seconds = std::stod(clock->at("body").at("result").get<std::string>());
    CHECK(seconds == Approx(2.8 + counts / 800.0).margin(0.0015));
  };
  SECTION("the collision filter alone: it stops, then the run terminates") {
    const std::vector<Json> messages = session({"collision"});
    const std::vector<Json> stops = dapArmEvents(messages, "stopped");
    REQUIRE(stops.size() == 1);
    CHECK(stops[0]["body"]["reason"] == "exception");
    const std::string text = stops[0]["body"]["text"].get<std::string>();
    INFO(text);
    CHECK(text.find("(collision): ") != std::string::npos);
    CHECK(text.find("hits object 1 (pallet)") != std::string::npos);
    atContact(messages);
    CHECK(dapArmEvents(messages, "terminated").size() == 1);
  }
  SECTION("the runtimeError filter: the run's end, at the contact") {
    const std::vector<Json> messages = session({"runtimeError"});
    const std::vector<Json> stops = dapArmEvents(messages, "stopped");
    REQUIRE(stops.size() >= 1);
    CHECK(stops[0]["body"]["reason"] == "exception");
    CHECK(stops[0]["body"]["text"].get<std::string>().find("runtime error: collision at 4.6") != std::string::npos);
    atContact(messages);
  }
}

TEST_CASE("dap: a close on nothing stops under the warning filter and is said at the step", "[debug][dap][moving-arm]") {
  const rs::testing::TempDir dir;
  const std::string program = dir.write("high.rsp", dapArmProgram(1100));
  const std::string note =
      "the gripper closed on nothing: nearest: block (object 2), its centre 40 below the tool centre point, which is "
      "20 outside its box\n";
  SECTION("the warning filter") {
    const std::vector<Json> messages =
        dapArmServe(dapArmRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
                    dapArmRequest(2, "launch", {{"program", program}, {"cell", "gantry-cell"}}) +
                    dapArmRequest(3, "setExceptionBreakpoints", {{"filters", {"warning", "deadlock"}}}) +
                    dapArmRequest(4, "configurationDone", Json::object()) +
                    dapArmRequest(5, "disconnect", Json::object()));
    const std::vector<Json> stops = dapArmEvents(messages, "stopped");
    REQUIRE(stops.size() == 1);
    CHECK(stops[0]["body"]["reason"] == "exception");
    CHECK(stops[0]["body"]["text"].get<std::string>().find("warning: a gripper closing on nothing") != std::string::npos);
  }
  SECTION("stepping, no filter") {
    const std::vector<Json> messages =
        dapArmServe(dapArmRequest(1, "initialize", {{"adapterID", "robotsim"}}) +
                    dapArmRequest(2, "launch", {{"program", program}, {"cell", "gantry-cell"}, {"stopOnEntry", true}}) +
                    dapArmRequest(3, "configurationDone", Json::object()) +
                    dapArmRequest(4, "stepIn", {{"threadId", 1}}) + dapArmRequest(5, "stepIn", {{"threadId", 1}}) +
                    dapArmRequest(6, "stepIn", {{"threadId", 1}}) + dapArmRequest(7, "disconnect", Json::object()));
    std::vector<std::string> console;
    for (const Json& e : dapArmEvents(messages, "output")) console.push_back(e["body"]["output"].get<std::string>());
    REQUIRE(console.size() == 1);  // once: at the third step, which ran the close
    CHECK(console[0] == note);
    // The output event comes between the third step's response and its stop.
    std::size_t response = 0, output = 0;
    for (std::size_t i = 0; i < messages.size(); ++i) {
      if (messages[i].value("request_seq", -1) == 6) response = i;
      if (messages[i].value("event", "") == "output") output = i;
    }
    CHECK(output > response);
  }
}
