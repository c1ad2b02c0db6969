// How each way the serial line can fail reads, now that a link answers the
// machine's own vm::Status (Timeout, Closed, Fault) and rhino::ControllerSession is
// the one place it becomes the run's Fault: the messages are the ones the
// backend always gave, word for word. The line is a real one where a real
// one can be made to fail so: the in-process emulator (silence, hang-up)
// and a real pseudo-terminal (nobody reading it, its other end closed).
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <sstream>
#include <string>

#include "runtime/rhino/emulator.h"
#include "runtime/rhino/serial_log.h"
#include "runtime/rhino/serial_port.h"
#include "runtime/rhino/controller_session.h"
#include "tests/rhino/serial_support.h"

namespace {

using namespace rs::rhino;
using rs::vm::Status;

// A pseudo-terminal's master end, and the path of its slave (the port).
struct Pty {
  int master = -1;
  std::string slave;
  Pty() {
    master = ::posix_openpt(O_RDWR | O_NOCTTY);
    REQUIRE(master >= 0);
    REQUIRE(::grantpt(master) == 0);
    REQUIRE(::unlockpt(master) == 0);
    slave = ::ptsname(master);
  }
  void close() {
    if (master >= 0) ::close(master);
    master = -1;
  }
  ~Pty() { close(); }
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;
};

// A Mark III port open on a real pseudo-terminal that nothing answers, a
// log and the wall clock: the pseudo-terminal tests differ only in what
// they do to it.
struct PtyPort {
  Pty pty;
  RhinoSettings settings = testing::testSettings(Dialect::Mark3);
  std::unique_ptr<SerialPort> port;
  SteadyClock clock;
  std::ostringstream logText;
  SerialLog log{logText};
  PtyPort() {
    std::string error;
    port = SerialPort::open(pty.slave, settings.line, error);
    INFO(error);
    REQUIRE(port);
  }
};

// A Mark III session on the in-process emulator with `fault` from the start.
struct EmulatorSession {
  RhinoSettings settings = testing::testSettings(Dialect::Mark3);
  ManualClock clock;
  EmulatorEngine engine;
  LoopbackLink link{engine, clock};
  std::ostringstream logText;
  SerialLog log{logText};
  ControllerSession session{link, clock, settings, &log, nullptr};
  explicit EmulatorSession(FaultKind fault)
      : engine([&] {
          EmulatorConfig c = testing::emulatorFor(testSettings(), testing::twoMotors());
          c.fault = {fault, 0, 0};
          return c;
        }()) {
    session.setDevice("emulator");
  }
  static RhinoSettings testSettings() { return testing::testSettings(Dialect::Mark3); }
};

// Asks "I" until the line fails (the fault starts after the first command).
Status firstFailure(ControllerSession& session) {
  for (int i = 0; i < 5; ++i) {
    std::uint8_t reply = 0;
    if (Status s = session.queryByte("I", reply); !s) return s;
  }
  FAIL("the line never failed");
  return Status::ok();
}

}  // namespace

TEST_CASE("serial failures: a silent controller is a timeout on the question", "[rhino][serial]") {
  EmulatorSession e(FaultKind::Silence);
  const Status s = firstFailure(e.session);
  CHECK(s.code == Status::Code::Fault);
  CHECK(s.message == "no reply from the controller to \"I\" within 0.200 s (timeout)");
  CHECK(e.session.lastFailureWasSilence());
  CHECK_FALSE(e.session.portGone());
  CHECK_THAT(e.logText.str(), Catch::Contains(" ! no reply from the controller to \"I\" within 0.200 s (timeout)\n"));
}

TEST_CASE("serial failures: a controller that hangs up is gone, and the log says how", "[rhino][serial]") {
  EmulatorSession e(FaultKind::Hangup);
  const Status s = firstFailure(e.session);
  CHECK(s.code == Status::Code::Fault);
  CHECK(s.message == "the serial port emulator hung up at \"I\" (the controller is gone)");
  CHECK(e.session.portGone());
  CHECK_FALSE(e.session.lastFailureWasSilence());
  const std::string log = e.logText.str();
  CHECK_THAT(log, Catch::Contains(" ! emulator: the port hung up\n"));
  CHECK_THAT(log, Catch::Contains(" ! the serial port emulator hung up at \"I\" (the controller is gone)\n"));
}

TEST_CASE("serial failures: a line nobody reads is blocked (a real pseudo-terminal)", "[rhino][serial]") {
  PtyPort p;
  LoggedLink logged(*p.port, p.log, p.clock);
  ControllerSession session(logged, p.clock, p.settings, &p.log, nullptr);
  session.setDevice(p.pty.slave);
  // The terminal's buffers take some kilobytes; then a write waits 0.2 s and gives up.
  Status s = Status::ok();
  for (int i = 0; i < 1'000'000 && s; ++i) s = session.send("E+1000");
  CHECK(s.code == Status::Code::Fault);
  CHECK(s.message == "the serial line to " + p.pty.slave + " is blocked: \"E+1000\" could not be sent within 0.200 s");
  CHECK_FALSE(session.portGone());
  CHECK_THAT(p.logText.str(), Catch::Contains("  (not sent: write timed out)\n"));
}

TEST_CASE("serial failures: a port whose other end closed is gone (a real pseudo-terminal)", "[rhino][serial]") {
  PtyPort p;
  p.pty.close();
  ControllerSession session(*p.port, p.clock, p.settings, &p.log, nullptr);
  session.setDevice(p.pty.slave);
  std::uint8_t reply = 0;
  const Status s = session.queryByte("I", reply);
  CHECK(s.code == Status::Code::Fault);
  CHECK(s.message == "the serial port " + p.pty.slave + " hung up at \"I\" (the controller is gone)");
  CHECK(session.portGone());
  CHECK_THAT(p.logText.str(), Catch::Contains(" ! " + p.pty.slave + ": the port "));
}
