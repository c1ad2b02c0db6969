// The debug adapter against scripted sessions: each tests/debug/dap/NAME.json
// holds what a client sends (requests, or raw bytes for malformed frames)
// and every message the adapter must answer with, in order, exactly
// (responses, events, sequence numbers). They are served in-process by
// dap::serve over streams, as `robotsim dap` serves stdin and stdout.
// "${src}" stands for the source directory in both.
//
// How the expected messages were checked: by hand against the DAP
// specification (a response's request_seq and command, success false with
// a message for every refused request, the stopped event after the
// response of the request that moved the run) and against the programs:
// the lines, call stacks, clocks and values at each stop were worked out
// from the program text and the motor speeds as in
// tests/examples/test_examples.cpp.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <sstream>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/debug/debug_test_util.h"
#include "tests/support/piped_process.h"
#include "tools/dap/serve.h"
#include "tools/wire/framing.h"
#include "tools/wire/json.h"

namespace {

using rs::wire::Json;

const std::string kDapDir = rendertest::kSourceDir + "/tests/debug/dap/";

std::string substituted(std::string text) {
  for (std::size_t at; (at = text.find("${src}")) != std::string::npos;) text.replace(at, 6, rendertest::kSourceDir);
  return text;
}

struct Served {
  std::vector<Json> messages;
  int code = 0;
  std::string log;
};

Served serveBytes(const std::string& bytes) {
  std::istringstream in(bytes);
  std::ostringstream out, log;
  rs::wire::StreamInput input(in);
  rs::wire::StreamOutput output(out);
  Served s;
  s.code = rs::dap::serve(input, output, log);
  for (const rs::wire::Frame& f : rs::wire::parseFrames(out.str())) {
    REQUIRE(f.kind == rs::wire::Frame::Kind::Message);
    s.messages.push_back(Json::parse(f.body));
  }
  s.log = log.str();
  return s;
}

// The source directory back to "${src}", for a rewritten script.
std::string unsubstituted(std::string text) {
  for (std::size_t at; (at = text.find(rendertest::kSourceDir)) != std::string::npos;)
    text.replace(at, rendertest::kSourceDir.size(), "${src}");
  return text;
}

void checkSession(const std::string& name) {
  const std::string path = kDapDir + name + ".json";
  Json script = Json::parse(substituted(rs::testing::readBytes(path)));
  std::string bytes;
  for (const Json& item : script.at("send"))
    bytes += item.is_object() && item.contains("raw") ? item["raw"].get<std::string>()
                                                      : rs::wire::frameMessage(item.dump());
  const Served s = serveBytes(bytes);
  if (std::getenv("ROBOTSIM_UPDATE_GOLDEN")) {
    script["expect"] = s.messages;
    script["exit"] = s.code;
    rs::testing::rewriteGolden(path, unsubstituted(script.dump(1)) + "\n");
    return;
  }
  const Json& expect = script.at("expect");
  INFO(s.log);
  for (std::size_t i = 0; i < std::max(s.messages.size(), expect.size()); ++i) {
    INFO("message " << i);
    REQUIRE(i < s.messages.size());
    REQUIRE(i < expect.size());
    CHECK(s.messages[i].dump(1) == expect[i].dump(1));
  }
  CHECK(s.code == script.value("exit", 0));
}

}  // namespace

TEST_CASE("dap session: launch, breakpoints with conditions and hit counts, stepping, scopes, evaluate",
          "[debug][dap]") {
  checkSession("stepping");
}

TEST_CASE("dap session: stepBack and reverseContinue", "[debug][dap]") { checkSession("reverse"); }

TEST_CASE("dap session: exception breakpoints for deadlock, and the end of the program", "[debug][dap]") {
  checkSession("exceptions");
}

TEST_CASE("dap session: malformed messages and requests in the wrong order get error responses", "[debug][dap]") {
  checkSession("errors");
}

TEST_CASE("dap: a missing or mistyped argument is named without the JSON library's own codes", "[debug][dap]") {
  const std::string program = kDapDir + "../programs/wait_forever.rsp";
  std::string bytes;
  for (const std::string& body :
       {std::string(R"({"seq":1,"type":"request","command":"initialize","arguments":{}})"),
        R"({"seq":2,"type":"request","command":"launch","arguments":{"program":")" + program + R"("}})",
        std::string(R"({"seq":3,"type":"request","command":"setVariable","arguments":{"variablesReference":1,"name":"X"}})"),
        std::string(R"({"seq":4,"type":"request","command":"setVariable","arguments":{"variablesReference":"x","name":"X","value":"1"}})"),
        std::string(R"({"seq":5,"type":"request","command":"disconnect","arguments":{}})")})
    bytes += rs::wire::frameMessage(body);
  const Served s = serveBytes(bytes);
  std::map<int, Json> responses;
  for (const Json& m : s.messages)
    if (m.value("type", "") == "response") responses[m.at("request_seq").get<int>()] = m;
  REQUIRE(responses.count(3) == 1);
  REQUIRE(responses.count(4) == 1);
  CHECK(responses[3].at("message") == "bad arguments for setVariable: key 'value' not found");
  CHECK(responses[4].at("message") == "bad arguments for setVariable: type must be number, but is string");
  REQUIRE(responses.count(5) == 1);
  CHECK(responses[5].at("success") == true);
}

