// Where a run's time went (`robotsim run --profile`): computed afterwards
// from its RunLog (every step's clock and the motors' moves) and the image
// (opcodes, source lines, labels), so the interpreter's loop pays nothing.
//
// Every step's time (its end minus its start on the clock) counts once in
// the total and in one kind: waiting (WAITFOR, DELAY), gripper (a move in
// which only gripper motors change), moving (any other move: MOVE, MOVETO,
// MOVEP, HRDHOME, GOSOFT), other (whatever else took time: nothing does on
// the simulated machine). Then by source line, by label (the code from a
// label to the next one: each step counts once, under the label above its
// instruction), by subroutine (time from a GOSUB's target to its RETURN,
// the subroutines it calls included; a subroutine that calls itself counts
// each moment once), and the slowest moves. And the time the robot waited
// in WAITFOR, by input and by what drives it: the cause of the input change
// that ended each wait (a wire from a device, a stimulus, a reactive rule).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/run/run_log.h"
#include "vm/image.h"

namespace rs::runtime {

/// Microseconds by kind.
struct TimeSplit {
  vm::Micros moving = 0, waiting = 0, gripper = 0, other = 0;
  vm::Micros total() const { return moving + waiting + gripper + other; }
  bool operator==(const TimeSplit&) const = default;
};

struct LineTime {
  std::uint32_t line = 0;   ///< source line
  std::uint64_t steps = 0;  ///< instructions executed on it
  TimeSplit time;
};

/// A label's region, or a subroutine (named by the label at its start).
struct NamedTime {
  std::string name;         ///< the label; "(start)" for code before the first label
  std::uint32_t line = 0;   ///< the source line of its first instruction
  std::uint64_t count = 0;  ///< steps in a label's region; calls of a subroutine
  TimeSplit time;
};

/// One move, by how long it took.
struct SlowMove {
  std::uint32_t step = 0;         ///< 0-based step of the run
  std::uint32_t instruction = 0;  ///< 0-based
  std::uint32_t line = 0;
  vm::Micros start = 0, duration = 0;
  char motor = 0;                  ///< the motor that arrived last (the one that set the time)
  std::int32_t from = 0, to = 0;   ///< its encoder counts
};

/// The time WAITFOR steps on one input waited, for the waits one driver ended.
struct InputWait {
  int input = 0;
  /// What changed the input so the wait ended: "wire from sensor eye",
  /// "stimulus", "rule", "set by the debugger"; "already ON" ("already
  /// OFF") when the input was so as the WAITFOR began; "nothing (the run
  /// stopped waiting)" for the wait the run ended in (a deadlock, a limit).
  std::string driver;
  std::uint64_t waits = 0;  ///< WAITFOR steps
  vm::Micros time = 0;      ///< their time on the clock, in all
  bool operator==(const InputWait&) const = default;
};

struct Profile {
  TimeSplit total;
  std::uint64_t moves = 0;              ///< steps that moved a motor
  std::vector<LineTime> lines;          ///< by line number, only lines that ran
  std::vector<NamedTime> labels;        ///< in code order, only regions that ran
  std::vector<NamedTime> subroutines;   ///< in code order, only those called
  std::vector<SlowMove> slowest;        ///< longest first (ties: earlier first)
  std::vector<InputWait> inputWaits;    ///< by input, then driver
};

/// The profile of a logged run of `image`; at most `slowestCount` moves.
Profile profileOf(const vm::Image& image, const RunLog& log, std::size_t slowestCount = 5);

}  // namespace rs::runtime
