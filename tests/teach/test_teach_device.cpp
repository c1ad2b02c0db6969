// The teach pendant with a device: `robotsim emulate`'s engine on a real
// pseudo-terminal (runtime/rhino/emulator.h), opened the way `robotsim
// teach --device` opens it (teach::openPendant), driven through the live
// server's HTTP API as the page drives it. After a series of jogs the
// emulator's motors stand where the page says; a controller that falls
// silent during a jog stops every motor, the state carries the fault, and
// nothing more is sent.
#include <catch2/catch.hpp>

#include <thread>

#include "../render/render_test_util.h"
#include "launch/program.h"
#include "runtime/rhino/emulator.h"
#include "tests/cli/cli_support.h"
#include "tools/live/live_server.h"
#include "tools/teach/page.h"
#include "tools/teach/pendant_source.h"
#include "tools/teach/open_pendant.h"

// Last: its <resolv.h> defines _res, a name Eigen's headers use.
#include <httplib.h>

namespace {

using nlohmann::json;
using rs::rhino::Dialect;

struct DeviceRig {
  rs::testing::TempDir dir;
  std::string path = dir.write("p.rsp", "        END\nPOINTS\n");
  std::unique_ptr<rs::rhino::PtyEmulator> emulator;
  rs::teach::OpenedPendant opened;
  std::unique_ptr<rs::teach::PendantSource> source;
  std::unique_ptr<rs::live::LiveServer> server;
  std::vector<rs::vm::MotorSpec> motors;

  DeviceRig(Dialect dialect, std::array<std::int32_t, 8> start = {}) {
    const rs::workcell::Workcell cell = rendertest::cell("scara-pick");
    motors = rs::launch::cellTarget(cell).motors;
    rs::rhino::EmulatorConfig c;
    c.settings = rs::rhino::defaultSettings(dialect);
    c.motors = motors;
    c.rateScale = 10;  // the moves take a tenth of the robot's time
    c.start = start;
    std::string error;
    emulator = rs::rhino::PtyEmulator::open(c, error);
    REQUIRE(emulator);
    emulator->start();
    rs::teach::TeachRequest request;
    request.program.file = path;
    request.program.cell = "scara-pick";
    request.serial.device = emulator->path();
    request.serial.dialect = dialect == Dialect::Mark3 ? "mark3" : "mark4";
    request.serial.settings = {"timeout=0.2"};
    opened = rs::teach::openPendant(request);
    for (const auto& d : opened.diagnostics) INFO(d.message);
    REQUIRE(opened.ok());
    source = std::make_unique<rs::teach::PendantSource>(*opened.pendant,
                                                        rs::teach::teachPageHtml(opened.pendant->cell(), path));
    server = std::make_unique<rs::live::LiveServer>(*source, rs::live::randomToken());
    REQUIRE(server->start("127.0.0.1", 0, error));
  }
  ~DeviceRig() {
    server.reset();
    source.reset();
    opened.pendant.reset();  // closes the port before the emulator goes
    emulator->stop();
  }
  json command(const json& c) {
    httplib::Client client("127.0.0.1", server->port());
    client.set_read_timeout(10, 0);
    const auto r = client.Post("/api/command?token=" + server->token(), c.dump(), "application/json");
    REQUIRE(r);
    return json::parse(r->body);
  }
  json state() {
    httplib::Client client("127.0.0.1", server->port());
    return json::parse(client.Get("/api/state?token=" + server->token())->body);
  }
  // The emulator's motors in the robot's order.
  std::vector<std::int32_t> emulated() {
    const rs::rhino::EmulatorSnapshot s = emulator->snapshot();
    std::vector<std::int32_t> out;
    for (const rs::vm::MotorSpec& m : motors) out.push_back(s.motors[static_cast<std::size_t>(m.letter - 'A')].position);
    return out;
  }
};

}  // namespace

