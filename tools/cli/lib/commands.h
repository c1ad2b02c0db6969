// The table of robotsim's commands: each row its name, its one-line help,
// the function that adds its options to a CLI11 subcommand and the function
// that runs it. app.cpp builds the parser from it and dispatches through
// it; man_page.cpp and bash_completion.cpp write the man pages and the
// completion script from it (docs/architecture.md, "Adding a command").
#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tools/cli/lib/convert_command.h"
#include "tools/cli/lib/debug_command.h"
#include "tools/cli/lib/export_command.h"
#include "tools/cli/lib/ik_command.h"
#include "tools/cli/lib/list_command.h"
#include "tools/cli/lib/lsp_command.h"
#include "tools/cli/lib/plot_command.h"
#include "tools/cli/lib/program_commands.h"
#include "tools/cli/lib/render_commands.h"
#include "tools/cli/lib/robot_commands.h"
#include "tools/cli/lib/run_command.h"
#include "tools/cli/lib/serial_commands.h"
#include "tools/cli/lib/teach_command.h"
#include "tools/cli/lib/test_command.h"
#include "tools/cli/lib/version_command.h"

namespace rs::cli {

/// What the command line fills in: one options struct per family of
/// commands. Commands of one family share theirs (run and check, the four
/// program commands, the four robot commands, render and animate), as only
/// one command is parsed.
struct CommandValues {
  RunCommandOptions run;
  ProgramCommandOptions program;
  RobotQuery robot;
  IkOptions ik;
  ExportOptions exporting;
  ConvertOptions convert;
  ListOptions list;
  PortsOptions ports;
  EmulateOptions emulate;
  RenderOptions render;
  PlotOptions plot;
  TeachOptions teach;
  TestOptions test;
  LspOptions lsp;
  DebugOptions debug;
  std::string helpTopic;
  std::string versionFormat;
};

/// The streams a command talks on.
struct CommandStreams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
};

struct Command {
  std::string_view name;
  std::string_view help;  ///< one line: `robotsim --help`, the man page's NAME
  /// Null in the main binary's copy of the table for a row run by a helper.
  void (*addOptions)(CLI::App* cmd, CommandValues& values);
  /// The exit code. Null in the main binary's copy for a row run by a helper.
  int (*run)(const CommandValues& values, const CommandStreams& io);
  /// Needs the renderer, the HTTP server or a terminal library: the
  /// installed `robotsim` execs its helper `robotsim-NAME` (tools/cli/lib/helpers.h),
  /// which links them, so that no other command loads them.
  bool inHelper = false;
};

/// Every command, in the order `robotsim --help` lists them.
std::span<const Command> commandTable();

/// `robotsim --help`'s first line.
inline constexpr std::string_view kRobotsimHelp =
    "robotsim: compile, check, run and inspect ROBOTSIM robot programs";

/// The parser made from the table: CLI11's app with one subcommand per row,
/// in the table's order, and the values its options fill. CLI11 holds
/// pointers into `values`, so a CommandLine stays where it is made.
class CommandLine {
 public:
  /// Every row with its options (the man pages, the completions).
  CommandLine();
  /// Every row, but only the row named `command` with its options: a run
  /// parses one command, and adding the options of all of them was a fifth
  /// of robotsim's start-up. An unknown name gives every row bare.
  explicit CommandLine(std::string_view command);
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  CLI::App& app() { return app_; }
  const CLI::App& app() const { return app_; }
  const CommandValues& values() const { return values_; }
  /// Row i's subcommand.
  const CLI::App& subcommand(std::size_t i) const { return *subcommands_.at(i); }
  /// After app().parse: the row whose subcommand was parsed, or nullptr.
  const Command* parsedCommand() const;

 private:
  CommandLine(std::string_view command, bool everyRow);

  CommandValues values_;
  CLI::App app_;
  std::vector<CLI::App*> subcommands_;
};

}  // namespace rs::cli
