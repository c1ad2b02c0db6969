// A cell of several robots, each on its own controller (run --cell CELL
// --device LABEL=DEV ...): examples/two_robots/interlock.rsd, two Rhino
// XR-4s whose outputs 1 are wired to each other's inputs 1, run with both
// robots on emulated controllers. The expected commands are derived from
// left.rsp and right.rsp by hand (Mark IV: a move is "PD,<motor>,<target>"
// for each motor that moves, then "MC"; OUTSIG n ON/OFF is "OB,n,1"/"OB,n,0";
// WAITFOR is the cell's, not the controller's): each robot twice reaches in
// (F to 300), comes back (F to 0), turns output 1 ON, then OFF.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <chrono>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include "runtime/rhino/interrupt.h"

#include "compiler/description/library.h"
#include "runtime/run/cell_run.h"
#include "tests/cli/cli_support.h"
#include "tests/render/render_test_util.h"
#include "tests/rhino/serial_support.h"
#include "tests/runtime/cell_spec_support.h"

namespace {

using namespace rs::rhino;
using rs::testing::runCli;
using rs::testing::TempDir;

const std::string kInterlock = rendertest::kSourceDir + "/examples/two_robots/interlock.rsd";
const std::string kXr4 = rendertest::kSourceDir + "/stdlib/robots/rhino-xr4.rsd";

const std::vector<std::string> kEachRobotSends = {"PD,F,300", "PD,F,0", "OB,1,1", "OB,1,0",
                                                  "PD,F,300", "PD,F,0", "OB,1,1", "OB,1,0"};

std::vector<rs::vm::MotorSpec> xr4Motors() {
  rs::compiler::Library library(rs::compiler::librarySearchPath({}));
  const std::optional<rs::workcell::Robot> robot = library.robot(kXr4);
  REQUIRE(robot);
  return rs::compiler::motorTable(*robot);
}

// The moves and outputs a controller was given (its polls and queries left out).
std::vector<std::string> movesAndOutputs(const std::vector<std::string>& received) {
  std::vector<std::string> out;
  for (const std::string& c : received)
    if (c.starts_with("PD,") || c.starts_with("OB,")) out.push_back(c);
  return out;
}

// What the emulator on its thread has received once the last commands the
// run wrote (outputs, which are not answered) have reached it: at most 5 s.
std::vector<std::string> settledMovesAndOutputs(PtyEmulator& emu, std::size_t expected) {
  std::vector<std::string> got;
  for (int i = 0; i < 500; ++i) {
    got = movesAndOutputs(emu.received());
    if (got.size() >= expected) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return got;
}

std::unique_ptr<PtyEmulator> xr4Emulator(FaultPlan fault = {}, double rateScale = 20) {
  EmulatorConfig c;
  c.settings = defaultSettings(Dialect::Mark4);
  c.motors = xr4Motors();
  c.rateScale = rateScale;
  c.fault = fault;
  std::string error;
  auto emu = PtyEmulator::open(c, error);
  INFO(error);
  REQUIRE(emu);
  emu->start();
  return emu;
}

// A robot of a test cell: "MODEL AT x y z", its label, its program's text.
struct TestRobot {
  std::string placed, label, program;
};

// cell.rsd in `dir`: the two robots, each with its program (LABEL.rsp).
std::string writeTwoRobotCell(TempDir& dir, const TestRobot& first, const TestRobot& second) {
  std::string text = "WORKCELL pair\n";
  for (const TestRobot* r : {&first, &second}) {
    text += "  ROBOT " + r->placed + " AS " + r->label + " PROGRAM " + r->label + ".rsp\n";
    dir.write(r->label + ".rsp", r->program);
  }
  return dir.write("cell.rsd", text + "END\n");
}

nlohmann::json cellSummary(const std::string& out) { return nlohmann::json::parse(out); }

// Both robots of the interlock cell on in-process controllers on manual
// clocks: each controller's serial log, and where the cell ended.
struct FollowedInterlock {
  std::vector<std::string> logs;
  rs::vm::RunOutcome outcome;
  std::vector<std::vector<std::int32_t>> motors;
  std::vector<std::vector<std::int32_t>> variables;
};

// The steps a Mark III host sent motor F ("F+95", "F-40", ...), added up
// by sign: the interlock's robots each reach in twice (2 x 300 forward,
// 2 x 300 back), in whatever chunks the polls let the host send.
std::pair<int, int> mark3StepsOfF(const std::vector<std::string>& received) {
  int forward = 0, back = 0;
  for (const std::string& c : received)
    if (c.size() > 2 && c[0] == 'F' && (c[1] == '+' || c[1] == '-')) (c[1] == '+' ? forward : back) += std::stoi(c.substr(2));
  return {forward, back};
}

FollowedInterlock runFollowed(bool followed, Dialect dialect = Dialect::Mark4) {
  const RhinoSettings settings = rs::rhino::testing::testSettings(dialect);
  const std::vector<rs::vm::MotorSpec> motors = xr4Motors();
  std::vector<std::unique_ptr<rs::rhino::testing::LoopbackRig>> rigs;
  rs::runtime::CellRunSpec spec = rs::testing::cellRunSpecOf(kInterlock);
  FollowedInterlock r;
  {
    for (auto& p : spec.programs) {
      if (!followed) break;
      rigs.push_back(std::make_unique<rs::rhino::testing::LoopbackRig>(
          settings, motors, rs::rhino::testing::emulatorFor(settings, motors)));
      REQUIRE(rigs.back()->machine.open());
      p.follower = &rigs.back()->machine;
    }
    rs::runtime::CellRun cell(spec);
    r.outcome = cell.runToEnd();
    for (std::size_t p = 0; p < cell.size(); ++p) {
      const auto pos = cell.robot(p).rig().machine().positions();
      r.motors.emplace_back(pos.begin(), pos.end());
      const auto vars = cell.robot(p).interpreter().variables();
      r.variables.emplace_back(vars.begin(), vars.end());
    }
  }
  for (auto& rig : rigs) {
    const std::vector<std::string> received(rig->engine.received().begin(), rig->engine.received().end());
    if (dialect == Dialect::Mark4) CHECK(movesAndOutputs(received) == kEachRobotSends);
    else CHECK(mark3StepsOfF(received) == std::pair<int, int>{600, 600});
    r.logs.push_back(rig->logText.str());
  }
  return r;
}

}  // namespace

TEST_CASE("a cell run with each robot on its own controller ends as the simulated one, with the same logs every run",
          "[serial][cell-run]") {
  const FollowedInterlock simulated = runFollowed(false);
  INFO(simulated.outcome.message);
  REQUIRE(simulated.outcome.ok());
  const FollowedInterlock first = runFollowed(true);
  INFO(first.outcome.message);
  REQUIRE(first.outcome.ok());
  CHECK(first.motors == simulated.motors);
  CHECK(first.variables == simulated.variables);
  const FollowedInterlock second = runFollowed(true);
  REQUIRE(second.logs.size() == 2);
  CHECK(second.logs == first.logs);  // byte for byte: each controller on its own manual clock
  CHECK_THAT(first.logs[0], Catch::Contains("\"PD,F,300\\r\""));
  // The same on the Mark III, which is fed in chunks and polled.
  const FollowedInterlock mark3 = runFollowed(true, Dialect::Mark3);
  INFO(mark3.outcome.message);
  REQUIRE(mark3.outcome.ok());
  CHECK(mark3.motors == simulated.motors);
  CHECK(runFollowed(true, Dialect::Mark3).logs == mark3.logs);
}

TEST_CASE("robotsim run --cell --device LABEL=DEV drives one controller a robot, in lock-step with the cell",
          "[serial][cell-run]") {
  TempDir dir;
  const auto sim = runCli({"run", "--cell", kInterlock, "--format", "json"});
  INFO(sim.err);
  REQUIRE(sim.code == 0);
  auto left = xr4Emulator();
  auto right = xr4Emulator();
  const std::string leftLog = (dir.path() / "left.log").string();
  const std::string rightLog = (dir.path() / "right.log").string();
  const auto real = runCli({"run", "--cell", kInterlock, "--format", "json", "--dialect", "mark4", "--device",
                            "left=" + left->path(), "--device", "right=" + right->path(), "--log-serial",
                            "left=" + leftLog, "--log-serial", "right=" + rightLog, "--serial-set", "timeout=0.5"});
  INFO(real.err);
  REQUIRE(real.code == 0);
  // The summary is the cell's, on its one clock: the simulated run's. The
  // right robot only moves once the wire from the left's output 1 says so:
  // had the wire not worked, the run would have ended in a deadlock.
  CHECK(cellSummary(real.out) == cellSummary(sim.out));
  CHECK(cellSummary(real.out)["robots"][1]["variables"]["TURNS"] == 2);  // right.rsp's two turns, each on the wire
  CHECK(settledMovesAndOutputs(*left, kEachRobotSends.size()) == kEachRobotSends);
  CHECK(settledMovesAndOutputs(*right, kEachRobotSends.size()) == kEachRobotSends);
  CHECK(left->snapshot().outputs == 0);
  CHECK(right->snapshot().motors[5].position == 0);  // F back at 0
  std::ifstream in(leftLog);
  std::string header;
  std::getline(in, header);
  CHECK_THAT(header, Catch::StartsWith("# robotsim serial log: mark4 on " + left->path()));
  CHECK(std::filesystem::file_size(rightLog) > 0);
}

TEST_CASE("robotsim run --cell --device: mistakes are refused before anything is opened", "[serial][cell-run]") {
  TempDir dir;
  auto emu = xr4Emulator();
  const std::string dev = emu->path();
  const auto refused = [&](std::vector<std::string> devices, const std::string& message, const std::string& hint) {
    std::vector<std::string> args = {"run", "--cell", kInterlock, "--dialect", "mark4"};
    for (const std::string& d : devices) args.push_back("--device"), args.push_back(d);
    const auto r = runCli(args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--device: error: " + message));
    CHECK_THAT(r.err, Catch::Contains("hint: " + hint));
  };
  refused({"middle=" + dev}, "workcell interlock has no robot labelled `middle`", "the cell's robots are `left`, `right`");
  refused({dev}, "'" + dev + "' names no robot: a cell of several robots takes --device LABEL=DEVICE",
          "the cell's robots are `left`, `right`");
  refused({"left=" + dev, "left=/dev/null"}, "robot left is given two devices",
          "one controller a robot: give each robot's label once");
  refused({"left=" + dev, "right=" + dev}, "robots left and right are given the same device " + dev,
          "each robot drives its own controller");
  CHECK(emu->received().empty());  // nothing was sent to the controller

  // A run of one robot's program drives one controller.
  const std::string prog = dir.write("one.rsp", "MOVE 10 0 0 0 0 0\nEND\n");
  const auto one = runCli({"run", prog, "--device", dev, "--device", "/dev/null"});
  CHECK(one.code == 2);
  CHECK_THAT(one.err, Catch::Contains("--device: error: a run of one robot drives one controller"));

  // A robot that is not a Rhino: the gantry's motors are X, Y, Z.
  const std::string cell = writeTwoRobotCell(dir, {"rhino-xr4 AT 0 750 0", "arm", "MOVE 10 0 0 0 0 0\nEND\n"},
                                             {"gantry AT 3000 0 0", "crane", "DELAY 0.1\nEND\n"});
  const auto gantry = runCli({"run", "--cell", cell, "--device", "crane=" + dev});
  INFO(gantry.err);
  CHECK(gantry.code == 2);
  CHECK_THAT(gantry.err, Catch::Contains("--device: error: robot crane (gantry) cannot run on a Rhino controller"));
  CHECK_THAT(gantry.err, Catch::Contains("hint: only a robot whose motors are a Rhino controller's (A..H)"));
}

TEST_CASE("robotsim run --cell --device: a regular file or a FIFO is no controller", "[serial][cell-run]") {
  TempDir dir;
  const std::string file = dir.write("not-a-port", "");
  const std::string fifo = (dir.path() / "fifo").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  for (const std::string& path : {file, fifo}) {
    const auto r = runCli({"run", "--cell", kInterlock, "--device", "left=" + path});
    INFO(r.err);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("robotsim: error: " + path + " is not a serial device (not a terminal)"));
  }
}

TEST_CASE("robotsim emulate --controllers 2 plays two controllers, each on its own terminal", "[serial]") {
  const auto r = runCli({"emulate", "--controllers", "2", "--robot", kXr4, "--dialect", "mark4", "--duration",
                         "0.1", "--no-stdin", "--quiet"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::istringstream lines(r.out);
  std::string line;
  std::getline(lines, line);
  CHECK(line == "2 Rhino Mark IV controller emulators:");
  std::vector<std::string> paths;
  for (int k = 1; k <= 2; ++k) {
    std::getline(lines, line);
    const std::string prefix = "controller " + std::to_string(k) + " on /dev/";
    CHECK_THAT(line, Catch::StartsWith(prefix));
    paths.push_back(line.substr(std::string("controller 1 on ").size()));
  }
  CHECK(paths[0] != paths[1]);
  CHECK_THAT(r.out, Catch::Contains("connect: robotsim run --cell CELL --device LABEL1=" + paths[0] +
                                    " --device LABEL2=" + paths[1] + " --dialect mark4"));
  // A console line "K: COMMAND" is for controller K; one without, for controller 1.
  TempDir dir;
  const std::string script = dir.write("two.txt", "2: in 3 on\nin 1 on\n3: status\n");
  const auto typed = runCli({"emulate", "--controllers", "2", "--script", script, "--duration", "0.3", "--no-stdin"});
  INFO(typed.err);
  CHECK_THAT(typed.out, Catch::Contains(script + ":3: '3: status': K: COMMAND names a controller 1..2"));
  CHECK_THAT(typed.out, Catch::Contains("controller 1: emulator stopped: "));
  CHECK_THAT(typed.out, Catch::Contains("| in 1....... |"));
  CHECK_THAT(typed.out, Catch::Contains("| in ..3..... |"));
  const auto bad = runCli({"emulate", "--controllers", "0", "--duration", "0.1", "--no-stdin"});
  CHECK(bad.code != 0);
  CHECK_THAT(bad.err, Catch::Contains("--controllers"));
}

TEST_CASE("robotsim run --cell --device: a controller that fails stops the cell at its robot's move", "[serial][cell-run]") {
  // The handshake (TH, SE, PA for each of the six motors) and the first
  // move's PD,F,300 and MI are answered; the first "SA" (is it done?) is not.
  auto left = xr4Emulator({FaultKind::Silence, 10, 0});
  const auto r = runCli({"run", "--cell", kInterlock, "--dialect", "mark4", "--device", "left=" + left->path(),
                         "--serial-set", "timeout=0.2"});
  INFO(r.err);
  CHECK(r.code == 1);
  // left.rsp's line 7 is its first MOVE; the right robot, simulated, is stopped with the cell.
  CHECK_THAT(r.err, Catch::Contains("left.rsp:7:9: error: runtime error: no reply from the controller to \"SA\""));
  CHECK_THAT(r.err, Catch::Contains("stop sent to every motor (MA)"));
  CHECK_THAT(r.err, Catch::Contains("hint: robot left stopped the cell"));
  CHECK_THAT(r.out, Catch::Contains("robot right: "));
  CHECK_THAT(r.out, Catch::Contains("stopped at line 5"));
}

TEST_CASE("a second Ctrl-C writes the stop to every controller of a cell run", "[serial][cell-run]") {
  // Two guards, one a controller, as a cell run of two robots on devices
  // has (launch/rhino.cpp): pipes stand in for the two ports.
  int left[2], right[2];
  REQUIRE(::pipe(left) == 0);
  REQUIRE(::pipe(right) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    InterruptGuard a, b;
    a.setEmergencyStop(left[1], "MA\r");
    b.setEmergencyStop(right[1], "FX\rEX\r");
    ::raise(SIGINT);
    ::raise(SIGINT);  // exits 130 after writing both
    ::_exit(1);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  const auto readAll = [](int fd) {
    char buf[64];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    return std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
  };
  ::close(left[1]), ::close(right[1]);
  CHECK(readAll(left[0]) == "MA\r");
  CHECK(readAll(right[0]) == "FX\rEX\r");
  ::close(left[0]), ::close(right[0]);
}

TEST_CASE("robotsim run --cell --device: the cell does not pass a move's end before the controller is done",
          "[serial][cell-run]") {
  // Robot a's move of 300 steps ends at 1 s on the cell's clock (F at its
  // description's 300 steps/s), and takes its controller 1 s too (the
  // emulator at the robot's speeds). Robot b waits 1.5 s of the cell's
  // clock, then moves: lock-step holds the cell at 1 s until a's controller
  // is done, so b's move reaches b's controller a second after the start,
  // not at once (the cell's clock alone runs through 1.5 s in microseconds).
  TempDir dir;
  const std::string cell = writeTwoRobotCell(dir, {"rhino-xr4 AT 0 750 0", "a", "MOVE 300 0 0 0 0 0\nEND\n"},
                                             {"rhino-xr4 AT 3000 750 0", "b", "DELAY 1.5\nMOVE 10 0 0 0 0 0\nEND\n"});
  auto a = xr4Emulator({}, 1);
  auto b = xr4Emulator({}, 20);
  const std::string bLog = (dir.path() / "b.log").string();
  const auto r = runCli({"run", "--cell", cell, "--dialect", "mark4", "--device", "a=" + a->path(), "--device",
                         "b=" + b->path(), "--log-serial", "b=" + bLog});
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::ifstream in(bLog);
  double sentAt = -1;  // b's log: "   1.012345 > ... "PD,F,10\r""
  for (std::string line; std::getline(in, line);)
    if (line.find("\"PD,F,10\\r\"") != std::string::npos) sentAt = std::stod(line);
  INFO(rs::testing::readBytes(bLog));
  CHECK(sentAt > 0.8);
}
