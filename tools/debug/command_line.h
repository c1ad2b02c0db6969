// What the terminal debugger's two consoles (Console for one program,
// CellConsole for a cell of several robots) read a command line with: the
// table of commands and their help, the split into a command and its
// arguments, the counts, times and breakpoint qualifiers (`if COND`, `hits
// N`) they take, and the values `print` shows of a robot. One reading, so
// that a command means the same in both.
//
//   CommandLine line = readCommand(text, commands);
//   if (line.command) { Arguments a(*line.command, line.args, out); if (auto n = a.count()) ... }
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diag/result.h"
#include "runtime/run/run.h"
#include "tools/debug/device_points.h"
#include "tools/debug/expression.h"

namespace rs::debug {

struct Command {
  std::string_view name;
  std::string_view shortForm;
  std::string_view usage;
  std::string_view summary;  ///< `help` lists it up to its first ';', `help NAME` says it all
  bool is(std::string_view word) const { return word == name || (!shortForm.empty() && word == shortForm); }
};

/// The names of `commands` (for completion and help).
std::vector<std::string> commandNamesOf(std::span<const Command> commands);

/// A line split into its first word and the rest. `command` is null for a
/// blank line or a comment (`blank`), and for a word no command has: then
/// `error` says so (with the nearest name).
struct CommandLine {
  const Command* command = nullptr;
  std::string_view args;
  bool blank = false;
  std::string error;
};
CommandLine readCommand(std::string_view line, std::span<const Command> commands);

/// `help` (the list, under `heading`) or `help COMMAND`.
void printHelp(std::ostream& out, std::span<const Command> commands, std::string_view topic, std::string_view heading);

/// A whole number with nothing around it.
std::optional<std::uint64_t> wholeCount(std::string_view text);
/// `text` safe to print, cut at 60 characters.
std::string shownText(std::string_view text);
/// Words joined with one space.
std::string joinedWords(std::span<const std::string_view> words);

/// A command's arguments as the stepping commands take them; each reader
/// prints the error (`error: ...`) and answers nullopt (false) when they are wrong.
class Arguments {
 public:
  Arguments(const Command& command, std::string_view args, std::ostream& out)
      : command_(command), args_(args), out_(out) {}
  bool none() const;
  /// A count from 1 (1 without an argument).
  std::optional<std::uint64_t> count() const;
  /// A time in seconds.
  std::optional<vm::Micros> time() const;

 private:
  const Command& command_;
  std::string_view args_;
  std::ostream& out_;
};

/// `break PLACE... [if COND] [hits N]`: the words of the place, and the
/// condition (on `image`'s program) and the hit count.
struct BreakWords {
  std::vector<std::string_view> place;
  std::optional<Condition> condition;
  std::optional<HitCondition> hits;
};
/// (An empty place: nothing more is read; the console says what a place is.)
diag::Result<BreakWords> readBreak(const vm::Image& image, std::string_view args);
/// A place both consoles take alike: `at TIME`, `when COND` (on the
/// program of `run`), a device's event (`sensor NAME [on|off]`, `feeder
/// NAME`, `sink NAME`, unless one word that is a label of the program),
/// `collision`, `warning`.
struct MomentPlace {
  enum class Kind : std::uint8_t { Time, When, Device, Collision, Warning };
  Kind kind = Kind::Time;
  vm::Micros time = 0;
  Condition when;
  DevicePoint device;
};
/// nullopt: `place` is none of these (a line, a label, ...: the console's own).
std::optional<diag::Result<MomentPlace>> readMomentPlace(const runtime::Run& run, std::span<const std::string_view> place);

/// `print WHAT` of a robot's run as `view` shows it, for what both consoles
/// print alike (nothing or variables, motors, tcp, io, objects, devices, an
/// expression); false when `what` is none of these (the console's own: clock).
/// `devicesAt`: the clock of the devices' state (the run's, after an
/// instruction under way when the view is inside it).
bool printRunValue(std::ostream& out, const runtime::Run& run, const runtime::RunView& view, std::string_view what,
                   vm::Micros devicesAt);

/// `disasm [@N]`: the instructions around `current` (or N), as robotsim disasm lists them.
void printDisasm(std::ostream& out, const vm::Image& image, std::uint32_t current, std::string_view args);

}  // namespace rs::debug
