#include "tools/cli/lib/fish_completion.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

#include "tools/cli/lib/completion_spec.h"

namespace rs::cli {

namespace {

// `text` in single quotes in fish, where only \ and ' are escaped.
std::string fishQuoted(std::string_view text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\\' || c == '\'') out += '\\';
    out += c;
  }
  return out + "'";
}

// "-s o -l output": fish's spelling of an option's names.
std::string fishNames(const CompletionOption& o) {
  std::vector<std::string> parts;
  for (const std::string& n : o.names)
    parts.push_back(n.starts_with("--") ? "-l " + n.substr(2) : "-s " + n.substr(1));
  return fmt::format("{}", fmt::join(parts, " "));
}

// What follows the names: -r (a value) and what completes it.
std::string fishValue(const CompletionOption& o) {
  switch (o.value) {
    case CompletionValue::None: return "";
    case CompletionValue::File: return " -r -F";
    case CompletionValue::Cell: return " -r -a '(__robotsim_names cells)'";
    case CompletionValue::Robot: return " -r -a '(__robotsim_names robots)'";
    case CompletionValue::Choice: return fmt::format(" -x -a {}", fishQuoted(fmt::format("{}", fmt::join(o.choices, " "))));
  }
  return "";
}

}  // namespace

std::string fishCompletion(const CommandLine& commandLine) {
  const CompletionSpec spec = completionSpec(commandLine);
  std::string lines, valued;
  for (const CompletionOption& o : spec.globalOptions)
    lines += fmt::format("complete -c robotsim -n __robotsim_needs_command {}{} -d {}\n", fishNames(o), fishValue(o),
                         fishQuoted(o.help));
  for (const CompletionCommand& c : spec.commands)
    lines += fmt::format("complete -c robotsim -n __robotsim_needs_command -f -a {} -d {}\n", c.name,
                         fishQuoted(c.help));
  for (const CompletionCommand& c : spec.commands) {
    lines += '\n';
    for (const CompletionOption& o : c.options) {
      lines += fmt::format("complete -c robotsim -n '__robotsim_using {}' {}{} -d {}\n", c.name, fishNames(o),
                           fishValue(o), fishQuoted(o.help));
      if (o.value == CompletionValue::None) continue;
      for (const std::string& n : o.names) valued += fmt::format(" '{}:{}'", c.name, n);
    }
    for (std::size_t i = 0; i < c.arguments.size(); ++i)
      if (c.arguments[i].value == CompletionValue::Cell)
        lines += fmt::format("complete -c robotsim -n '__robotsim_argument {} {}' -a '(__robotsim_names cells)' -d {}\n",
                             c.name, i, fishQuoted(c.arguments[i].help));
  }
  return fmt::format(R"fish(# fish completion for robotsim, written by robotsim_gen_docs from the command
# table (tools/cli/lib/commands.cpp): do not edit.

# Library names ($argv[1]: cells, workcells and robots; or robots): robotsim
# itself knows where its library is.
function __robotsim_names
    set -l words (commandline -opc)
    $words[1] __complete $argv[1] 2>/dev/null
end

# Whether robotsim's command word is still to come.
function __robotsim_needs_command
    set -l words (commandline -opc)
    for w in $words[2..-1]
        string match -q -- '-*' $w; or return 1
    end
    return 0
end

# Whether the command word is $argv[1].
function __robotsim_using
    set -l words (commandline -opc)
    for w in $words[2..-1]
        string match -q -- '-*' $w; and continue
        test "$w" = "$argv[1]"
        return
    end
    return 1
end

# Whether the word being completed is positional argument $argv[2] (from 0)
# of command $argv[1]: the words after the command, less options and the
# values of those that take one.
function __robotsim_argument
    set -l words (commandline -opc)
    set -l command ''
    set -l count 0
    set -l skip 0
    for w in $words[2..-1]
        if test $skip = 1
            set skip 0
        else if test -z "$command"
            string match -q -- '-*' $w; or set command $w
        else if string match -q -- '-*=*' $w
        else if string match -q -- '-*' $w
            contains -- "$command:$w"{1}; and set skip 1
        else
            set count (math $count + 1)
        end
    end
    test "$command" = "$argv[1]" -a $skip = 0 -a $count = $argv[2]
end

{0})fish",
                     lines, valued);
}

}  // namespace rs::cli
