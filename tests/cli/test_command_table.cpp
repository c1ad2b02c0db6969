// The command table (tools/cli/lib/commands.h) and what is made from it: the
// parser has one subcommand per row, in order, with the row's help; each
// row's handler is the one that runs; the man pages (man_page.h) name every
// option the parser accepts and render in man-db without a warning; the
// bash completion script (bash_completion.h), sourced in a real bash,
// completes commands and options; robotsim_gen_docs writes them all.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/bash_completion.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/gen_docs.h"
#include "tools/cli/lib/man_page.h"

namespace {

using rs::cli::CommandLine;
using rs::cli::commandTable;
using rs::testing::runCli;
using rs::testing::TempDir;

struct ShellResult {
  int status = -1;  // the exit status, or -1 when the command did not exit
  std::string out;
};

// `command` in /bin/sh, its standard output read whole.
ShellResult shell(const std::string& command) {
  ShellResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != -1 && WIFEXITED(status)) r.status = WEXITSTATUS(status);
  return r;
}

bool onPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::set<std::string> linesOf(const std::string& text) {
  std::set<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.insert(line);
  return lines;
}

// Every name the parser accepts for `cmd`'s options, as typed.
std::vector<std::string> optionNames(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : cmd.get_options()) {
    for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
  }
  return names;
}

}  // namespace

TEST_CASE("the parser has one subcommand per row of the table, in its order, with its help", "[cli][commands]") {
  const CommandLine commandLine;
  const auto subcommands = commandLine.app().get_subcommands([](const CLI::App*) { return true; });
  const auto table = commandTable();
  REQUIRE(subcommands.size() == table.size());
  std::set<std::string_view> seen;
  for (std::size_t i = 0; i < table.size(); ++i) {
    INFO(table[i].name);
    CHECK(subcommands[i]->get_name() == table[i].name);
    CHECK(subcommands[i]->get_description() == table[i].help);
    CHECK(&commandLine.subcommand(i) == subcommands[i]);
    CHECK(seen.insert(table[i].name).second);  // no name twice
    CHECK(table[i].help.find('\n') == std::string_view::npos);  // one line
    // The completion script writes names and options unquoted.
    std::vector<std::string> words = optionNames(*subcommands[i]);
    words.emplace_back(table[i].name);
    for (const std::string& word : words) {
      INFO(word);
      CHECK(std::all_of(word.begin(), word.end(),
                        [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; }));
    }
  }
  // robotsim --help lists each row with its help.
  const auto help = runCli({"--help"});
  CHECK(help.code == 0);
  for (const auto& command : table) {
    INFO(command.name);
    CHECK(help.out.find("  " + std::string(command.name) + " ") != std::string::npos);
  }
}

TEST_CASE("the row whose subcommand was parsed is the one that runs", "[cli][commands]") {
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    CommandLine commandLine;
    // --help stops the parse before a missing argument would.
    const std::string name(table[i].name);
    const char* args[] = {"robotsim", name.c_str(), "--help"};
    try {
      commandLine.app().parse(3, args);
    } catch (const CLI::CallForHelp&) {
    }
    INFO(name);
    REQUIRE(commandLine.parsedCommand() == &table[i]);
  }
  // And its handler is what answers: help's prints the instruction summary.
  const auto help = runCli({"help"});
  CHECK(help.code == 0);
  CHECK(help.out.find("JMPVAR") != std::string::npos);
}

TEST_CASE("a command line with one command's options parses that command as the whole table does", "[cli][commands]") {
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string name(table[i].name);
    CAPTURE(name);
    const CommandLine whole, one{name};
    CHECK(optionNames(one.subcommand(i)) == optionNames(whole.subcommand(i)));
    CHECK(one.subcommand(i).help() == whole.subcommand(i).help());
    // The other rows are there by name, without their options.
    for (std::size_t j = 0; j < table.size(); ++j)
      if (j != i) CHECK(one.subcommand(j).get_options().size() <= 1);  // at most --help
  }
}

TEST_CASE("an option's Needs and Excludes are listed by name, the same in every process", "[cli][commands]") {
  // CLI11 keeps them in sets of pointers: addresses, not names, would order them.
  const auto table = commandTable();
  const auto teach = std::find_if(table.begin(), table.end(), [](const auto& row) { return row.name == "teach"; });
  REQUIRE(teach != table.end());
  const CommandLine commandLine;
  const std::string help = commandLine.subcommand(static_cast<std::size_t>(teach - table.begin())).help();
  INFO(help);
  CHECK(help.find("--tui Excludes: --listen --open") != std::string::npos);
  CHECK(help.find("--dialect TEXT:{mark3,mark4} Needs: --device") != std::string::npos);
}