TEST_CASE("dap: a launch argument of the wrong type is named in the error, and the adapter goes on", "[debug][dap]") {
  const std::string program = kDapDir + "../programs/wait_forever.rsp";
  std::string bytes;
  for (const std::string& body :
       {std::string(R"({"seq":1,"type":"request","command":"initialize","arguments":{}})"),
        R"({"seq":2,"type":"request","command":"launch","arguments":{"program":")" + program + R"(","collisions":7}})",
        R"({"seq":3,"type":"request","command":"launch","arguments":{"program":")" + program + R"(","lib":"stdlib"}})",
        R"({"seq":4,"type":"request","command":"launch","arguments":{"program":")" + program + R"(","inputs":[1]}})",
        std::string(R"({"seq":5,"type":"request","command":"disconnect","arguments":{}})")})
    bytes += rs::wire::frameMessage(body);
  const Served s = serveBytes(bytes);
  const std::map<int, std::string> expected{{2, "bad arguments for launch: collisions is a string, not number"},
                                            {3, "bad arguments for launch: lib is a list of strings"},
                                            {4, "bad arguments for launch: inputs is a list of strings"}};
  std::map<int, Json> responses;
  for (const Json& m : s.messages)
    if (m.value("type", "") == "response") responses[m.at("request_seq").get<int>()] = m;
  for (const auto& [seq, message] : expected) {
    CAPTURE(seq);
    REQUIRE(responses.count(seq) == 1);
    CHECK(responses[seq].at("success") == false);
    CHECK(responses[seq].at("message") == message);
  }
  // Still serving: the disconnect after them is answered.
  REQUIRE(responses.count(5) == 1);
  CHECK(responses[5].at("success") == true);
}

TEST_CASE("dap session: a client that leaves during a long run stops it, and the adapter exits 1", "[debug][dap]") {
  checkSession("gone");
}

TEST_CASE("robotsim dap: a client that closes its pipe mid-run ends the process cleanly", "[debug][dap][process]") {
  const rstest::PipedProcess dap = rstest::spawnRobotsim({"dap"});
  signal(SIGPIPE, SIG_IGN);
  // A program that waits for ever in small steps: without the client it
  // would run to the step limit, 100 million instructions.
  const std::string program = kDapDir + "../programs/wait_forever.rsp";
  std::string bytes;
  for (const std::string& body :
       {std::string(R"({"seq":1,"type":"request","command":"initialize","arguments":{}})"),
        R"({"seq":2,"type":"request","command":"launch","arguments":{"program":")" + program + R"(","maxTime":1000000}})",
        std::string(R"({"seq":3,"type":"request","command":"configurationDone"})")})
    bytes += rs::wire::frameMessage(body);
  REQUIRE(write(dap.in, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size()));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  close(dap.in);   // the client is gone: EOF ...
  close(dap.out);  // ... and nobody reads (EPIPE)
  const int status = rstest::waitForExit(dap.pid, 10);
  REQUIRE(status != -1);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
}

TEST_CASE("dap: the end of a run whose gripper never took anything says so on the console", "[debug][dap][grasp]") {
  // Over block 1 of gantry-cell, down 110 (not 149): the gripper closes at
  // line 3 with the tool centre point 40 above the block's centre
  // (tests/runtime/test_empty_close.cpp works it out).
  const rs::testing::TempDir dir;
  const std::string program = dir.write("high.rsp",
                                        "        MOVETO -2800 2800 0 0\n"
                                        "        MOVE 0 0 1100 0\n"
                                        "        MOVE 0 0 0 100\n"
                                        "        END\n");
  const auto request = [](int seq, const std::string& command, Json arguments) {
    return rs::wire::frameMessage(
        Json{{"seq", seq}, {"type", "request"}, {"command", command}, {"arguments", std::move(arguments)}}.dump());
  };
  const Served s = serveBytes(request(1, "initialize", {{"adapterID", "robotsim"}}) +
                              request(2, "launch", {{"program", program}, {"cell", "gantry-cell"}}) +
                              request(3, "configurationDone", Json::object()) +
                              request(4, "disconnect", Json::object()));
  INFO(s.log);
  std::string console;
  for (const Json& m : s.messages)
    if (m.value("event", "") == "output") console += m["body"]["output"].get<std::string>();
  CHECK(console.find("the program ended; warning at line 3: the gripper closed once but never took an object; "
                     "here it closed on nothing with the tool centre point at (220, 90, 680) (nearest: block "
                     "(object 2), its centre 40 below the tool centre point, which is 20 outside its box)\n") !=
        std::string::npos);
}
