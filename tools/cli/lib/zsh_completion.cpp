#include "tools/cli/lib/zsh_completion.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

#include "tools/cli/lib/completion_spec.h"

namespace rs::cli {

namespace {

// `text` inside single quotes in zsh: each ' closes, is escaped, reopens.
std::string zshSingleQuoted(std::string_view text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// An option's help or a value's name inside an _arguments spec, where
// brackets end the help and colons separate the parts.
std::string zshSpecText(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '\\' || c == '[' || c == ']' || c == ':') out += '\\';
    out += c;
  }
  return out;
}

std::string zshAction(CompletionValue value, const std::vector<std::string>& choices) {
  switch (value) {
    case CompletionValue::None: return "";
    case CompletionValue::File: return "_files";
    case CompletionValue::Cell: return "_robotsim_names cells";
    case CompletionValue::Robot: return "_robotsim_names robots";
    case CompletionValue::Choice: return fmt::format("({})", fmt::join(choices, " "));
  }
  return "_files";
}

// One _arguments spec per name: "--cell[help]:CELL:_robotsim_names cells";
// the other names of the same option excluded once one is given, unless
// it repeats.
std::vector<std::string> zshOptionSpecs(const CompletionOption& o) {
  std::vector<std::string> specs;
  const std::string exclude =
      o.repeatable || o.names.size() < 2 ? "" : fmt::format("({})", fmt::join(o.names, " "));
  for (const std::string& name : o.names) {
    std::string spec = (o.repeatable ? "*" : exclude) + name + "[" + zshSpecText(o.help) + "]";
    if (o.value != CompletionValue::None)
      spec += ":" + zshSpecText(o.valueName.empty() ? "VALUE" : o.valueName) + ":" + zshAction(o.value, o.choices);
    specs.push_back(zshSingleQuoted(spec));
  }
  return specs;
}

std::string zshArgumentSpec(const CompletionArgument& a, std::size_t index) {
  const std::string position = a.many ? "*" : std::to_string(index + 1) + (a.required ? "" : ":");
  return zshSingleQuoted(position + ":" + zshSpecText(a.name) + ":" + zshAction(a.value, {}));
}

}  // namespace

std::string zshCompletion(const CommandLine& commandLine) {
  const CompletionSpec spec = completionSpec(commandLine);
  std::vector<std::string> globals, commands;
  for (const CompletionOption& o : spec.globalOptions)
    for (std::string& s : zshOptionSpecs(o)) globals.push_back(std::move(s));
  std::string cases;
  for (const CompletionCommand& c : spec.commands) {
    commands.push_back(zshSingleQuoted(c.name + ":" + c.help));
    std::vector<std::string> specs;
    for (const CompletionOption& o : c.options)
      for (std::string& s : zshOptionSpecs(o)) specs.push_back(std::move(s));
    for (std::size_t i = 0; i < c.arguments.size(); ++i) specs.push_back(zshArgumentSpec(c.arguments[i], i));
    cases += fmt::format("        {})\n          _arguments -S \\\n            {} && ret=0\n          ;;\n", c.name,
                         fmt::join(specs, " \\\n            "));
  }
  return fmt::format(R"zsh(#compdef robotsim
# zsh completion for robotsim, written by robotsim_gen_docs from the command
# table (tools/cli/lib/commands.cpp): do not edit.

# Library names (the last argument: cells, workcells and robots; or robots),
# which robotsim itself knows where to find, and description files.
# _arguments puts its own options before that word.
_robotsim_names() {{
  local -a names
  names=(${{(f)"$(${{(Q)_robotsim_command}} __complete ${{argv[-1]}} 2>/dev/null)"}})
  _alternative "names:library name:compadd -a names" 'files:description file:_files -g "*.rsd(-.)"'
}}

_robotsim() {{
  local curcontext=$curcontext state state_descr line ret=1
  local _robotsim_command=$words[1]
  typeset -A opt_args
  _arguments -C \
    {0} \
    '1:command:->command' \
    '*::argument:->argument' && ret=0
  case $state in
    command)
      local -a commands
      commands=(
        {1}
      )
      _describe -t commands 'robotsim command' commands && ret=0
      ;;
    argument)
      curcontext=${{curcontext%:*:*}}:robotsim-$words[1]:
      case $words[1] in
{2}      esac
      ;;
  esac
  return ret
}}

_robotsim "$@"
)zsh",
                     fmt::join(globals, " \\\n    "), fmt::join(commands, "\n        "), cases);
}

}  // namespace rs::cli
