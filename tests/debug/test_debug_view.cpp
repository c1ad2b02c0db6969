// robotsim debug --view (tools/cli/lib/debug_view.h): the live-view server
// follows a debugging session. A Console drives the session as a batch
// would; after each command a client (cpp-httplib's, over 127.0.0.1)
// reads /api/state and the test compares it with what the console's own
// `print motors`, `print tcp` and `print clock` say at that moment; going
// back must serve exactly what was served when the run first stood there.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <map>
#include <sstream>

#include "base/seconds.h"
#include "tests/cli/cli_support.h"
#include "tests/debug/debug_test_util.h"
#include "tools/cli/lib/debug_view.h"
#include "tools/debug/console.h"

// Last: its <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

using nlohmann::json;

struct Viewed {
  rs::debug::DebugSession session;
  std::ostringstream out;
  rs::debug::Console console{session, nullptr, out};
  std::shared_ptr<rs::cli::DebugView> view;
  int port = 0;
  std::string token;

  explicit Viewed(const std::string& program = "gantry_pick.rsp", const std::string& cell = "gantry-cell")
      : session(debugtest::specOnCell(program, cell)) {
    std::string error;
    view = rs::cli::DebugView::start(session, program, error);
    INFO(error);
    REQUIRE(view);
    const std::string url = view->url();  // http://127.0.0.1:PORT/?token=TOKEN
    const std::size_t colon = url.rfind(':'), slash = url.find('/', colon), eq = url.find('=');
    REQUIRE(url.starts_with("http://127.0.0.1:"));
    port = std::stoi(url.substr(colon + 1, slash - colon - 1));
    token = url.substr(eq + 1);
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port);
    c.set_read_timeout(5, 0);
    return c;
  }
  json state() const {
    auto res = client().Get("/api/state?token=" + token);
    REQUIRE(res);
    REQUIRE(res->status == 200);
    return json::parse(res->body);
  }
  std::string run(const std::string& line) {
    out.str("");
    REQUIRE(console.execute(line));
    return out.str();
  }
};

// `print motors` as numbers: "X = -2800" per line, in the motors' order.
std::vector<std::int64_t> printedMotors(const std::string& text) {
  std::vector<std::int64_t> values;
  std::istringstream lines(text);
  std::string letter, equals;
  std::int64_t value = 0;
  while (lines >> letter >> equals >> value) values.push_back(value);
  return values;
}

// The state checked against the console's own answers at this moment.
void checkAgainstConsole(Viewed& v, const json& s) {
  CHECK(s["encoders"].get<std::vector<std::int64_t>>() == printedMotors(v.run("print motors")));
  const json& tcp = s["tcp"];
  REQUIRE(tcp.size() == 3);
  CHECK(v.run("print tcp") == fmt::format("tcp = ({:.3f}, {:.3f}, {:.3f})\n", tcp[0].get<double>(), tcp[1].get<double>(),
                                          tcp[2].get<double>()));
  CHECK(v.run("print clock") == fmt::format("clock = {} s (step {})\n",
                                            rs::base::formatSeconds(s["clock"].get<rs::vm::Micros>()),
                                            s["steps"].get<std::uint64_t>()));
}

// What the page draws, without what says how it got there.
json moment(json s) {
  s.erase("revision");
  s.erase("message");
  return s;
}

}  // namespace

TEST_CASE("debug --view serves the stopped moment after every command, forwards and backwards", "[debug][view]") {
  Viewed v;
  json s = v.state();
  CHECK(s["readOnly"] == true);
  CHECK(s["steps"] == 0);
  CHECK(s["message"] == "at the start of the run");
  checkAgainstConsole(v, s);
  std::uint64_t revision = s["revision"];
  std::map<std::uint64_t, json> seen;  // by step
  seen[0] = moment(s);
  v.run("break place");
  for (const std::string command : {"step", "step", "step", "step 2", "continue", "step 3"}) {
    INFO(command);
    v.run(command);
    s = v.state();
    CHECK(s["revision"].get<std::uint64_t>() > revision);
    revision = s["revision"];
    checkAgainstConsole(v, s);
    seen[s["steps"]] = moment(s);
    if (command == "continue") {
      // At label place the gripper holds block 1 (the pallet is object 0).
      CHECK(s["objects"][1]["held"] == true);
      const std::string objects = v.run("print objects");
      const std::size_t second = objects.find("\n2 block at");
      REQUIRE(second != std::string::npos);
      CHECK(objects.substr(second, objects.find('\n', second + 1) - second).ends_with(", held, moved"));
    }
  }
  REQUIRE(seen.size() == 7);
  // Back: each moment is served as it was served going forwards.
  for (const std::string command : {"reverse-step", "reverse-step 2", "reverse-continue", "goto-time 0"}) {
    INFO(command);
    v.run(command);
    s = v.state();
    CHECK(s["revision"].get<std::uint64_t>() > revision);
    revision = s["revision"];
    checkAgainstConsole(v, s);
    const std::uint64_t steps = s["steps"];
    if (seen.count(steps)) CHECK(moment(s) == seen[steps]);
  }
  // goto-time 0 stands at 0 s exactly: before the first instruction, as
  // the session stood at its start (the first move starts at 0 s).
  CHECK(s["steps"] == 0);
  CHECK(moment(s) == seen[0]);
}

