// The serial commands through `robotsim` itself (in-process): run --device
// on the emulator, the errors a user meets, ports, emulate.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "stdlib/default_robot.h"
#include "tests/cli/cli_support.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using rs::testing::runCli;
using rs::testing::TempDir;

const char* const kSerialCliProgram =
    "SET N 3\n"
    "MOVETO 200 -100 50 20 60\n"
    "OUTSIG 1 ON\n"
    "MOVE -50 10 0 0 -20\n"
    "JMPIN 4 ON done\n"
    "ADD N 1\n"
    "done: HRDHOME\n"
    "END\n";

nlohmann::json summary(const std::string& out) {
  const auto start = out.rfind("\n{");
  return nlohmann::json::parse(start == std::string::npos ? out : out.substr(start + 1));
}

std::unique_ptr<PtyEmulator> emulator(Dialect d, FaultKind fault = FaultKind::None) {
  EmulatorConfig c;
  c.settings = defaultSettings(d);
  c.motors = rs::stdlib::rhinoScaraMotors();  // the default robot
  c.rateScale = 5;
  c.fault = {fault, 4, 3'000'000};
  std::string error;
  auto emu = PtyEmulator::open(c, error);
  REQUIRE(emu);
  emu->start();
  return emu;
}

}  // namespace

TEST_CASE("robotsim run --device ends like robotsim run, and logs the bytes", "[serial]") {
  TempDir dir;
  const std::string prog = dir.write("prog.rsp", kSerialCliProgram);
  const auto sim = runCli({"run", prog, "--format", "json"});
  REQUIRE(sim.code == 0);
  for (const char* dialect : {"mark3", "mark4"}) {
    auto emu = emulator(std::string(dialect) == "mark3" ? Dialect::Mark3 : Dialect::Mark4);
    const std::string log = (dir.path() / (std::string(dialect) + ".log")).string();
    const auto real = runCli({"run", prog, "--format", "json", "--device", emu->path(), "--dialect", dialect,
                              "--log-serial", log, "--serial-set", "timeout=0.3"});
    INFO(real.err);
    REQUIRE(real.code == 0);
    const auto a = summary(sim.out);
    const auto b = summary(real.out);
    CHECK(a["motors"] == b["motors"]);
    CHECK(a["outputs"] == b["outputs"]);
    CHECK(a["variables"] == b["variables"]);
    std::ifstream in(log);
    std::string first;
    std::getline(in, first);
    CHECK_THAT(first, Catch::StartsWith(std::string("# robotsim serial log: ") + dialect + " on /dev/"));
  }
}

TEST_CASE("robotsim run --device: a failing controller exits 1 after stopping the motors", "[serial]") {
  TempDir dir;
  const std::string prog = dir.write("prog.rsp", kSerialCliProgram);
  auto emu = emulator(Dialect::Mark3, FaultKind::Silence);
  const auto r = runCli({"run", prog, "--device", emu->path(), "--serial-set", "timeout=0.2"});
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Catch::Contains("error: runtime error: no reply from the controller to"));
  CHECK_THAT(r.err, Catch::Contains("stop sent to every motor (EX DX CX BX AX)"));
}

TEST_CASE("robotsim run --device: usage errors", "[serial]") {
  TempDir dir;
  const std::string prog = dir.write("prog.rsp", kSerialCliProgram);
  const auto missing = runCli({"run", prog, "--device", "/nonexistent/ttyUSB0"});
  CHECK(missing.code == 1);
  CHECK(missing.err == "robotsim: error: cannot open /nonexistent/ttyUSB0: No such file or directory\n");
  CHECK(runCli({"run", prog, "--log-serial", "x.log"}).code == 2);  // needs --device
  CHECK(runCli({"run", prog, "--device", "/dev/null", "--input", "1=ON"}).code ==
        2);  // inputs come from the controller
  CHECK(runCli({"run", prog, "--device", "/dev/null", "--dialect", "mark5"}).code == 2);
  const auto bad = runCli({"run", prog, "--device", "/dev/null", "--serial-set", "chunk=500"});
  CHECK(bad.code == 2);
  CHECK_THAT(bad.err, Catch::Contains("chunk=500: expected 1..127 steps"));
  const auto notTty = runCli({"check", prog, "--device", "/dev/null"});
  CHECK(notTty.code == 1);
  CHECK_THAT(notTty.err, Catch::Contains("/dev/null is not a serial device"));
}

TEST_CASE("robotsim ports says when there are none", "[serial]") {
  TempDir dir;
  const auto none = runCli({"ports", "--dev", dir.path().string()});
  CHECK(none.code == 0);
  CHECK_THAT(none.out, Catch::StartsWith("No serial devices found"));
  CHECK_THAT(none.out, Catch::Contains("robotsim emulate"));
  std::ofstream(dir.path() / "ttyUSB0") << "";
  const auto one = runCli({"ports", "--dev", dir.path().string()});
  CHECK_THAT(one.out, Catch::Contains("ttyUSB0  USB serial adapter"));
  const auto json = runCli({"ports", "--dev", dir.path().string(), "--json"});
  CHECK(nlohmann::json::parse(json.out)["ports"].size() == 1);
}