TEST_CASE("each command's man page names every option and argument the parser accepts", "[cli][commands][man]") {
  const CommandLine commandLine;
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const CLI::App& cmd = commandLine.subcommand(i);
    const std::string page = rs::cli::commandManPage(commandLine, i);
    INFO(table[i].name);
    for (const char* section : {".SH NAME\n", ".SH SYNOPSIS\n", ".SH DESCRIPTION\n", ".SH OPTIONS\n",
                                ".SH EXIT STATUS\n", ".SH SEE ALSO\n"})
      CHECK(page.find(section) != std::string::npos);
    CHECK(page.find("robotsim\\-" + rs::cli::troffText(table[i].name) + " \\- " + rs::cli::troffText(table[i].help)) !=
          std::string::npos);
    std::size_t named = 0;
    for (const CLI::Option* opt : cmd.get_options()) {
      for (const std::string& s : opt->get_snames()) {
        CHECK(page.find("\\fB" + rs::cli::troffText("-" + s) + "\\fR") != std::string::npos);
        ++named;
      }
      for (const std::string& l : opt->get_lnames()) {
        CHECK(page.find("\\fB" + rs::cli::troffText("--" + l) + "\\fR") != std::string::npos);
        ++named;
      }
      if (!opt->nonpositional()) {
        CHECK(page.find("\\fI" + rs::cli::troffText(opt->get_name()) + "\\fR") != std::string::npos);
        ++named;
      }
      CHECK(page.find(rs::cli::troffText(opt->get_description())) != std::string::npos);
    }
    CHECK(named >= 2);  // at least -h and --help
    for (const char* code : {".B 0\n", ".B 1\n", ".B 2\n"}) CHECK(page.find(code) != std::string::npos);
  }
  const std::string top = rs::cli::robotsimManPage(commandLine);
  for (const auto& command : table) {
    INFO(command.name);
    CHECK(top.find(".BR robotsim\\-" + rs::cli::troffText(command.name) + " (1)") != std::string::npos);
  }
}

TEST_CASE("troff text: hyphens and backslashes escaped, a leading dot or quote guarded", "[cli][commands][man]") {
  CHECK(rs::cli::troffText("--max-steps") == "\\-\\-max\\-steps");
  CHECK(rs::cli::troffText("a\\b") == "a\\eb");
  CHECK(rs::cli::troffText(".rsp files") == "\\&.rsp files");
  CHECK(rs::cli::troffText("'quoted'") == "\\&'quoted'");
  CHECK(rs::cli::troffText("") == "");
}

TEST_CASE("the man pages render in man-db without a warning", "[cli][commands][man]") {
  if (!onPath("man")) {
    WARN("man is not installed here; skipped");
    return;
  }
  const CommandLine commandLine;
  const TempDir dir;
  std::vector<std::string> pages{dir.write("robotsim.1", rs::cli::robotsimManPage(commandLine))};
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i)
    pages.push_back(dir.write(rs::cli::manPageFileName(table[i].name), rs::cli::commandManPage(commandLine, i)));
  for (const std::string& page : pages) {
    INFO(page);
    // --warnings: groff's own (-ww); anything on standard error fails.
    const ShellResult r =
        shell("MANWIDTH=80 LC_ALL=C.UTF-8 man --warnings -E UTF-8 -l '" + page + "' 2>&1 >/dev/null");
    CHECK(r.status == 0);
    CHECK(r.out == "");
    const ShellResult text = shell("MANWIDTH=80 LC_ALL=C.UTF-8 man -E UTF-8 -l '" + page + "' 2>/dev/null");
    CHECK(text.out.find("NAME") != std::string::npos);
    CHECK(text.out.find("EXIT STATUS") != std::string::npos);
    if (onPath("lexgrog")) {
      // What mandb and apropos would index: the NAME line.
      const ShellResult whatis = shell("lexgrog '" + page + "'");
      CHECK(whatis.status == 0);
      CHECK(whatis.out.find("robotsim") != std::string::npos);
    }
  }
}

namespace {

// The completion script sourced in a non-interactive bash, the function
// that `complete -p robotsim` names called with COMP_WORDS = `words` (the
// last the one being completed); COMPREPLY, one a line.
std::set<std::string> complete(const TempDir& dir, const std::string& words) {
  static const std::string driver = R"(source "$1"; shift
spec=$(complete -p robotsim) || exit 3
fn=${spec#*-F }; fn=${fn%% *}
COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
"$fn" robotsim "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
printf '%s\n' "${COMPREPLY[@]}"
)";
  const std::string script = dir.write("robotsim.bash", rs::cli::bashCompletion(CommandLine()));
  const std::string driverFile = dir.write("driver.sh", driver);
  const ShellResult r = shell("bash --norc --noprofile '" + driverFile + "' '" + script + "' " + words);
  REQUIRE(r.status == 0);
  return linesOf(r.out);
}

// Of `names`, those that start with `prefix`.
std::set<std::string> startingWith(const std::vector<std::string>& names, const std::string& prefix) {
  std::set<std::string> out;
  for (const std::string& n : names)
    if (n.starts_with(prefix)) out.insert(n);
  return out;
}

}  // namespace