TEST_CASE("teach --device: after a series of jogs the emulator's motors stand where the page says", "[teach]") {
  for (const Dialect dialect : {Dialect::Mark3, Dialect::Mark4}) {
    INFO((dialect == Dialect::Mark3 ? "mark3" : "mark4"));
    DeviceRig rig(dialect);
    for (const auto& [motor, delta] : {std::pair{0, 40}, {1, -25}, {0, 10}, {2, 30}, {4, 12}, {3, -7}}) {
      const json r = rig.command({{"op", "jog"}, {"motor", motor}, {"delta", delta}});
      CHECK(r["ok"] == true);
    }
    const json state = rig.state();
    CHECK(state["encoders"] == json({50, -25, 30, -7, 12}));
    CHECK(state["device"] == rig.emulator->path());
    CHECK(rig.emulated() == std::vector<std::int32_t>{50, -25, 30, -7, 12});
    CHECK(state["fault"] == "");
    const json read = rig.command({{"op", "readPosition"}});
    CHECK(read["ok"] == true);
    CHECK(read["message"] == (dialect == Dialect::Mark3 ? "a Mark III cannot report its encoders: the counts are those "
                                                          "tracked since teach started, 50 -25 30 -7 12"
                                                        : "read from the controller: 50 -25 30 -7 12"));
    // Soft limits first: nothing beyond a range reaches the line.
    const std::uint64_t before = rig.emulator->snapshot().commands;
    CHECK(rig.command({{"op", "set"}, {"motor", 2}, {"value", 351}})["ok"] == false);
    CHECK(rig.emulator->snapshot().commands == before);
    // Inputs are the controller's: the pendant cannot switch them, and
    // reads them after every move.
    CHECK(rig.command({{"op", "input"}, {"line", 1}})["ok"] == false);
    rig.emulator->setInput(3, true);
    CHECK(rig.state()["inputs"][2] == false);
    REQUIRE(rig.command({{"op", "jog"}, {"motor", 0}, {"delta", -1}})["ok"] == true);
    CHECK(rig.state()["inputs"] == json({false, false, true, false, false, false, false, false}));
  }
}

TEST_CASE("teach --device: read position takes the controller's counts", "[teach]") {
  // A Mark IV reports its encoders: the pendant starts where the robot
  // stands (E at 60, D at -30) and reads them again on request.
  DeviceRig rig(Dialect::Mark4, {0, 0, 0, -30, 60, 0, 0, 0});  // A..H: D is index 3, E index 4
  CHECK(rig.state()["encoders"] == json({60, -30, 0, 0, 0}));
  REQUIRE(rig.command({{"op", "jog"}, {"motor", 0}, {"delta", 5}})["ok"] == true);
  const json r = rig.command({{"op", "readPosition"}});
  CHECK(r["ok"] == true);
  CHECK(r["message"] == "read from the controller: 65 -30 0 0 0");
  CHECK(rig.emulated() == std::vector<std::int32_t>{65, -30, 0, 0, 0});
}

TEST_CASE("teach --device: a controller silent during a jog stops everything and the state says so", "[teach]") {
  for (const Dialect dialect : {Dialect::Mark3, Dialect::Mark4}) {
    INFO((dialect == Dialect::Mark3 ? "mark3" : "mark4"));
    DeviceRig rig(dialect);
    REQUIRE(rig.command({{"op", "jog"}, {"motor", 0}, {"delta", 20}})["ok"] == true);
    // Silent from the jog's second command on: the move is sent, its
    // progress is never reported.
    rig.emulator->setFault({rs::rhino::FaultKind::Silence, 1});  // counted from now
    const json r = rig.command({{"op", "jog"}, {"motor", 0}, {"delta", 300}});
    CHECK(r["ok"] == false);
    const json state = rig.state();
    const std::string fault = state["fault"];
    CHECK_THAT(fault, Catch::Contains("no reply from the controller"));
    CHECK(state["failed"] == true);
    // Every motor stopped: none runs, and they stay where they stopped.
    const std::vector<std::int32_t> stopped = rig.emulated();
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    CHECK(rig.emulated() == stopped);
    const rs::rhino::EmulatorSnapshot s = rig.emulator->snapshot();
    for (const auto& m : s.motors) {
      CHECK_FALSE(m.running);
      CHECK(m.registerSteps == 0);
    }
    // Nothing more is sent: every move is refused at once.
    const std::uint64_t commands = s.commands;
    const json again = rig.command({{"op", "jog"}, {"motor", 1}, {"delta", 5}});
    CHECK(again["ok"] == false);
    CHECK_THAT(again["message"].get<std::string>(), Catch::StartsWith("the device failed, nothing is sent"));
    CHECK(rig.command({{"op", "gripper"}, {"close", true}})["ok"] == false);
    CHECK(rig.emulator->snapshot().commands == commands);
  }
}