TEST_CASE("robotsim emulate runs a script and stops", "[serial]") {
  TempDir dir;
  const std::string script = dir.write("io.txt", "in 3 on\nswitch E open\nbogus\nwait 0.05\nquit\n");
  const auto r = runCli({"emulate", "--no-stdin", "--script", script, "--duration", "5"});
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::StartsWith("Rhino Mark III controller emulator on /dev/"));
  CHECK_THAT(r.out, Catch::Contains("input 3 ON"));
  CHECK_THAT(r.out, Catch::Contains(script + ":3: unknown command 'bogus' (type help)"));
  CHECK_THAT(r.out, Catch::Contains("emulator stopped: mark3"));
  CHECK_THAT(r.out, Catch::Contains("in ..3....."));
  const auto mark4 =
      runCli({"emulate", "--no-stdin", "--dialect", "mark4", "--robot", "rhino-xr3", "--duration", "0.1"});
  CHECK(mark4.code == 0);
  CHECK_THAT(mark4.out, Catch::Contains("Mark IV"));
  CHECK_THAT(mark4.out, Catch::Contains("F 300/s"));
  CHECK(runCli({"emulate", "--robot", "no-such-robot", "--no-stdin"}).code == 2);
  CHECK(runCli({"emulate", "--start", "Z=5", "--no-stdin"}).code == 2);
}

TEST_CASE("robotsim emulate: console numbers are whole numbers, read strictly", "[serial]") {
  TempDir dir;
  const std::string script = dir.write("nums.txt",
                                       "fault silence after -1\n"
                                       "fault silence after 5x\n"
                                       "fault silence after 99999999999999999999\n"
                                       "wait 1x\n"
                                       "wait -1\n"
                                       "fault slow after +3\n"
                                       "wait 0.01\n"
                                       "quit\n");
  const auto r = runCli({"emulate", "--no-stdin", "--script", script, "--duration", "5"});
  CHECK(r.code == 0);
  const std::string bad = "fault KIND after N: N is a whole number of commands 0..1000000000000, not ";
  CHECK_THAT(r.out, Catch::Contains(script + ":1: " + bad + "'-1'"));
  CHECK_THAT(r.out, Catch::Contains(script + ":2: " + bad + "'5x'"));
  CHECK_THAT(r.out, Catch::Contains(script + ":3: " + bad + "'99999999999999999999'"));
  CHECK_THAT(r.out, Catch::Contains(script + ":4: wait: bad time '1x'"));
  CHECK_THAT(r.out, Catch::Contains(script + ":5: wait: time must not be negative, got '-1'"));
  CHECK_THAT(r.out, Catch::Contains("fault slow armed"));  // line 6: '+3' is 3
  CHECK_THAT(r.out, Catch::Contains("emulator stopped"));
  CHECK(r.out.find(script + ":6:") == std::string::npos);
  const auto start = runCli({"emulate", "--start", "E=5x", "--no-stdin"});
  CHECK(start.code == 2);
  CHECK_THAT(start.err, Catch::Contains("--start: 'E=5x' is not L=N with N in -1000000..1000000"));
  CHECK(runCli({"emulate", "--start", "E=+-5", "--no-stdin"}).code == 2);
  CHECK(runCli({"emulate", "--start", "E=+5,D=-40", "--no-stdin", "--duration", "0.05"}).code == 0);
}

TEST_CASE("robotsim run --device: the wrong dialect's handshake suggests the right --dialect", "[serial]") {
  TempDir dir;
  const std::string prog = dir.write("prog.rsp", kSerialCliProgram);
  SECTION("a Mark III handshake to a Mark IV") {
    auto emu = emulator(Dialect::Mark4);
    const std::string log = dir.file("probe.log");
    const auto r = runCli({"run", prog, "--device", emu->path(), "--serial-set", "timeout=0.2", "--log-serial", log});
    CHECK(r.code == 1);
    // The Mark IV leaves "I" unanswered (error 10 on its stack) and answers
    // "SE" with that error, 10.
    CHECK_THAT(r.err, Catch::StartsWith("robotsim: error: no working Mark III controller on " + emu->path() +
                                        ": no reply from the controller to \"I\" within 0.200 s (timeout)"));
    CHECK_THAT(r.err, Catch::EndsWith("\n  hint: the controller on " + emu->path() +
                                      " answers as a Mark IV (\"SE\" was answered with 10): run with --dialect "
                                      "mark4\n"));
    const std::vector<std::string> sent = rs::rhino::testing::sentCommands(rs::testing::readBytes(log));
    REQUIRE(sent.size() >= 2);
    CHECK(sent[0] == "I");
    CHECK(sent[1] == "SE");
  }
  SECTION("a Mark IV handshake to a Mark III") {
    auto emu = emulator(Dialect::Mark3);
    const auto r = runCli({"run", prog, "--device", emu->path(), "--dialect", "mark4", "--serial-set", "timeout=0.2"});
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::StartsWith("robotsim: error: no working Mark IV controller on " + emu->path() +
                                        ": no reply from the controller to \"SE\" within 0.200 s (timeout)"));
    CHECK_THAT(r.err, Catch::EndsWith("\n  hint: the controller on " + emu->path() +
                                      " answers as a Mark III (\"I\" was answered with one byte): run with "
                                      "--dialect mark3\n"));
  }
  SECTION("a silent controller gets no dialect hint") {
    EmulatorConfig c;
    c.settings = defaultSettings(Dialect::Mark3);
    c.motors = rs::stdlib::rhinoScaraMotors();
    c.fault = {FaultKind::Silence, 0, 0};
    std::string error;
    auto emu = PtyEmulator::open(c, error);
    REQUIRE(emu);
    emu->start();
    const auto r = runCli({"run", prog, "--device", emu->path(), "--serial-set", "timeout=0.2"});
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Catch::Contains("no working Mark III controller"));
    CHECK(r.err.find("hint:") == std::string::npos);
  }
}

