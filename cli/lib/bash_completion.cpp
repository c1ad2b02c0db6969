#include "cli/lib/bash_completion.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

namespace rs::cli {

namespace {

// "-o --output --cell ...": every name an option of `app` answers to.
std::string optionWords(const CLI::App& app) {
  std::vector<std::string> words;
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& s : opt->get_snames()) words.push_back("-" + s);
    for (const std::string& l : opt->get_lnames()) words.push_back("--" + l);
  }
  return fmt::format("{}", fmt::join(words, " "));
}

}  // namespace

std::string bashCompletion(const CommandLine& commandLine) {
  const std::span<const Command> table = commandTable();
  std::vector<std::string_view> names;
  for (const Command& command : table) names.push_back(command.name);
  std::string cases;
  for (std::size_t i = 0; i < table.size(); ++i)
    cases += fmt::format("    {}) words='{}' ;;\n", table[i].name, optionWords(commandLine.subcommand(i)));
  // Names and options are plain words (the table's test checks), so they
  // stand in single quotes and compgen -W as they are.
  return fmt::format(R"(# bash completion for robotsim, written by robotsim_gen_docs from the command
# table (cli/lib/commands.cpp): do not edit.
{0}() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} command='' i
  for ((i = 1; i < COMP_CWORD; i++)); do
    case ${{COMP_WORDS[i]}} in
      -*) ;;
      *) command=${{COMP_WORDS[i]}}; break ;;
    esac
  done
  local words
  if [[ -z $command ]]; then
    if [[ $cur == -* ]]; then words='{1}'; else words='{2}'; fi
  else
    [[ $cur == -* ]] || return 0  # file names: complete -o default
    case $command in
{3}    *) return 0 ;;
    esac
  fi
  mapfile -t COMPREPLY < <(compgen -W "$words" -- "$cur")
}}
complete -o default -F {0} robotsim
)",
                     kBashCompletionFunction, optionWords(commandLine.app()), fmt::join(names, " "), cases);
}

}  // namespace rs::cli
