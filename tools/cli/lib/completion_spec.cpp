#include "tools/cli/lib/completion_spec.h"

#include <CLI/CLI.hpp>

namespace rs::cli {

namespace {

// "TEXT:{text,json}" (CLI11's type name with an IsMember check's
// description): the words between the braces.
std::vector<std::string> choicesOf(const std::string& typeName) {
  std::vector<std::string> words;
  const std::size_t open = typeName.find('{');
  const std::size_t close = typeName.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return words;
  std::string word;
  for (std::size_t i = open + 1; i < close; ++i) {
    if (typeName[i] == ',') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else if (typeName[i] != ' ') {
      word += typeName[i];
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

// The names that mean a description by library name: --cell and the cell
// or robot argument of render, table, matrix, where, describe and ik take a
// workcell or a robot; --robot (emulate) a robot only.
CompletionValue valueKind(const CLI::Option& opt, const std::vector<std::string>& choices) {
  if (!choices.empty()) return CompletionValue::Choice;
  const std::string name = opt.nonpositional() ? opt.get_lnames().empty() ? "" : opt.get_lnames().front()
                                               : opt.get_name();
  if (name == "cell" || (!opt.nonpositional() && name == "robot")) return CompletionValue::Cell;
  if (name == "robot") return CompletionValue::Robot;
  return CompletionValue::File;
}

CompletionOption optionOf(const CLI::Option& opt) {
  CompletionOption o;
  for (const std::string& s : opt.get_snames()) o.names.push_back("-" + s);
  for (const std::string& l : opt.get_lnames()) o.names.push_back("--" + l);
  o.help = opt.get_description();
  // A flag (CLI11 expects no value after it; --trace{text} too: its value
  // only ever follows '=').
  if (opt.get_expected_max() == 0 || opt.get_type_size() == 0) return o;
  o.choices = choicesOf(opt.get_type_name());
  o.value = valueKind(opt, o.choices);
  o.valueName = opt.get_option_text();
  if (o.valueName.empty()) o.valueName = opt.get_type_name().substr(0, opt.get_type_name().find(':'));
  o.repeatable = opt.get_items_expected_max() > 1;
  return o;
}

}  // namespace

CompletionSpec completionSpec(const CommandLine& commandLine) {
  CompletionSpec spec;
  for (const CLI::Option* opt : commandLine.app().get_options()) spec.globalOptions.push_back(optionOf(*opt));
  const std::span<const Command> table = commandTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    CompletionCommand command{std::string(table[i].name), std::string(table[i].help), {}, {}};
    for (const CLI::Option* opt : commandLine.subcommand(i).get_options()) {
      if (opt->nonpositional()) {
        command.options.push_back(optionOf(*opt));
        continue;
      }
      CompletionArgument argument;
      argument.name = opt->get_name();
      argument.help = opt->get_description();
      argument.value = valueKind(*opt, {});
      argument.many = opt->get_items_expected_max() > 1;
      argument.required = opt->get_required();
      command.arguments.push_back(argument);
    }
    spec.commands.push_back(std::move(command));
  }
  return spec;
}

}  // namespace rs::cli