TEST_CASE("robotsim run --device: after a fault the summary says which motors are uncertain and which outputs are ON",
          "[serial]") {
  // Two outputs turned ON, then a move of E to 400 during which the
  // controller falls silent: its first poll is never answered, so no step
  // of the move was confirmed. E was last confirmed at 0 and commanded to
  // 400; D, C, B, A did not move. Counting the commands each dialect sends
  // before the poll (checked against docs/serial.md):
  //   Mark III: I (handshake), L (output 1), P5 (outputs 1 and 3), E+40, then E? -> silence after 4
  //   Mark IV:  TH, SE, PA,E PA,D PA,C PA,B PA,A, OB,1,1, OB,3,1, PD,E,400, MI, then SA -> silence after 11
  TempDir dir;
  const std::string prog = dir.write("fault.rsp",
                                     "OUTSIG 1 ON\n"
                                     "OUTSIG 3 ON\n"
                                     "MOVETO 400 0 0 0 0\n"
                                     "END\n");
  for (const auto& [dialect, name, after] :
       {std::tuple{Dialect::Mark3, "mark3", 4ull}, std::tuple{Dialect::Mark4, "mark4", 11ull}}) {
    INFO(name);
    EmulatorConfig c;
    c.settings = defaultSettings(dialect);
    c.motors = rs::stdlib::rhinoScaraMotors();
    c.fault = {FaultKind::Silence, after, 0};
    std::string error;
    auto emu = PtyEmulator::open(c, error);
    REQUIRE(emu);
    emu->start();
    const auto text = runCli({"run", prog, "--device", emu->path(), "--dialect", name, "--serial-set", "timeout=0.2"});
    CHECK(text.code == 1);
    INFO(text.out);
    CHECK_THAT(text.out, Catch::Contains("  motors          E=0  D=0  C=0  B=0  A=0\n"));
    CHECK_THAT(text.out, Catch::Contains("  uncertain       E between 0 (last confirmed) and 400 (last commanded)\n"));
    CHECK_THAT(text.out, Catch::Contains("  left ON         outputs 1, 3 (as last set: stopping the motors does not "
                                         "turn outputs off)\n"));
  }
  EmulatorConfig c;
  c.settings = defaultSettings(Dialect::Mark3);
  c.motors = rs::stdlib::rhinoScaraMotors();
  c.fault = {FaultKind::Silence, 4, 0};
  std::string error;
  auto emu = PtyEmulator::open(c, error);
  REQUIRE(emu);
  emu->start();
  const auto r = runCli({"run", prog, "--format", "json", "--device", emu->path(), "--serial-set", "timeout=0.2"});
  CHECK(r.code == 1);
  const nlohmann::json j = summary(r.out);
  REQUIRE(j.contains("fault"));
  CHECK_THAT(j["fault"]["message"].get<std::string>(),
             Catch::StartsWith("no reply from the controller to \"E?\" within 0.200 s (timeout)"));
  CHECK(j["fault"]["uncertain_motors"] == nlohmann::json::parse(R"([{"motor":"E","confirmed":0,"commanded":400}])"));
  CHECK(j["fault"]["outputs_left_on"] == nlohmann::json::parse("[1,3]"));
  CHECK(j["outputs"] == nlohmann::json::parse("[true,false,true,false,false,false,false,false]"));
}

TEST_CASE("robotsim run --device: a run without a fault has no fault section", "[serial]") {
  TempDir dir;
  const std::string prog = dir.write("ok.rsp", "OUTSIG 2 ON\nMOVETO 40 0 0 0 0\nEND\n");
  auto emu = emulator(Dialect::Mark3);
  const auto r = runCli({"run", prog, "--format", "json", "--device", emu->path(), "--serial-set", "timeout=0.3"});
  REQUIRE(r.code == 0);
  CHECK_FALSE(summary(r.out).contains("fault"));
  auto emu2 = emulator(Dialect::Mark3);
  const auto t = runCli({"run", prog, "--device", emu2->path(), "--serial-set", "timeout=0.3"});
  REQUIRE(t.code == 0);
  CHECK(t.out.find("uncertain") == std::string::npos);
}
