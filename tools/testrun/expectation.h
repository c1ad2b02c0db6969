// What a correct run is, written in the program itself as comments the
// compiler ignores and `robotsim test` reads (docs/testing.md):
//
//   ; test: stimuli pick_and_place.stim        how to run it
//   ; expect: finished                         what must hold
//   ; expect: output 3 pulses 3 times
//   ; expect: time <= 40
//   GOTO PIKC   ; expect-error: undefined label 'PIKC'
//
// Every line is `; test: SETTING ...`, `; expect: SUBJECT ...` or
// `; expect-error: TEXT`; a bad one is a positioned diagnostic, never a
// silently ignored line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "diag/diagnostic.h"
#include "diag/source_file.h"
#include "vm/interpreter.h"

namespace rs::testrun {

enum class ExpectKind : std::uint8_t {
  Status,        // finished | deadlock | step limit | time limit | clock standing still | runtime error [at line N]
  Time,          // time <= S | time >= S | time = S
  Motors,        // motors E=0 D=10 [within N]
  Output,        // output N on|off [at T | during A..B]
  Input,         // input N on|off [at T | during A..B]
  Pulses,        // output N pulses K times
  Variable,      // variable V = N
  Tcp,           // tcp X Y Z [within D]
  ObjectAt,      // object NAME at X Y Z [within D]: its AT corner; object NAME centre at X Y Z [within D]: its centre
  ObjectHeld,    // object NAME held | object NAME not held
  Order,         // (input|output) N on|off before (input|output) M on|off: the first times
  MotorBound,    // motor E never above N | motor E never below N: during the whole run
  Trace,         // trace FILE: the run's text trace is the file's bytes
  NoCollision,   // no collision: the run's collision check found none
  CollidesWith,  // collides with NAME [at line N]: a collision of a part so named (link, object, floor)
  DeviceCount,   // sensor|conveyor|feeder|sink NAME count [<=|>=|=] N: a device's count at the end
  CompileError,  // expect-error: TEXT (on the line of the error)
};

/// An input or output reaching a state, for Order: the first time it does.
struct LineEvent {
  bool output = false;
  int number = 0;
  bool on = true;
};

enum class Compare : std::uint8_t { AtMost, AtLeast, Equal };

/// The device a DeviceCount names, and what it counts: a sensor's ON
/// edges, a conveyor's parts carried, a feeder's parts fed, a sink's parts taken.
enum class DeviceKind : std::uint8_t { Sensor, Conveyor, Feeder, Sink };

struct Expectation {
  ExpectKind kind = ExpectKind::Status;
  diag::Pos pos;     ///< of the word `expect`
  std::string text;  ///< as written after the colon, for messages
  // Status
  vm::StopReason reason = vm::StopReason::End;
  std::uint32_t line = 0;  ///< runtime error at line N (0: any line)
  // Time, and the moments of Output and Input
  Compare compare = Compare::Equal;
  vm::Micros micros = 0;
  std::optional<vm::Micros> at;
  std::optional<std::pair<vm::Micros, vm::Micros>> during;
  // Motors
  std::vector<std::pair<char, std::int32_t>> motors;
  /// The column of each of `motors`' terms as written (E=100), for a
  /// message about one of them; empty for an expectation not read from text.
  std::vector<std::uint32_t> motorCols;
  std::int32_t within = 0;
  // MotorBound: `motors[0]` is the motor and its bound; `on`: never above (else never below)
  // Output, Input, Pulses
  int number = 0;
  bool on = true;
  std::uint32_t count = 0;
  // Variable, ObjectAt, ObjectHeld
  std::string name;
  bool centre = false;  ///< ObjectAt: the centre of the object's box, not its AT corner
  // DeviceCount: which kind of device `name` is (its count is `count`, compared by `compare`)
  DeviceKind device = DeviceKind::Sensor;
  std::uint32_t nameCol = 0;  ///< the column of `name` as written (DeviceCount), for a name the cell lacks
  std::int32_t value = 0;
  std::array<double, 3> point{};
  double tolerance = 0.5;
  // Order: `first` happens before `second`
  LineEvent first, second;
  // CompileError: the error's message must contain this
  std::string message;
  /// `feeder.motors E=0`: in a cell of several robots, the robot the
  /// expectation is about, by its label as written (docs/testing.md, "A cell
  /// of several robots"); empty: the program's robot, or the cell as a whole.
  std::string robot;
  std::uint32_t robotCol = 0;  ///< the column of the label
  /// Order: `before right.output 1 on`, the robot of the second event
  /// (empty: the first's).
  std::string secondRobot;
  std::uint32_t secondRobotCol = 0;
  /// Status `LABEL.stopped`: the robot was stopped by another robot's
  /// failure (the cell's emergency stop), not by its own end.
  bool stopped = false;
  /// In a scenario file, `expect: ... points N`: what it earns when it
  /// holds (a teacher's partial credit), in hundredths of a point.
  std::optional<std::int64_t> points;
};

/// How to run the program (`; test:` lines); paths as written, relative to
/// the program's folder.
/// `program LABEL FILE` in a scenario file: robot LABEL of the cell runs FILE.
struct RobotProgram {
  std::string label, file;
  diag::Pos pos;      ///< of the word `program`
  std::uint32_t labelCol = 0, fileCol = 0;
};

struct TestSettings {
  std::string cell;
  /// `test: robot LABEL`: the cell's robot the program under test runs on
  /// (like --robot; with --spec, the robot each submission is).
  std::string robot;
  /// Set by a scenario file only: the other robots' programs.
  std::vector<RobotProgram> programs;
  std::string stimuliFile;
  std::vector<std::string> inputs;  ///< N=ON@T
  std::string maxTime;              ///< seconds, as written
  std::optional<std::uint64_t> maxSteps;
  std::optional<std::uint64_t> maxKnots;
};

struct ParsedExpectations {
  TestSettings settings;
  std::vector<Expectation> expectations;
  std::vector<diag::Diagnostic> errors;  ///< bad `; test:` or `; expect:` lines
  bool any() const { return !expectations.empty(); }
  bool expectsCompileErrors() const;
  bool statesStatus() const;
  bool wantsTrace() const;
  /// Has `collides with`: the run then goes on after a collision (warn).
  bool expectsCollision() const;
};

/// Reads every expectation and setting of a program's comments.
ParsedExpectations parseExpectations(const diag::SourceFile& source);

/// One `test:`, `expect:` or `expect-error:` directive of line `n`, its head
/// starting at byte `i`, into `out` (a bad one as an error there); false
/// when the line holds none. The scenario files' reader (scenario_file.h)
/// shares it.
bool readDirective(std::string_view line, std::uint32_t n, std::size_t i, const std::string& file,
                   ParsedExpectations& out);

}  // namespace rs::testrun
