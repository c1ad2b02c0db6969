#include "tools/cli/lib/app.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>
#include <optional>

#include "base/near_names.h"
#include "base/text.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/completion_query.h"
#include "tools/cli/lib/completion_spec.h"
#include "tools/cli/lib/helper_handshake.h"
#include "tools/cli/lib/helpers.h"

namespace rs::cli {

namespace {

// "robotsim frobnicate": CLI11 would only say that a subcommand is required.
std::optional<int> unknownCommand(CLI::App& app, int argc, const char* const* argv, std::ostream& err) {
  if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return std::nullopt;
  const std::string_view word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_name() == word) return std::nullopt;
    names.push_back(sub->get_name());
  }
  // The word as typed, control bytes escaped.
  std::string shown = base::safeText(word.substr(0, 64));
  if (word.size() > 64) shown += "...";
  const std::string_view near = base::nearestName(word, names);
  err << fmt::format("robotsim: error: unknown command '{}'{}\n", shown,
                     near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near));
  err << fmt::format("  commands: {}\n  robotsim --help says what each does\n", fmt::join(names, ", "));
  return kExitBadInput;
}

}  // namespace

int runCommand(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  // `robotsim --version [--format json]` is `robotsim version [...]`: the
  // conventional spelling, one implementation.
  std::vector<const char*> versionArgs;
  if (argc >= 2 && std::string_view(argv[1]) == "--version") {
    versionArgs.assign(argv, argv + argc);
    versionArgs[1] = "version";
    argv = versionArgs.data();
  }
  // A helper asked by robotsim whether it is its own (helper_handshake.h):
  // before anything else, and never by the main binary.
  if (argc == 2 && argv[1] == kHelperHandshakeWord && !leavesRowsToHelpers(commandTable())) {
    out << helperHandshakeLine() << std::flush;
    return kExitOk;
  }
  // The shell completions' hidden query (completion_query.h), before the table's commands.
  if (argc >= 2 && argv[1] == kCompleteQueryWord) return completionQuery(argc - 2, argv + 2, out, err);
  // Before the parser is made (a third of the start-up): the main binary's
  // table has no options for these rows, their helper parses its own.
  if (const Command* row = commandLeftToHelper(commandTable(), argc, argv)) return execHelper(row->name, argc, argv, err);
  // Only the named command's options: the others are never parsed.
  CommandLine commandLine(argc >= 2 ? std::string_view(argv[1]) : std::string_view());
  CLI::App& app = commandLine.app();
  if (const std::optional<int> code = unknownCommand(app, argc, argv, err)) return *code;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e, out, err);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  // require_subcommand(1): a parse that returns chose exactly one.
  const Command* command = commandLine.parsedCommand();
  if (command == nullptr) return kExitBadInput;
  return command->run(commandLine.values(), CommandStreams{std::cin, out, err});
}

}  // namespace rs::cli
