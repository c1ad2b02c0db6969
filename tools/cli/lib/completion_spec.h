// What the shell completions know about robotsim's command line, read once
// from the command table and CLI11's own lists of each command's options
// (as man_page.cpp does), so that bash, zsh and fish complete exactly what
// the parser accepts: each command, its options, whether an option takes a
// value and what kind (a library cell, a library robot, one of a fixed set
// of words, or a file), and its positional arguments.
#pragma once

#include <string>
#include <vector>

#include "tools/cli/lib/commands.h"

namespace rs::cli {

/// What a value is completed with.
enum class CompletionValue {
  None,    ///< a flag: no value
  File,    ///< a file or folder name (the shell's own)
  Cell,    ///< a library workcell or robot name (--cell, a command's cell/robot argument), or a .rsd file
  Robot,   ///< a library robot name (--robot), or a .rsd file
  Choice,  ///< one of `choices`
};

struct CompletionOption {
  std::vector<std::string> names;  ///< as typed: "-o", "--output"
  std::string help;
  std::string valueName;           ///< "FILE", "N", ... (empty for a flag)
  CompletionValue value = CompletionValue::None;
  std::vector<std::string> choices;
  bool repeatable = false;
};

struct CompletionArgument {
  std::string name;  ///< "file", "cell", ...
  std::string help;
  CompletionValue value = CompletionValue::File;
  bool many = false;  ///< takes every word left (test's paths)
  bool required = false;
};

struct CompletionCommand {
  std::string name;
  std::string help;
  std::vector<CompletionOption> options;
  std::vector<CompletionArgument> arguments;
};

struct CompletionSpec {
  std::vector<CompletionOption> globalOptions;  ///< robotsim's own (--help)
  std::vector<CompletionCommand> commands;      ///< in the table's order
};

CompletionSpec completionSpec(const CommandLine& commandLine);

/// The hidden first word of the query the completions ask robotsim:
/// `robotsim __complete cells|robots` prints the library's names, one a
/// line (completion_query.h). Not a command: no row, no page, no --help.
inline constexpr std::string_view kCompleteQueryWord = "__complete";

}  // namespace rs::cli
