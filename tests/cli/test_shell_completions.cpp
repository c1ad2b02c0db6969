// The shell completions made from the command table, in the real shells
// with their own completion machinery: bash (complete -p, the registered
// function called as bash calls it, compgen), zsh (its completion system
// in an interactive zsh on a pseudo-terminal: completion/zsh_complete.zsh)
// and fish (complete -C). Library names come from `robotsim __complete`
// (the built robotsim first on PATH), checked against a listing of
// stdlib/ made here; commands and options against the parser's own lists.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tools/cli/lib/bash_completion.h"
#include "tools/cli/lib/commands.h"
#include "tools/cli/lib/completion_query.h"
#include "tools/cli/lib/fish_completion.h"
#include "tools/cli/lib/man_page.h"
#include "tools/cli/lib/zsh_completion.h"
#include "tests/support/build_facts.h"

namespace {

using rs::cli::CommandLine;
using rs::cli::commandTable;
using rs::testing::TempDir;

// `command` in /bin/sh: its standard output, and whether it exited 0.
std::pair<bool, std::string> completionShell(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  const int status = ::pclose(pipe);
  return {status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0, out};
}

bool completionShellInstalled(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// Each line's first tab-separated field (fish adds "\tdescription").
std::set<std::string> completionWords(const std::string& text) {
  std::set<std::string> words;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    line = line.substr(0, line.find('\t'));
    if (!line.empty()) words.insert(line);
  }
  return words;
}

// The library's names, listed here from the source tree's stdlib: the
// workcells and the robots, or the robots alone.
std::set<std::string> stdlibNames(bool cells, const std::string& prefix = "") {
  std::set<std::string> names;
  std::vector<std::string> folders{"robots"};
  if (cells) folders.emplace_back("workcells");
  for (const std::string& folder : folders)
    for (const auto& entry : std::filesystem::directory_iterator(std::string(ROBOTSIM_SOURCE_DIR) + "/stdlib/" + folder))
      if (entry.path().extension() == ".rsd" && entry.path().stem().string().starts_with(prefix))
        names.insert(entry.path().stem().string());
  return names;
}

std::set<std::string> tableCommands(const std::string& prefix = "") {
  std::set<std::string> names;
  for (const auto& c : commandTable())
    if (std::string(c.name).starts_with(prefix)) names.emplace(c.name);
  return names;
}

std::set<std::string> commandOptions(std::size_t row, const std::string& prefix) {
  const CommandLine commandLine;
  std::set<std::string> names;
  for (const CLI::Option* opt : commandLine.subcommand(row).get_options()) {
    for (const std::string& s : opt->get_snames())
      if (("-" + s).starts_with(prefix)) names.insert("-" + s);
    for (const std::string& l : opt->get_lnames())
      if (("--" + l).starts_with(prefix)) names.insert("--" + l);
  }
  return names;
}

std::size_t rowOf(const std::string& name) {
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].name == name) return i;
  FAIL("no command " << name);
  return 0;
}

// A place for the scripts, an empty working folder (file names offered
// there would mix with the library's), the built robotsim first on PATH
// and no ROBOTSIM_PATH.
struct CompletionBench {
  TempDir dir;
  std::string scripts, empty, env;
  CompletionBench() {
    scripts = (dir.path() / "scripts").string();
    empty = (dir.path() / "work").string();
    std::filesystem::create_directories(scripts);
    std::filesystem::create_directories(empty);
    const CommandLine commandLine;
    dir.write("scripts/robotsim.bash", rs::cli::bashCompletion(commandLine));
    dir.write("scripts/_robotsim", rs::cli::zshCompletion(commandLine));
    dir.write("scripts/robotsim.fish", rs::cli::fishCompletion(commandLine));
    const std::string bin = std::filesystem::path(rs::testing::robotsimBinary()).parent_path().string();
    env = "cd '" + empty + "' && env -u ROBOTSIM_PATH PATH='" + bin + "':\"$PATH\" ";
  }
  // bash: the function `complete -p robotsim` names, called with COMP_WORDS
  // = `words` (the last the one completed, '' for an empty one).
  std::set<std::string> bash(const std::string& words) const {
    const std::string driver = dir.write("bash_driver.sh", R"(source "$1"; shift
spec=$(complete -p robotsim) || exit 3
fn=${spec#*-F }; fn=${fn%% *}
COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
"$fn" robotsim "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
printf '%s\n' "${COMPREPLY[@]}"
)");
    const auto [ok, out] = completionShell(env + "bash --norc --noprofile '" + driver + "' '" + scripts +
                                           "/robotsim.bash' " + words);
    REQUIRE(ok);
    return completionWords(out);
  }
  // zsh: `line` typed and a Tab in an interactive zsh.
  std::set<std::string> zsh(const std::string& line) const {
    const auto [ok, out] = completionShell(env + "timeout 30 zsh -f '" + std::string(ROBOTSIM_SOURCE_DIR) +
                                           "/tests/cli/completion/zsh_complete.zsh' '" + scripts + "' '" + line + "'");
    REQUIRE(ok);
    return completionWords(out);
  }
  // fish: complete -C on `line`, the script sourced as fish would load it.
  std::set<std::string> fish(const std::string& line) const {
    const auto [ok, out] = completionShell(env + "timeout 30 fish --no-config -c 'source " + scripts +
                                           "/robotsim.fish; complete -C \"" + line + "\"'");
    REQUIRE(ok);
    return completionWords(out);
  }
};

}  // namespace

