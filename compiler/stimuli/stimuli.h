// Input stimuli: what the world outside the robot does to its eight inputs
// during a run. Timed changes ("at 1.5 s input 3 turns ON") and reactive
// rules ("when output 1 turns ON, input 2 turns ON 0.5 s later") make runs
// with WAITFOR and JMPIN deterministic. The file format is in docs/stimuli.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "vm/machine.h"

namespace rs::stimuli {

/// Latest time a stimulus may name: 1e6 seconds, in microseconds.
inline constexpr vm::Micros kMaxStimulusTime = 1'000'000LL * 1'000'000LL;

/// At time `at`, input `input` (1..vm::kIoCount) turns ON or OFF.
struct InputChange {
  vm::Micros at = 0;
  int input = 1;
  bool on = true;
  std::uint32_t line = 0;  ///< where the stimuli file wrote it (0: not from a file)
  /// The robot whose input it is, as a cell of several robots labels it
  /// (`input right.3`); empty: the cell's one robot. `robotColumn` is where
  /// the label stands on its line (1-based; 0: not from a file).
  std::string robot = {};
  std::uint32_t robotColumn = 0;
  /// Made by the debugger's `set input` (the cell debugger replays the run
  /// with it among the stimuli): its cause is "set by the debugger".
  bool bySession = false;
  bool operator==(const InputChange&) const = default;
};

/// When output `output` (1..vm::kIoCount) turns to `outputOn`, input `input` turns to
/// `inputOn` after `delay` (>= 0) microseconds.
struct ReactiveRule {
  int output = 1;
  bool outputOn = true;
  int input = 1;
  bool inputOn = true;
  vm::Micros delay = 0;
  std::uint32_t line = 0;  ///< where the stimuli file wrote it (0: not from a file)
  /// The robots of the output and of the input (`when output left.1 on then
  /// input right.2 on`), as InputChange::robot; columns as robotColumn.
  std::string outputRobot = {}, inputRobot = {};
  std::uint32_t outputRobotColumn = 0, inputRobotColumn = 0;
  bool operator==(const ReactiveRule&) const = default;
};

/// Everything that drives the inputs during one run. Order matters: changes
/// due at the same time apply in list order.
struct Stimuli {
  std::vector<InputChange> changes;
  std::vector<ReactiveRule> rules;
  bool operator==(const Stimuli&) const = default;
};

/// Parses stimuli text (any bytes) into its model, or one failure per bad
/// line (all of them, in line order: line and column 1-based, counting
/// bytes). `fileName` only labels the failures.
diag::Result<Stimuli> parseStimuli(std::string_view text, std::string_view fileName);

/// Reads and parses a stimuli file; an unreadable or oversized file is one
/// failure with line 0.
diag::Result<Stimuli> loadStimuliFile(const std::filesystem::path& path);

/// Parses the command-line form `N=ON@T` or `N=OFF@T` (e.g. `3=ON@1.5`;
/// without `@T` the time is 0). `origin` labels the failure (its `file`;
/// line 1, the column within the argument).
diag::Result<InputChange> parseStimulusArg(std::string_view arg, std::string_view origin = "command line");

}  // namespace rs::stimuli
