// A Rhino controller in software, for students without a robot and for the
// tests: it speaks the Mark III or Mark IV dialect exactly as the backend
// assumes (docs/serial.md), moves its motors at a realistic step rate, has a
// home switch at encoder 0 of each motor, eight inputs the user sets and
// eight outputs the host sets, and injects faults on request.
//
// EmulatorEngine is the pure model: bytes in, bytes out, time passed in.
// PtyEmulator puts it on a pseudo-terminal (`robotsim emulate`, end-to-end
// tests); LoopbackLink connects it to the backend in-process on a manual
// clock (golden transcripts).
#pragma once

#include <array>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "runtime/rhino/link.h"
#include "runtime/rhino/settings.h"
#include "vm/image.h"

namespace rs::rhino {

enum class FaultKind : std::uint8_t {
  None,
  Silence,  // commands are obeyed, nothing is answered
  Garbage,  // every answer is replaced by line noise
  Slow,     // every answer comes `slowDelay` late
  Hangup,   // the port is closed
};

std::string_view faultName(FaultKind k);
bool parseFault(std::string_view text, FaultKind& out);

/// A fault that starts after the first `after` commands were served.
struct FaultPlan {
  FaultKind kind = FaultKind::None;
  std::uint64_t after = 0;
  Micros slowDelay = 2'000'000;
};

struct EmulatorConfig {
  RhinoSettings settings = defaultSettings(Dialect::Mark3);  // dialect and assumptions to play
  std::vector<vm::MotorSpec> motors;                         // the robot: letters, step rates (speed), ranges
  double rateScale = 1.0;                                    // every step rate multiplied by this
  Micros latency = 5'000;                                    // an answer's delay (the notes: 5-15 ms)
  int switchWidth = 20;                                      // a switch is closed while |position| <= this
  std::array<std::int32_t, 8> start{};                       // where motors A..H start
  FaultPlan fault;
};

inline constexpr int kEmulatedMotors = 8;              // A..H
inline constexpr std::int32_t kDefaultStepRate = 300;  // steps/s of a port the robot does not use

struct EmulatedMotor {
  char letter = 'A';
  bool used = false;                 // the robot has this motor
  double rate = kDefaultStepRate;    // steps per second
  std::int32_t position = 0;         // encoder count
  int registerSteps = 0;             // Mark III: signed steps still to go
  std::int32_t destination = 0;      // Mark IV: PD / PR
  bool running = false;              // Mark IV: started and not there yet
  double carry = 0;                  // part of a step already earned
  std::optional<bool> forcedSwitch;  // set by "switch L open|closed"
};

struct EmulatorSnapshot {
  std::array<EmulatedMotor, kEmulatedMotors> motors;
  std::vector<char> order;  // the robot's letters, in its order
  std::uint8_t outputs = 0;
  std::uint8_t inputs = 0;
  std::uint64_t commands = 0;
  bool faultActive = false;
  FaultKind fault = FaultKind::None;
  bool hungUp = false;
  bool hostMode = false;  // Mark IV: TH seen
};

class EmulatorEngine {
 public:
  explicit EmulatorEngine(EmulatorConfig config);

  /// Bytes from the host at time `now`; complete commands are executed.
  void receive(std::span<const std::uint8_t> bytes, Micros now);
  /// Moves the motors up to `now` (time only goes forward).
  void advance(Micros now);
  /// Answer bytes due by `now`, in order, removed from the queue.
  std::vector<std::uint8_t> takeReplies(Micros now);
  std::optional<Micros> nextReplyAt() const;

  void setInput(int line, bool on);
  void forceSwitch(char letter, std::optional<bool> closed);
  void setFault(FaultPlan plan);
  bool switchClosed(char letter) const;