TEST_CASE("debug --view: set input shows at once, the page refuses commands, the token is needed",
          "[debug][view]") {
  Viewed v;
  v.run("step");
  CHECK(v.state()["inputs"][2] == false);
  v.run("set input 3 on");
  const json s = v.state();
  CHECK(s["inputs"][2] == true);
  CHECK(s["message"] == "step done");  // the same stop, another input
  // Read-only: a jog is refused with 403 and a message the page shows.
  auto res = v.client().Post("/api/command?token=" + v.token, R"({"op":"jog","motor":0,"delta":10})",
                             "application/json");
  REQUIRE(res);
  CHECK(res->status == 403);
  const json reply = json::parse(res->body);
  CHECK(reply["ok"] == false);
  CHECK(reply["message"].get<std::string>().find("read-only") != std::string::npos);
  CHECK(v.state()["encoders"] == s["encoders"]);  // nothing moved
  // No token, no state; the page is the read-only one.
  auto denied = v.client().Get("/api/state");
  REQUIRE(denied);
  CHECK(denied->status == 403);
  auto page = v.client().Get("/?token=" + v.token);
  REQUIRE(page);
  CHECK(page->body.find("\"readOnly\":true") != std::string::npos);
}

TEST_CASE("debug --view needs a workcell", "[debug][view]") {
  rs::debug::DebugSession session(debugtest::specOf("        END\n"));
  std::string error;
  CHECK_FALSE(rs::cli::DebugView::start(session, "program.rsp", error));
  CHECK(error.find("--cell") != std::string::npos);
}

TEST_CASE("robotsim debug --view prints the page's address, and without a workcell exits 2", "[debug][view]") {
  rs::testing::TempDir dir;
  const std::string quit = dir.write("quit.txt", "quit\n");  // -x: stdin is never read
  const rs::testing::CliResult viewed =
      rs::testing::runCli({"debug", debugtest::kExamples + "gantry_pick.rsp", "--cell", "gantry-cell", "--view", "-x", quit});
  CHECK(viewed.code == 0);
  CHECK(viewed.out.find("\nlive view: http://127.0.0.1:") != std::string::npos);
  const rs::testing::CliResult bare =
      rs::testing::runCli({"debug", rendertest::kSourceDir + "/tests/debug/programs/wait_forever.rsp", "--view", "-x", quit});
  CHECK(bare.code == 2);
  CHECK(bare.err.find("--view draws the workcell: give one with --cell CELL") != std::string::npos);
  const rs::testing::CliResult open = rs::testing::runCli({"debug", quit, "--open"});
  CHECK(open.code == 2);  // --open needs --view
}

TEST_CASE("debug --view shows the cell's devices where the run stopped", "[debug][view][devices]") {
  Viewed v("adept_production.rsp", "adept-cell");
  const json before = v.state().at("devices");
  REQUIRE(before.at("sensors").size() == 1);
  CHECK(before.at("sensors")[0].at("name") == "eye");
  CHECK(before.at("sensors")[0].at("on") == false);
  CHECK(before.at("sensors")[0].at("count") == 0);
  v.run("break sensor eye on");
  v.run("continue");
  // What `print devices` says at this stop: the sensor ON once, the infeed
  // running with the parts it carried.
  const std::string printed = v.run("print devices");
  INFO(printed);
  REQUIRE(printed.find("sensor eye         ON, turned ON 1 time\n") != std::string::npos);
  const json after = v.state().at("devices");
  CHECK(after.at("sensors")[0].at("on") == true);
  CHECK(after.at("sensors")[0].at("count") == 1);
  bool infeed = false;
  for (const json& c : after.at("conveyors"))
    if (c.at("name") == "infeed") {
      infeed = true;
      CHECK(c.at("running") == true);
      CHECK(printed.find(fmt::format("conveyor infeed    running, carried {} parts", c.at("carried").get<int>())) !=
            std::string::npos);
    }
  CHECK(infeed);
  // Back to the start: the devices as they were.
  v.run("reverse-continue");
  v.run("goto-time 0");
  CHECK(v.state().at("devices").at("sensors")[0].at("count") == 0);
}
