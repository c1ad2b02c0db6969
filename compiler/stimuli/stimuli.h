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

#include "diag/diagnostic.h"
#include "vm/machine.h"

namespace rs::stimuli {

/// Latest time a stimulus may name: 1e6 seconds, in microseconds.
inline constexpr vm::Micros kMaxStimulusTime = 1'000'000LL * 1'000'000LL;

/// At time `at`, input `input` (1..8) turns ON or OFF.
struct InputChange {
  vm::Micros at = 0;
  int input = 1;
  bool on = true;
  bool operator==(const InputChange&) const = default;
};

/// When output `output` (1..8) turns to `outputOn`, input `input` turns to
/// `inputOn` after `delay` (>= 0) microseconds.
struct ReactiveRule {
  int output = 1;
  bool outputOn = true;
  int input = 1;
  bool inputOn = true;
  vm::Micros delay = 0;
  std::uint32_t line = 0;  ///< where the stimuli file wrote it (0: not from a file)
  bool operator==(const ReactiveRule&) const = default;
};

/// Everything that drives the inputs during one run. Order matters: changes
/// due at the same time apply in list order.
struct Stimuli {
  std::vector<InputChange> changes;
  std::vector<ReactiveRule> rules;
  bool operator==(const Stimuli&) const = default;
};

/// A parsed stimuli file: the model of every good line, and one error per
/// bad line (all of them, in line order). Bad lines add nothing to the model.
struct StimuliParse {
  Stimuli stimuli;
  /// One error per bad line: line and column 1-based, counting bytes; line
  /// 0 when the whole file is at fault (it cannot be read).
  std::vector<diag::Diagnostic> errors;
};

/// Parses stimuli text (any bytes). `fileName` only labels the errors.
StimuliParse parseStimuli(std::string_view text, std::string_view fileName);

/// Reads and parses a stimuli file; an unreadable or oversized file is one
/// error with line 0.
StimuliParse loadStimuliFile(const std::filesystem::path& path);

/// One command-line stimulus: exactly one of the two is set.
struct StimulusArgParse {
  std::optional<InputChange> change;
  std::optional<diag::Diagnostic> error;  // line 1, column within the argument
};

/// Parses the command-line form `N=ON@T` or `N=OFF@T` (e.g. `3=ON@1.5`;
/// without `@T` the time is 0). `origin` labels the error (its `file`).
StimulusArgParse parseStimulusArg(std::string_view arg, std::string_view origin = "command line");

}  // namespace rs::stimuli