  bool hungUp() const { return hungUp_; }
  EmulatorSnapshot snapshot() const;
  /// Every command received, in order (at most the last 100000).
  const std::deque<std::string>& received() const { return received_; }
  /// The commands received after the first `seen` (those still kept), in
  /// order; `seen` becomes the number received so far. Start from 0.
  std::vector<std::string> receivedSince(std::uint64_t& seen) const;
  /// Console lines since the last call ("output 1 ON", "unknown command").
  std::vector<std::string> takeEvents();
  /// One line: motors, outputs, inputs, commands, fault.
  std::string statusLine() const;
  const EmulatorConfig& config() const { return config_; }

 private:
  void execute(std::string command, Micros now);
  void executeMark3(const std::string& c, Micros now);
  void executeMark4(const std::string& c, Micros now);
  void reply(std::string bytes, Micros now);
  void replyNumber(long value, Micros now);
  std::uint8_t inquiryBits(char command) const;
  EmulatedMotor* motor(char letter);
  void mark4Error(int code, std::string_view why);
  bool faultActive() const;
  void event(std::string text);

  EmulatorConfig config_;
  std::array<EmulatedMotor, kEmulatedMotors> motors_;
  std::vector<char> order_;
  std::string pending_;  // bytes of the command being received
  struct Reply {
    Micros due;
    std::string bytes;
  };
  std::deque<Reply> replies_;
  std::deque<std::string> received_;
  std::vector<std::string> events_;
  std::vector<int> errors_;  // Mark IV error stack
  Micros lastAdvance_ = 0;
  std::uint64_t commands_ = 0;
  std::uint8_t outputs_ = 0;
  std::uint8_t inputs_ = 0;
  bool hungUp_ = false;
  bool hostMode_ = false;
  bool homing_ = false;
  bool faultAnnounced_ = false;
};

/// The engine on a pseudo-terminal. The host opens path(); the emulator
/// keeps its own handle on the slave so hosts may come and go.
class PtyEmulator {
 public:
  static std::unique_ptr<PtyEmulator> open(EmulatorConfig config, std::string& error);
  ~PtyEmulator();
  PtyEmulator(const PtyEmulator&) = delete;
  PtyEmulator& operator=(const PtyEmulator&) = delete;

  const std::string& path() const { return path_; }
  /// One round: waits up to `wait` for host bytes (or for `extraFd` to be
  /// readable), runs the engine, sends the answers that are due. Returns
  /// true when `extraFd` is readable.
  bool pump(Micros wait, int extraFd = -1);
  /// Runs pump() on a thread until stop() (tests, in-process use).
  void start();
  void stop();

  bool hungUp() const;
  void setInput(int line, bool on);
  void forceSwitch(char letter, std::optional<bool> closed);
  void setFault(FaultPlan plan);
  EmulatorSnapshot snapshot();
  std::vector<std::string> received();
  /// EmulatorEngine::receivedSince, for --verbose: no copy of the rest.
  std::vector<std::string> receivedSince(std::uint64_t& seen);
  std::vector<std::string> takeEvents();
  std::string statusLine();
  Micros now() const { return clock_.now(); }

 private:
  PtyEmulator(EmulatorConfig config, int master, int slave, std::string path);
  void hangUp();

  mutable std::mutex mutex_;
  EmulatorEngine engine_;
  SteadyClock clock_;
  int master_ = -1;
  int slave_ = -1;
  std::string path_;
  std::thread thread_;
  std::atomic<bool> running_{false};
};

/// The engine as a Link, on a manual clock: what the backend writes is
/// received at once; a read returns the next answer when it is due (the
/// clock moves to it) or times out (the clock moves by the timeout). Each
/// byte also takes its time on the line (11 bits at the configured baud).
class LoopbackLink final : public Link {
 public:
  LoopbackLink(EmulatorEngine& engine, ManualClock& clock);
  vm::Status write(std::span<const std::uint8_t> bytes, Micros timeout) override;
  vm::Status read(std::span<std::uint8_t> buffer, Micros timeout, std::size_t& count) override;
  std::string name() const override { return "emulator"; }

 private:
  EmulatorEngine& engine_;
  ManualClock& clock_;
  std::deque<std::uint8_t> pending_;
  Micros byteTime_;
};

}  // namespace rs::rhino