TEST_CASE("robotsim __complete lists the library's cells and robots, and ROBOTSIM_PATH's", "[cli][completion]") {
  const TempDir extra;
  std::filesystem::create_directories(extra.path() / "robots");
  extra.write("my-cell.rsd", "; a flat library folder\n");
  extra.write("robots/my-arm.rsd", "; a robot\n");
  extra.write("notes.txt", "not a description\n");
  ::unsetenv("ROBOTSIM_PATH");
  const auto cells = rs::testing::runCli({"__complete", "cells"});
  CHECK(cells.code == 0);
  CHECK(cells.err == "");
  CHECK(completionWords(cells.out) == stdlibNames(true));
  const auto robots = rs::testing::runCli({"__complete", "robots"});
  CHECK(completionWords(robots.out) == stdlibNames(false));
  CHECK(completionWords(robots.out).count("puma560") == 1);
  CHECK(completionWords(robots.out).count("puma-cell") == 0);

  const auto withLib = rs::testing::runCli({"__complete", "cells", "--lib", extra.path().string()});
  std::set<std::string> expected = stdlibNames(true);
  expected.insert({"my-cell", "my-arm"});
  CHECK(completionWords(withLib.out) == expected);
  ::setenv("ROBOTSIM_PATH", extra.path().c_str(), 1);
  CHECK(completionWords(rs::testing::runCli({"__complete", "robots"}).out).count("my-arm") == 1);
  ::unsetenv("ROBOTSIM_PATH");

  const auto bad = rs::testing::runCli({"__complete", "points"});
  CHECK(bad.code == 2);
  CHECK(bad.out == "");
  CHECK(bad.err.find("robotsim: error: __complete: unknown kind 'points'") == 0);
  CHECK(bad.err.find("usage: robotsim __complete cells|robots") != std::string::npos);
  const auto stray = rs::testing::runCli({"__complete", "cells", "--frob"});
  CHECK(stray.code == 2);
  CHECK(stray.err.find("unexpected '--frob'") != std::string::npos);
  // Not a command: --help does not list it.
  CHECK(rs::testing::runCli({"--help"}).out.find("__complete") == std::string::npos);
}

TEST_CASE("bash completes library names, fixed words and positional cells", "[cli][completion]") {
  if (!completionShellInstalled("bash")) {
    WARN("bash is not installed here; skipped");
    return;
  }
  const CompletionBench bench;
  CHECK(bench.bash("robotsim run prog.rsp --cell ''") == stdlibNames(true));
  CHECK(bench.bash("robotsim run prog.rsp --cell sc") == stdlibNames(true, "sc"));
  CHECK(bench.bash("robotsim run --cell gantry-cell prog.rsp --max-steps 5 --cell g") == stdlibNames(true, "g"));
  CHECK(bench.bash("robotsim emulate --robot p") == stdlibNames(false, "p"));
  CHECK(bench.bash("robotsim emulate --robot p").count("puma-cell") == 0);
  CHECK(bench.bash("robotsim render ''") == stdlibNames(true));
  // A flag takes no value: the word after it is still the cell argument.
  CHECK(bench.bash("robotsim render --axes ''") == stdlibNames(true));
  CHECK(bench.bash("robotsim describe pu") == stdlibNames(true, "pu"));
  CHECK(bench.bash("robotsim ik --frame robot pu") == std::set<std::string>{"puma-cell", "puma560"});
  CHECK(bench.bash("robotsim run prog.rsp --format ''") == std::set<std::string>{"json", "text"});
  CHECK(bench.bash("robotsim test --format c") == std::set<std::string>{"csv"});
  CHECK(bench.bash("robotsim ik --frame ''") == std::set<std::string>{"robot", "world"});
  // Left to bash's file names: a program, the value of --cell's neighbours,
  // a cell argument already given, the numbers after it.
  CHECK(bench.bash("robotsim run --cell gantry-cell ''").empty());
  CHECK(bench.bash("robotsim render gantry-cell --program ''").empty());
  CHECK(bench.bash("robotsim render gantry-cell ''").empty());
  CHECK(bench.bash("robotsim ik puma-cell ''").empty());
  // Commands and options as before.
  CHECK(bench.bash("robotsim ch") == std::set<std::string>{"check"});
  CHECK(bench.bash("robotsim run prog.rsp --max-") == commandOptions(rowOf("run"), "--max-"));
}