TEST_CASE("the bash completion, sourced in bash, completes commands and each command's options", "[cli][commands]") {
  if (!onPath("bash")) {
    WARN("bash is not installed here; skipped");
    return;
  }
  const TempDir dir;
  const CommandLine commandLine;
  std::vector<std::string> commands;
  for (const auto& command : commandTable()) commands.emplace_back(command.name);

  SECTION("the registration names the function") {
    const std::string script = dir.write("robotsim.bash", rs::cli::bashCompletion(commandLine));
    const ShellResult r = shell("bash --norc --noprofile -c 'source \"" + script + "\" && complete -p robotsim'");
    CHECK(r.status == 0);
    CHECK(r.out.find(std::string("-F ") + rs::cli::kBashCompletionFunction + " robotsim") != std::string::npos);
  }
  SECTION("the first word: the commands with that prefix") {
    CHECK(complete(dir, "robotsim ch") == startingWith(commands, "ch"));
    CHECK(complete(dir, "robotsim ch") == std::set<std::string>{"check"});
    CHECK(complete(dir, "robotsim t") == startingWith(commands, "t"));
    CHECK(complete(dir, "robotsim t").size() == 4);  // table, teach, test, tokens
    CHECK(complete(dir, "robotsim ''") == startingWith(commands, ""));
    CHECK(complete(dir, "robotsim --h") == std::set<std::string>{"--help"});
  }
  SECTION("an option: the options of the command before it, from the parser") {
    const auto table = commandTable();
    for (std::size_t i = 0; i < table.size(); ++i) {
      const std::string name(table[i].name);
      INFO(name);
      const std::vector<std::string> options = optionNames(commandLine.subcommand(i));
      CHECK(complete(dir, "robotsim " + name + " -") == startingWith(options, "-"));
    }
    const std::vector<std::string> run = optionNames(commandLine.subcommand(0));
    CHECK(complete(dir, "robotsim run prog.rsp --max-") == startingWith(run, "--max-"));
    CHECK(complete(dir, "robotsim run prog.rsp --max-") ==
          std::set<std::string>{"--max-errors", "--max-knots", "--max-steps", "--max-time"});
    CHECK(complete(dir, "robotsim compile --o") == std::set<std::string>{"--output"});
  }
  SECTION("anything else is left to bash's file names") {
    CHECK(complete(dir, "robotsim run ex").empty());
    CHECK(complete(dir, "robotsim frobnicate --x").empty());
  }
}

TEST_CASE("robotsim_gen_docs writes every page and the script, and bad usage is exit 2", "[cli][commands]") {
  const TempDir dir;
  const std::string man = (dir.path() / "man").string();
  std::filesystem::create_directories(man);
  const std::string bash = dir.file("robotsim.bash");
  const CommandLine commandLine;
  auto run = [](std::vector<std::string> args) {
    std::vector<const char*> argv{"robotsim_gen_docs"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int code = rs::cli::genDocsCommand(static_cast<int>(argv.size()), argv.data(), out, err);
    return std::pair{code, err.str()};
  };
  const auto [code, err] = run({"--man", man, "--bash", bash});
  CHECK(code == 0);
  CHECK(err == "");
  CHECK(rs::testing::readBytes(man + "/robotsim.1") == rs::cli::robotsimManPage(commandLine));
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i)
    CHECK(rs::testing::readBytes(man + "/" + rs::cli::manPageFileName(table[i].name)) ==
          rs::cli::commandManPage(commandLine, i));
  CHECK(rs::testing::readBytes(bash) == rs::cli::bashCompletion(commandLine));
  CHECK(std::distance(std::filesystem::directory_iterator(man), {}) == static_cast<long>(table.size() + 1));

  const auto nothing = run({});
  CHECK(nothing.first == 2);
  CHECK(nothing.second.find("robotsim_gen_docs: error: nothing to write") == 0);
  const auto missing = run({"--man", dir.file("no-such-folder")});
  CHECK(missing.first == 2);
  const auto unwritable = run({"--bash", dir.file("no-such-folder/robotsim.bash")});
  CHECK(unwritable.first == 2);
  CHECK(unwritable.second.find("robotsim_gen_docs: error: ") == 0);
}
