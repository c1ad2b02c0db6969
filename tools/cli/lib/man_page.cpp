#include "tools/cli/lib/man_page.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <sstream>
#include <vector>

#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {

namespace {

// The words of exit_codes.h, for EXIT STATUS.
struct ExitMeaning {
  int code;
  std::string_view meaning;
};
constexpr std::array kExitMeanings{
    ExitMeaning{kExitOk, "All is well."},
    ExitMeaning{kExitRunFailed,
                "The program ran and failed: a runtime error, a deadlock, the step or the time limit."},
    ExitMeaning{kExitBadInput,
                "Nothing could run: a compile error, unreadable or corrupt input, or bad usage."},
};

// The title line; no date, so that the same table gives the same bytes.
std::string manHeader(std::string_view title) {
  std::string upper(title);
  for (char& c : upper) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return fmt::format(".TH {} 1 \"\" \"robotsim\" \"User Commands\"\n", troffText(upper));
}

void exitStatus(std::ostringstream& out) {
  out << ".SH EXIT STATUS\n";
  for (const ExitMeaning& e : kExitMeanings) out << ".TP\n.B " << e.code << '\n' << troffText(e.meaning) << '\n';
}

// "\fB\-o\fR, \fB\-\-output\fR \fITEXT\fR": how an option is written.
std::string optionSpelling(const CLI::Option& opt) {
  std::vector<std::string> names;
  for (const std::string& s : opt.get_snames()) names.push_back("\\fB" + troffText("-" + s) + "\\fR");
  for (const std::string& l : opt.get_lnames()) names.push_back("\\fB" + troffText("--" + l) + "\\fR");
  std::string spelled = fmt::format("{}", fmt::join(names, ", "));
  std::string value = opt.get_option_text();
  if (value.empty() && opt.get_type_size() != 0) value = opt.get_type_name();
  if (!value.empty()) spelled += " \\fI" + troffText(value) + "\\fR";
  return spelled;
}

std::string positionalSpelling(const CLI::Option& opt) {
  std::string spelled = "\\fI" + troffText(opt.get_name()) + "\\fR";
  if (opt.get_items_expected_max() > 1) spelled += " .\\|.\\|.";
  return spelled;
}

// A footer is written for an 80-column terminal: lines that start with a
// space are a table (kept as they are), the others one paragraph each run
// of them (filled by the reader's width).
void footerText(std::ostringstream& out, const std::string& footer) {
  std::istringstream lines(footer);
  std::string line;
  bool literal = false;
  while (std::getline(lines, line)) {
    const bool indented = !line.empty() && line[0] == ' ';
    if (indented != literal) {
      out << (indented ? ".nf\n" : ".fi\n");
      literal = indented;
    }
    if (line.empty()) {
      out << ".PP\n";
      continue;
    }
    out << troffText(line) << '\n';
  }
  if (literal) out << ".fi\n";
}

}  // namespace

std::string troffText(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 8);
  for (char c : text) {
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
  }
  // A line starting with . or ' is a request to troff.
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

std::string manPageFileName(std::string_view command) {
  return command.empty() ? "robotsim.1" : fmt::format("robotsim-{}.1", command);
}

std::string robotsimManPage(const CommandLine& commandLine) {
  std::ostringstream out;
  out << manHeader("robotsim");
  std::string_view what = kRobotsimHelp;
  if (what.starts_with("robotsim: ")) what.remove_prefix(10);
  out << ".SH NAME\nrobotsim \\- " << troffText(what) << '\n';
  out << ".SH SYNOPSIS\n.B robotsim\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIARGUMENTS\\fR]\n";
  out << ".SH DESCRIPTION\n"
      << troffText("robotsim compiles robot programs to a verified bytecode image and runs them on a "
                   "deterministic virtual machine that drives a simulated robot. Each command has its own page; "
                   "robotsim COMMAND --help prints the same.")
      << "\n.SS Commands\n";
  const std::span<const Command> table = commandTable();
  for (const Command& command : table)
    out << ".TP\n.B " << troffText(command.name) << '\n' << troffText(command.help) << '\n';
  out << ".SH OPTIONS\n";
  for (const CLI::Option* opt : commandLine.app().get_options())
    out << ".TP\n" << optionSpelling(*opt) << '\n' << troffText(opt->get_description()) << '\n';
  exitStatus(out);
  out << ".SH SEE ALSO\n";
  for (std::size_t i = 0; i < table.size(); ++i)
    out << ".BR robotsim\\-" << troffText(table[i].name) << " (1)" << (i + 1 < table.size() ? ",\n" : "\n");
  return out.str();
}

std::string commandManPage(const CommandLine& commandLine, std::size_t row) {
  const Command& command = commandTable()[row];
  const CLI::App& cmd = commandLine.subcommand(row);
  const std::vector<const CLI::Option*> options = cmd.get_options();
  std::ostringstream out;
  out << manHeader(fmt::format("robotsim-{}", command.name));
  out << ".SH NAME\nrobotsim\\-" << troffText(command.name) << " \\- " << troffText(command.help) << '\n';
  out << ".SH SYNOPSIS\n.B robotsim " << troffText(command.name) << "\n[\\fIOPTIONS\\fR]";
  for (const CLI::Option* opt : options) {
    if (opt->nonpositional()) continue;
    out << (opt->get_required() ? " " : " [") << positionalSpelling(*opt) << (opt->get_required() ? "" : "]");
  }
  out << "\n.SH DESCRIPTION\n" << troffText(command.help) << '\n';
  if (const std::string footer = cmd.get_footer(); !footer.empty()) {
    out << ".PP\n";
    footerText(out, footer);
  }
  out << ".SH OPTIONS\n";
  for (const CLI::Option* opt : options) {
    const std::string spelled = opt->nonpositional() ? optionSpelling(*opt) : positionalSpelling(*opt);
    out << ".TP\n" << spelled << '\n' << troffText(opt->get_description()) << '\n';
  }
  exitStatus(out);
  out << ".SH SEE ALSO\n.BR robotsim (1)\n";
  return out.str();
}

}  // namespace rs::cli
