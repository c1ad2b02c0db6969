#include "tools/cli/lib/bash_completion.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

#include "tools/cli/lib/completion_spec.h"

namespace rs::cli {

namespace {

// "-o --output --cell ...": every name of every option.
std::string optionWords(const std::vector<CompletionOption>& options) {
  std::vector<std::string> words;
  for (const CompletionOption& o : options) words.insert(words.end(), o.names.begin(), o.names.end());
  return fmt::format("{}", fmt::join(words, " "));
}

// What _robotsim_value answers for an option: none, file, cells, robots,
// or "choice WORD...".
std::string valueWord(const CompletionOption& o) {
  switch (o.value) {
    case CompletionValue::None: return "none";
    case CompletionValue::File: return "file";
    case CompletionValue::Cell: return "cells";
    case CompletionValue::Robot: return "robots";
    case CompletionValue::Choice: return fmt::format("choice {}", fmt::join(o.choices, " "));
  }
  return "file";
}

}  // namespace

std::string bashCompletion(const CommandLine& commandLine) {
  const CompletionSpec spec = completionSpec(commandLine);
  std::vector<std::string> names;
  std::string optionCases, valueCases, argumentCases;
  for (const CompletionCommand& c : spec.commands) {
    names.push_back(c.name);
    optionCases += fmt::format("    {}) echo '{}' ;;\n", c.name, optionWords(c.options));
    for (const CompletionOption& o : c.options) {
      if (o.value == CompletionValue::None) continue;  // the default answer
      std::vector<std::string> keys;
      for (const std::string& n : o.names) keys.push_back(c.name + ":" + n);
      valueCases += fmt::format("    {}) echo '{}' ;;\n", fmt::join(keys, "|"), valueWord(o));
    }
    for (std::size_t i = 0; i < c.arguments.size(); ++i)
      if (c.arguments[i].value == CompletionValue::Cell)
        argumentCases += fmt::format("    {}:{}) echo cells ;;\n", c.name, i);
  }
  // Names, options and choices are plain words (the table's test checks),
  // so they stand in single quotes and compgen -W as they are.
  return fmt::format(R"bash(# bash completion for robotsim, written by robotsim_gen_docs from the command
# table (tools/cli/lib/commands.cpp): do not edit.

# Library names (workcells and robots, or robots alone): robotsim itself
# knows where its library is.
_robotsim_names() {{
  "${{COMP_WORDS[0]}}" __complete "$1" 2>/dev/null
}}

# $1 a command (empty: robotsim itself): its options.
_robotsim_options() {{
  case $1 in
{3}    '') echo '{1}' ;;
  esac
}}

# $1 a command, $2 one of its options: what the option's value is (none,
# file, cells, robots, or choice and the words).
_robotsim_value() {{
  case $1:$2 in
{4}    *) echo none ;;
  esac
}}

# $1 a command, $2 the index of a positional argument: cells or file.
_robotsim_argument() {{
  case $1:$2 in
{5}    *) echo file ;;
  esac
}}

{0}() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} command='' value='' word kind i args=0
  for ((i = 1; i < COMP_CWORD; i++)); do
    word=${{COMP_WORDS[i]}}
    if [[ -z $command ]]; then
      [[ $word == -* ]] || command=$word
      continue
    fi
    case $word in
      -*=*) ;;
      -*)
        kind=$(_robotsim_value "$command" "$word")
        if [[ $kind != none ]]; then
          if ((i + 1 == COMP_CWORD)); then value=$kind; fi
          ((i++))
        fi
        ;;
      *) ((args++)) ;;
    esac
  done
  local words
  if [[ -n $value ]]; then
    case $value in
      cells | robots) words=$(_robotsim_names "$value") ;;
      choice\ *) words=${{value#choice }} ;;
      *) return 0 ;;  # file names: complete -o default
    esac
  elif [[ -z $command ]]; then
    if [[ $cur == -* ]]; then words=$(_robotsim_options ''); else words='{2}'; fi
  elif [[ $cur == -* ]]; then
    words=$(_robotsim_options "$command")
  elif [[ $(_robotsim_argument "$command" "$args") == cells ]]; then
    words=$(_robotsim_names cells)
  else
    return 0
  fi
  mapfile -t COMPREPLY < <(compgen -W "$words" -- "$cur")
}}
complete -o default -F {0} robotsim
)bash",
                     kBashCompletionFunction, optionWords(spec.globalOptions), fmt::join(names, " "), optionCases,
                     valueCases, argumentCases);
}

}  // namespace rs::cli
