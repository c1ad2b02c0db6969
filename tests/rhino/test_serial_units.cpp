// The pieces: settings, the log format, the emulator's model of each
// dialect, the port list.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "tests/cli/cli_support.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using namespace rs::rhino::testing;
namespace vm = rs::vm;

std::span<const std::uint8_t> bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// Applies a --serial-set argument to `s` as the command line does: "" when
// it is taken, else what the failure says (and `s` is as it was).
std::string appliedOrWhy(RhinoSettings& s, std::string_view arg) {
  rs::diag::Result<RhinoSettings> applied = applySettingArg(s, arg);
  if (!applied) {
    CHECK(applied.failure().file == "--serial-set");
    return applied.failure().message;
  }
  s = std::move(applied).value();
  return {};
}

std::string replies(EmulatorEngine& e, std::string_view commands, Micros at) {
  e.receive(bytes(commands), at);
  const auto out = e.takeReplies(at + 1'000'000);
  return {out.begin(), out.end()};
}

}  // namespace

TEST_CASE("serial settings: defaults, overrides, errors", "[serial]") {
  RhinoSettings s = defaultSettings(Dialect::Mark3);
  CHECK(describe(s.line) == "9600 7E2, no flow control");
  CHECK(s.chunk == 40);
  CHECK(s.refill == 15);
  CHECK(s.switches[2] == BitSource{'I', 0});  // C on I bit 0 [S]
  CHECK(s.switches[7] == BitSource{'I', 5});  // H on I bit 5 [S]
  CHECK(appliedOrWhy(s, "baud=19200").empty());
  CHECK(appliedOrWhy(s, "parity=odd").empty());
  CHECK(appliedOrWhy(s, "stop-bits=1").empty());
  CHECK(appliedOrWhy(s, "flow=rtscts").empty());
  CHECK(describe(s.line) == "19200 7O1, RTS/CTS flow control");
  CHECK(appliedOrWhy(s, "timeout=0.25").empty());
  CHECK(s.timeout == 250'000);
  CHECK(appliedOrWhy(s, "switch.A=K5").empty());
  CHECK(s.switches[0] == BitSource{'K', 5});
  CHECK(appliedOrWhy(s, "output.3.on=P{n}+").empty());
  CHECK(appliedOrWhy(s, "baud=12345") == "baud=12345: expected a standard baud rate (9600, 19200, ...)");
  CHECK(appliedOrWhy(s, "chunk=200") == "chunk=200: expected 1..127 steps");
  // refill=0 would stall every long Mark III move (no chunk after the first).
  CHECK(appliedOrWhy(s, "refill=0") == "refill=0: expected 1..127 steps (0 would stall every long move)");
  CHECK(appliedOrWhy(s, "refill=128") == "refill=128: expected 1..127 steps (0 would stall every long move)");
  CHECK(s.refill == 15);
  CHECK(appliedOrWhy(s, "refill=1").empty());
  CHECK(s.refill == 1);
  CHECK(appliedOrWhy(s, "output.1.on={x}") == "output.1.on={x}: expected a command, optionally with {n} and {port}");
  CHECK_THAT(appliedOrWhy(s, "nonsense=1"), Catch::StartsWith("unknown serial setting 'nonsense'"));
  CHECK(appliedOrWhy(s, "chunk") == "serial setting 'chunk': expected KEY=VALUE");
  const auto bad = applySettingsText(s, "# lab robot\nchunk = 30\nrefill=10\n  parity = maybe\n", "lab.cfg");
  REQUIRE_FALSE(bad.ok());
  REQUIRE(bad.failures().size() == 1);
  CHECK(rs::diag::render(bad.failure(), nullptr) == "lab.cfg:4:3: error: parity=maybe: expected none, even or odd\n");
  // A file with a bad line gives no settings; without it, every line applies.
  const auto good = applySettingsText(s, "# lab robot\nchunk = 30\nrefill=10\n", "lab.cfg");
  REQUIRE(good.ok());
  CHECK(good->chunk == 30);
  CHECK(good->refill == 10);
  CHECK(defaultSettings(Dialect::Mark4).inputsActiveLow == false);
  CHECK(listSettings(defaultSettings(Dialect::Mark3)).size() == 52);
}

TEST_CASE("serial log format", "[serial]") {
  CHECK(logTime(1'234'567) == "1.234567");
  CHECK(escapeBytes(bytes("E+40\r")) == "E+40\\r");
  CHECK(escapeBytes(bytes("\x15~\"\\\n")) == "\\x15~\\\"\\\\\\n");
  std::ostringstream out;
  SerialLog log(out);
  log.sent(12'000, bytes("E?\r"));
  log.received(17'500, bytes(" "));
  log.sent(20'000, bytes("EX\r"), "the port is gone");
  log.event(21'000, "stop sent");
  CHECK(out.str() ==
        "   0.012000 > 45 3F 0D  \"E?\\r\"\n"
        "   0.017500 < 20  \" \"\n"
        "   0.020000 > 45 58 0D  \"EX\\r\"  (not sent: the port is gone)\n"
        "   0.021000 ! stop sent\n");
}

TEST_CASE("Mark III emulator: the move register, X, switches, inputs, outputs", "[serial]") {
  EmulatorConfig c = emulatorFor(defaultSettings(Dialect::Mark3), twoMotors());  // E 1000/s, A 500/s
  c.latency = 0;
  EmulatorEngine e(c);
  CHECK(replies(e, "I\r", 0) == " ");      // every switch closed: all at home
  CHECK(replies(e, "E+60\r", 0).empty());  // moves do not answer
  CHECK(replies(e, "E?\r", 0) == std::string(1, 32 + 60));
  CHECK(replies(e, "E?\r", 30'000) == std::string(1, 32 + 30));  // 30 ms at 1000 steps/s
  e.receive(bytes("E+20\r"), 30'000);                            // adds to what is left
  CHECK(replies(e, "E?\r", 30'000) == std::string(1, 32 + 50));
  CHECK(replies(e, "I\r", 30'000) == std::string(1, 32 + 4));  // E (bit 2) left its switch
  e.receive(bytes("EX\r"), 40'000);
  CHECK(replies(e, "E?\r", 100'000) == " ");
  CHECK(e.snapshot().motors[4].position == 40);
  e.receive(bytes("E+100\r"), 100'000);
  e.receive(bytes("E+100\r"), 100'000);  // 200 does not fit a signed byte: it wraps
  CHECK(e.snapshot().motors[4].registerSteps == -56);
  CHECK_THAT(e.takeEvents().back(), Catch::Contains("overflowed"));
  e.setInput(2, true);
  e.setInput(5, true);
  CHECK(replies(e, "J\r", 100'000) == std::string(1, 32 + 0b110100));  // A, B switches closed, input 2 ON (0)
  CHECK(replies(e, "K\r", 100'000) == std::string(1, 32 + 0b111110));  // input 5 ON
  e.receive(bytes("L\rP12\r"), 100'000);
  CHECK(e.snapshot().outputs == 0b00001101);  // 1 (L), 3 and 4 (P: bits 2..7)
  e.receive(bytes("M\rq\r"), 100'000);
  CHECK(e.snapshot().outputs == 0);
}

TEST_CASE("Mark IV emulator: PD/MI/SA/PA, errors, inputs, outputs", "[serial]") {
  EmulatorConfig c = emulatorFor(defaultSettings(Dialect::Mark4), twoMotors());
  c.latency = 0;
  EmulatorEngine e(c);
  CHECK(replies(e, "TH\rSE\r", 0) == "0\r");
  e.receive(bytes("PD,E,100\rMI\r"), 0);
  CHECK(replies(e, "SA\r", 0) == "16\r");  // bit 4: E busy
  CHECK(replies(e, "PA,E\r", 40'000) == "40\r");
  CHECK(replies(e, "SA\r", 200'000) == "0\r");
  CHECK(replies(e, "pa,e\r", 200'000) == "100\r");  // lower case works
  e.receive(bytes("PD,E,40000\rXX\rPD,Z,1\r"), 200'000);
  CHECK(replies(e, "SE\r", 200'000) == "92\r");  // the last error first
  CHECK(replies(e, "SE\r", 200'000) == "10\r");
  CHECK(replies(e, "SE\r", 200'000) == "11\r");
  CHECK(replies(e, "SE\r", 200'000) == "0\r");
  e.setInput(3, true);
  CHECK(replies(e, "IP\r", 200'000) == "4\r");
  e.receive(bytes("OB,8,1\r"), 200'000);
  CHECK(e.snapshot().outputs == 0x80);
  e.receive(bytes("HH\r"), 200'000);
  CHECK(replies(e, "SA\r", 1'000'000) == "0\r");
  CHECK(replies(e, "PA,E\r", 1'000'000) == "0\r");
  e.forceSwitch('E', false);
  e.receive(bytes("HH\r"), 1'000'000);
  CHECK(replies(e, "SE\r", 1'000'000) == "64\r");  // limit switch E not found
}

TEST_CASE("emulator faults start after N commands", "[serial]") {
  EmulatorConfig c = emulatorFor(defaultSettings(Dialect::Mark3), twoMotors());
  c.latency = 0;
  c.fault = {FaultKind::Garbage, 2, 0};
  EmulatorEngine e(c);
  CHECK(replies(e, "I\r", 0) == " ");
  CHECK(replies(e, "I\r", 0) == " ");
  CHECK(replies(e, "I\r", 0) == "\x15~?\r");
  c.fault = {FaultKind::Silence, 0, 0};
  EmulatorEngine quiet(c);
  CHECK(replies(quiet, "I\rE+5\r", 0).empty());
  CHECK(quiet.snapshot().motors[4].registerSteps == 5);  // still obeys
  c.fault = {FaultKind::Slow, 0, 3'000'000};
  EmulatorEngine slow(c);
  slow.receive(bytes("I\r"), 0);
  CHECK(slow.takeReplies(2'999'999).empty());
  CHECK(slow.takeReplies(3'000'000).size() == 1);
  c.fault = {FaultKind::Hangup, 1, 0};
  EmulatorEngine gone(c);
  gone.receive(bytes("I\rI\r"), 0);
  CHECK(gone.hungUp());
  FaultKind k{};
  CHECK(parseFault("hangup", k));
  CHECK(k == FaultKind::Hangup);
  CHECK_FALSE(parseFault("fire", k));
}

TEST_CASE("emulator: the commands received since last time, past the cap", "[serial]") {
  EmulatorConfig c = emulatorFor(defaultSettings(Dialect::Mark3), twoMotors());
  EmulatorEngine e(c);
  std::uint64_t seen = 0;
  CHECK(e.receivedSince(seen).empty());
  e.receive(bytes("I\rE+5\rE?\r"), 0);
  CHECK(e.receivedSince(seen) == std::vector<std::string>{"I", "E+5", "E?"});
  CHECK(seen == 3);
  CHECK(e.receivedSince(seen).empty());
  e.receive(bytes("J\r"), 0);
  CHECK(e.receivedSince(seen) == std::vector<std::string>{"J"});
  // The engine keeps the last 100000 commands; the count goes on past them.
  std::string many;
  for (int i = 0; i < 100'005; ++i) many += "K\r";
  e.receive(bytes(many), 0);
  const std::vector<std::string> next = e.receivedSince(seen);
  CHECK(next.size() == 100'000);
  CHECK(seen == 100'009);
  e.receive(bytes("I\r"), 0);
  CHECK(e.receivedSince(seen) == std::vector<std::string>{"I"});
  CHECK(e.received().size() == 100'000);
}

TEST_CASE("stop commands and motor letters, one list per dialect", "[serial]") {
  const auto motors = twoMotors();
  CHECK(stopCommands(Dialect::Mark3, motors) == std::vector<std::string>{"EX", "AX"});
  CHECK(stopCommands(Dialect::Mark4, motors) == std::vector<std::string>{"MA"});
  CHECK(unsupportedMotor(Dialect::Mark3, motors).empty());
  std::vector<vm::MotorSpec> bad = motors;
  bad[1].letter = 'J';
  CHECK(unsupportedMotor(Dialect::Mark3, bad) == "motor J: a Mark III controller has motors A..H only");
  CHECK(unsupportedMotor(Dialect::Mark4, bad) == "motor J: a Mark IV controller has motors A..H only");
}

TEST_CASE("the port list looks where serial devices are", "[serial]") {
  rs::testing::TempDir dir;
  namespace fs = std::filesystem;
  CHECK(listPorts(dir.path().string()).empty());
  for (const char* name : {"ttyS1", "ttyS10", "ttyS2", "ttyUSB0", "ttyACM0", "ttyprintk", "tty0"})
    std::ofstream(dir.path() / name) << "";
  fs::create_directories(dir.path() / "serial" / "by-id");
  fs::create_symlink("../../ttyUSB0", dir.path() / "serial" / "by-id" / "usb-FTDI_FT232R-if00-port0");
  const auto ports = listPorts(dir.path().string());
  std::vector<std::string> names;
  for (const auto& p : ports) names.push_back(fs::path(p.path).filename().string());
  CHECK(names ==
        std::vector<std::string>{"usb-FTDI_FT232R-if00-port0", "ttyUSB0", "ttyACM0", "ttyS1", "ttyS2", "ttyS10"});
  CHECK(ports[0].note == "-> ../../ttyUSB0");
}

TEST_CASE("a port that is not there, or not a terminal, is a clear error", "[serial]") {
  std::string error;
  CHECK_FALSE(SerialPort::open("/nonexistent/ttyUSB9", {}, error));
  CHECK(error == "cannot open /nonexistent/ttyUSB9: No such file or directory");
  rs::testing::TempDir dir;
  const std::string file = dir.write("plain", "x");
  CHECK_FALSE(SerialPort::open(file, {}, error));
  CHECK(error == file + " is not a serial device (not a terminal)");
}