TEST_CASE("zsh's completion system completes robotsim from _robotsim", "[cli][completion]") {
  if (!completionShellInstalled("zsh")) {
    WARN("zsh is not installed here (scripts/setup.sh test installs it); skipped");
    return;
  }
  const CompletionBench bench;
  CHECK(bench.zsh("robotsim ch") == tableCommands("ch"));
  CHECK(bench.zsh("robotsim t") == tableCommands("t"));
  CHECK(bench.zsh("robotsim ") == tableCommands());
  CHECK(bench.zsh("robotsim run prog.rsp --max-") == commandOptions(rowOf("run"), "--max-"));
  CHECK(bench.zsh("robotsim compile prog.rsp --o") == std::set<std::string>{"--output"});
  CHECK(bench.zsh("robotsim run prog.rsp --cell sc") == stdlibNames(true, "sc"));
  CHECK(bench.zsh("robotsim run prog.rsp --cell ") == stdlibNames(true));
  CHECK(bench.zsh("robotsim emulate --robot ") == stdlibNames(false));
  CHECK(bench.zsh("robotsim render ") == stdlibNames(true));
  CHECK(bench.zsh("robotsim render --axes ") == stdlibNames(true));
  CHECK(bench.zsh("robotsim test --format ") == std::set<std::string>{"csv", "json", "text"});
}

TEST_CASE("fish completes robotsim from robotsim.fish", "[cli][completion]") {
  if (!completionShellInstalled("fish")) {
    WARN("fish is not installed here (scripts/setup.sh test installs it); skipped");
    return;
  }
  const CompletionBench bench;
  CHECK(bench.fish("robotsim ch") == tableCommands("ch"));
  CHECK(bench.fish("robotsim t") == tableCommands("t"));
  CHECK(bench.fish("robotsim run prog.rsp --max-") == commandOptions(rowOf("run"), "--max-"));
  CHECK(bench.fish("robotsim compile prog.rsp --o") == std::set<std::string>{"--output"});
  CHECK(bench.fish("robotsim run prog.rsp --cell sc") == stdlibNames(true, "sc"));
  CHECK(bench.fish("robotsim run prog.rsp --cell ") == stdlibNames(true));
  CHECK(bench.fish("robotsim emulate --robot ") == stdlibNames(false));
  CHECK(bench.fish("robotsim render ") == stdlibNames(true));
  CHECK(bench.fish("robotsim render --axes ") == stdlibNames(true));
  CHECK(bench.fish("robotsim render gantry-cell ").empty());
  CHECK(bench.fish("robotsim test --format ") == std::set<std::string>{"csv", "json", "text"});
  // Each command with its help, as fish shows it.
  const auto [ok, out] = completionShell(bench.env + "fish --no-config -c 'source " + bench.scripts +
                                         "/robotsim.fish; complete -C \"robotsim chec\"'");
  CHECK(ok);
  CHECK(out == "check\t" + std::string(commandTable()[rowOf("check")].help) + "\n");
}

TEST_CASE("the build wrote the man pages and completions of this command table", "[cli][completion][man]") {
  const std::string docs = rs::testing::generatedDocs();
  const CommandLine commandLine;
  CHECK(rs::testing::readBytes(docs + "/robotsim.bash") == rs::cli::bashCompletion(commandLine));
  CHECK(rs::testing::readBytes(docs + "/_robotsim") == rs::cli::zshCompletion(commandLine));
  CHECK(rs::testing::readBytes(docs + "/robotsim.fish") == rs::cli::fishCompletion(commandLine));
  CHECK(rs::testing::readBytes(docs + "/man1/robotsim.1") == rs::cli::robotsimManPage(commandLine));
  const auto table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    INFO(table[i].name);
    CHECK(rs::testing::readBytes(docs + "/man1/" + rs::cli::manPageFileName(table[i].name)) ==
          rs::cli::commandManPage(commandLine, i));
  }
}
