#include "tools/debug/cell_console.h"

#include <fmt/format.h>

#include <charconv>

#include "base/ascii.h"
#include "base/near_names.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/debug/expression.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::debug {

struct CellConsole::Command {
  std::string_view name;
  std::string_view shortForm;
  std::string_view usage;
  std::string_view summary;
};

const std::vector<CellConsole::Command>& CellConsole::commands() {
  static const std::vector<Command> kCommands = {
      {"break", "b", "break [FILE:|ROBOT:]LINE",
       "stop before a line of a robot's program: FILE (as given, or its last part) or ROBOT (its label) names "
       "it; without one, the current robot's"},
      {"delete", "d", "delete [ID...]", "delete breakpoints (all of them without an ID)"},
      {"info", "i", "info threads|breakpoints", "list the robots (threads: * marks the current one) or the breakpoints"},
      {"thread", "t", "thread LABEL|N", "make a robot the current one (the one step, print, backtrace and list are about)"},
      {"step", "s", "step [N]", "run the current robot's next instruction (or N), the other robots going on in time with it"},
      {"next", "n", "next", "run the current robot's next instruction, over a GOSUB (until it returns)"},
      {"continue", "c", "continue", "run the cell until a breakpoint or the end"},
      {"until", "u", "until TIME", "run the cell until its clock reaches TIME seconds (breakpoints still stop it)"},
      {"reverse-step", "rs", "reverse-step [N]",
       "put the whole cell back to where the current robot was one instruction (or N) before"},
      {"reverse-continue", "rc", "reverse-continue",
       "put the whole cell back to the last moment a breakpoint would have stopped it, else the start"},
      {"goto-time", "gt", "goto-time TIME", "put the whole cell at the moment TIME seconds, forwards or backwards"},
      {"print", "p", "print [VAR|motors|tcp|io|clock|in N|out N|LETTER]", "show a value of the current robot"},
      {"backtrace", "bt", "backtrace", "the current robot's GOSUB stack, innermost first, with lines"},
      {"list", "l", "list [LINE]", "the current robot's source around its line (or LINE)"},
      {"help", "h", "help [COMMAND]", "list the commands, or explain one"},
      {"quit", "q", "quit", "leave the debugger"},
  };
  return kCommands;
}

const std::vector<std::string>& CellConsole::commandNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Command& c : commands()) n.emplace_back(c.name);
    return n;
  }();
  return names;
}

CellConsole::CellConsole(CellSession& session, std::vector<const diag::SourceFile*> sources, std::ostream& out)
    : session_(session), sources_(std::move(sources)), out_(out) {}

namespace {

std::optional<std::uint64_t> wholeCount(std::string_view text) {
  std::uint64_t n = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return n;
}

std::string shownText(std::string_view text) {
  std::string s = base::safeText(text.substr(0, 60));
  if (text.size() > 60) s += "...";
  return s;
}

}  // namespace

void CellConsole::error(std::string_view message) { out_ << "error: " << message << '\n'; }

std::string CellConsole::sourceLine(std::size_t robot, std::uint32_t line) const {
  const diag::SourceFile* source = robot < sources_.size() ? sources_[robot] : nullptr;
  if (!source || line == 0 || line > source->lineCount()) return {};
  return base::safeText(source->line(line));
}

std::string CellConsole::place(std::size_t robot) const {
  const runtime::RunView v = session_.view(robot);
  return fmt::format("line {} @{}, step {}", v.line, v.instruction + 1, v.steps);
}

void CellConsole::showStop(const CellStop& stop) {
  const std::size_t c = session_.current();
  const runtime::RunView v = session_.view(c);
  if (stop.reason != StopReason::Step) out_ << stop.message << '\n';
  out_ << fmt::format("{}: {}, clock {} s{}\n", base::safeText(session_.label(c)), place(c),
                      base::formatSeconds(session_.clock()), v.finished ? " (the run is over)" : "");
  const std::string text = sourceLine(c, v.line);
  if (!text.empty()) out_ << fmt::format("{:>5} | {}\n", v.line, text);
  else out_ << fmt::format("{:>5} | {}\n", v.line, vm::instructionText(*session_.cell().robot(c).spec().image, v.instruction));
}

bool CellConsole::execute(std::string_view line) {
  line = trimmed(line);
  if (line.empty() || line.front() == '#') return true;
  const std::size_t space = line.find_first_of(" \t");
  const std::string_view word = line.substr(0, space);
  const std::string_view args = space == std::string_view::npos ? std::string_view() : trimmed(line.substr(space));
  const Command* command = nullptr;
  for (const Command& c : commands())
    if (word == c.name || (!c.shortForm.empty() && word == c.shortForm)) command = &c;
  if (!command) {
    const std::string_view near = base::nearestName(word, commandNames());
    error(fmt::format("unknown command '{}'{}; help lists the commands", shownText(word),
                      near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
    return true;
  }
  const std::string_view name = command->name;
  const auto noArgs = [&] {
    if (args.empty()) return true;
    error(fmt::format("{} takes no argument (usage: {})", name, command->usage));
    return false;
  };
  const auto countArg = [&]() -> std::optional<std::uint64_t> {
    if (args.empty()) return 1;
    const auto n = wholeCount(args);
    if (!n || *n == 0) error(fmt::format("'{}' is not a count: {} takes a whole number from 1", shownText(args), name));
    return n && *n > 0 ? n : std::nullopt;
  };
  const auto timeArg = [&]() -> std::optional<vm::Micros> {
    if (args.empty()) {
      error(fmt::format("{} needs a time in seconds (usage: {})", name, command->usage));
      return std::nullopt;
    }
    const auto t = parseSeconds(args);
    if (!t) {
      error(t.failure().message);
      return std::nullopt;
    }
    return std::optional<vm::Micros>(*t);
  };
  if (name == "quit") return false;
  if (name == "help") help(args);
  else if (name == "break") breakCommand(args);
  else if (name == "delete") deleteCommand(args);
  else if (name == "info") infoCommand(args);
  else if (name == "thread") threadCommand(args);
  else if (name == "print") printCommand(args);
  else if (name == "list") listCommand(args);
  else if (name == "backtrace") { if (noArgs()) backtrace(); }
  else if (name == "step") {
    if (const auto n = countArg()) {
      auto r = session_.step(*n);
      if (!r) error(r.failure().message);
      else showStop(*r);
    }
  }
  else if (name == "next") {
    if (noArgs()) {
      auto r = session_.next();
      if (!r) error(r.failure().message);
      else showStop(*r);
    }
  }
  else if (name == "continue") { if (noArgs()) showStop(session_.resume()); }
  else if (name == "until") { if (const auto t = timeArg()) showStop(session_.until(*t)); }
  else if (name == "reverse-step") { if (const auto n = countArg()) showStop(session_.reverseStep(*n)); }
  else if (name == "reverse-continue") { if (noArgs()) showStop(session_.reverseContinue()); }
  else if (name == "goto-time") { if (const auto t = timeArg()) showStop(session_.gotoTime(*t)); }
  return true;
}

void CellConsole::help(std::string_view topic) {
  if (topic.empty()) {
    out_ << "commands (short forms in brackets), on a cell of several robots:\n";
    for (const Command& c : commands()) {
      const std::string usage =
          c.shortForm.empty() ? std::string(c.usage) : fmt::format("{} [{}]", c.usage, c.shortForm);
      if (usage.size() > 36) out_ << fmt::format("  {}\n  {:<36} {}\n", usage, "", c.summary);
      else out_ << fmt::format("  {:<36} {}\n", usage, c.summary);
    }
    out_ << "help COMMAND explains one\n";
    return;
  }
  for (const Command& c : commands())
    if (topic == c.name || (!c.shortForm.empty() && topic == c.shortForm)) {
      out_ << fmt::format("{}{}\n  {}\n", c.usage, c.shortForm.empty() ? "" : fmt::format("  (short: {})", c.shortForm),
                          c.summary);
      return;
    }
  error(fmt::format("no command '{}'; help lists the commands", shownText(topic)));
}

void CellConsole::breakCommand(std::string_view args) {
  if (args.empty()) return error("break needs a place: LINE, FILE:LINE or ROBOT:LINE (help break)");
  std::size_t robot = session_.current();
  std::string_view lineText = args;
  if (const std::size_t colon = args.rfind(':'); colon != std::string_view::npos) {
    const std::string_view who = args.substr(0, colon);
    const auto named = session_.robotNamed(who);
    if (!named) {
      std::string labels;
      for (std::size_t p = 0; p < session_.size(); ++p)
        labels += fmt::format("{}{} ({})", p ? ", " : "", base::safeText(session_.label(p)),
                              session_.fileName(p));
      return error(fmt::format("'{}' names no robot of the cell and none of its programs: {}", shownText(who), labels));
    }
    robot = *named;
    lineText = args.substr(colon + 1);
  }
  const auto line = wholeCount(lineText);
  if (!line || *line == 0 || *line > UINT32_MAX)
    return error(fmt::format("'{}' is not a line: break takes LINE, FILE:LINE or ROBOT:LINE, lines from 1", shownText(args)));
  const auto made = session_.breakAtLine(robot, static_cast<std::uint32_t>(*line));
  if (!made) return error(made.failure().message);
  const std::uint32_t at = session_.lineWithCode(robot, static_cast<std::uint32_t>(*line));
  out_ << fmt::format("breakpoint {}: {} line {} (robot {}){}\n", *made,
                      session_.fileName(robot), at,
                      base::safeText(session_.label(robot)),
                      at != *line ? fmt::format(" (line {} has no instruction)", *line) : "");
}

void CellConsole::deleteCommand(std::string_view args) {
  if (args.empty()) {
    session_.removeAll();
    out_ << "deleted every breakpoint\n";
    return;
  }
  for (std::string_view w : base::splitWords(args)) {
    const auto id = wholeCount(w);
    if (!id || *id > INT32_MAX) error(fmt::format("'{}' is not a breakpoint number", shownText(w)));
    else if (!session_.remove(static_cast<int>(*id))) error(fmt::format("no breakpoint {}", *id));
    else out_ << fmt::format("deleted {}\n", *id);
  }
}

void CellConsole::infoCommand(std::string_view args) {
  if (args == "threads" || args == "thread" || args == "t") {
    out_ << "  id  robot            program              where\n";
    for (std::size_t p = 0; p < session_.size(); ++p) {
      std::string state;
      if (session_.cell().end(p) == runtime::RobotEnd::Finished) state = ", ended";
      else if (session_.cell().end(p) == runtime::RobotEnd::Stopped) state = ", stopped with the cell";
      else if (session_.underWay(p)) state = ", in the instruction under way";
      out_ << fmt::format("{} {:<3} {:<16} {:<20} {}{}\n", p == session_.current() ? '*' : ' ', p + 1,
                          base::safeText(session_.label(p)),
                          session_.fileName(p), place(p), state);
    }
    return;
  }
  if (!(args == "breakpoints" || args == "break" || args == "b"))
    return error(args.empty() ? "info what? info threads lists the robots, info breakpoints the breakpoints"
                              : fmt::format("info '{}': info threads or info breakpoints", shownText(args)));
  if (session_.breakpoints().empty()) {
    out_ << "no breakpoints\n";
    return;
  }
  out_ << "id  what\n";
  for (const CellBreakpoint& b : session_.breakpoints())
    out_ << fmt::format("{:<3} break {} line {} (robot {}, reached {} time{})\n", b.id,
                        session_.fileName(b.robot), b.line,
                        base::safeText(session_.label(b.robot)), b.hitCount, b.hitCount == 1 ? "" : "s");
}

void CellConsole::threadCommand(std::string_view args) {
  if (args.empty()) {
    out_ << fmt::format("the current robot is {} (thread {})\n", base::safeText(session_.label(session_.current())),
                        session_.current() + 1);
    return;
  }
  std::optional<std::size_t> robot = session_.robotNamed(args);
  if (const auto n = wholeCount(args); !robot && n && *n >= 1 && *n <= session_.size()) robot = *n - 1;
  if (!robot) {
    std::string labels;
    for (std::size_t p = 0; p < session_.size(); ++p) labels += fmt::format("{}{}", p ? ", " : "", base::safeText(session_.label(p)));
    return error(fmt::format("no robot '{}' in the cell: its robots are {} (info threads lists them)", shownText(args), labels));
  }
  session_.select(*robot);
  const runtime::RunView v = session_.view(*robot);
  out_ << fmt::format("thread {} ({}): {}, clock {} s\n", *robot + 1, base::safeText(session_.label(*robot)),
                      place(*robot), base::formatSeconds(session_.clock()));
  if (const std::string text = sourceLine(*robot, v.line); !text.empty()) out_ << fmt::format("{:>5} | {}\n", v.line, text);
}

void CellConsole::printCommand(std::string_view args) {
  const std::size_t c = session_.current();
  const runtime::RunView v = session_.view(c);
  const vm::Image& image = *session_.cell().robot(c).spec().image;
  if (args.empty() || args == "variables") {
    if (v.variables.empty()) out_ << "the program has no variables\n";
    for (const auto& [name, value] : v.variables) out_ << fmt::format("{} = {}\n", base::safeText(name), value);
  } else if (args == "motors") {
    for (std::size_t m = 0; m < v.motors.size(); ++m)
      out_ << fmt::format("{} = {}\n", image.motors[m].letter, v.motors[m]);
  } else if (args == "tcp") {
    if (!v.tcp) out_ << "no tool centre point\n";
    else out_ << fmt::format("tcp = ({:.3f}, {:.3f}, {:.3f})\n", (*v.tcp)[0], (*v.tcp)[1], (*v.tcp)[2]);
  } else if (args == "io") {
    const auto bits = [](vm::IoMask mask) {
      std::string s;
      for (int i = 1; i <= vm::kIoCount; ++i) s += vm::lineIsOn(mask, i) ? " 1" : " 0";
      return s;
    };
    out_ << fmt::format("inputs  1-{0}:{1}\noutputs 1-{0}:{2}\n", vm::kIoCount, bits(v.inputs), bits(v.outputs));
  } else if (args == "clock") {
    out_ << fmt::format("clock = {} s (step {} of {})\n", base::formatSeconds(v.clock), v.steps,
                        base::safeText(session_.label(c)));
  } else {
    auto e = parseExpression(image, ioWords(args));
    if (!e) return error(e.failure().message);
    out_ << fmt::format("{} = {}\n", base::safeText(e->name), valueIn(v, *e));
  }
}

void CellConsole::listCommand(std::string_view args) {
  const std::size_t c = session_.current();
  const diag::SourceFile* source = c < sources_.size() ? sources_[c] : nullptr;
  if (!source) return error("no source text: the program was loaded from an image");
  const std::uint32_t current = session_.view(c).line;
  std::uint32_t centre = current;
  if (!args.empty()) {
    const auto n = wholeCount(args);
    if (!n || *n == 0 || *n > source->lineCount())
      return error(fmt::format("'{}': the program has lines 1 to {}", shownText(args), source->lineCount()));
    centre = static_cast<std::uint32_t>(*n);
  }
  const std::uint32_t first = centre > 5 ? centre - 5 : 1;
  const std::uint32_t last = std::min(source->lineCount(), first + 9);
  for (std::uint32_t l = first; l <= last; ++l)
    out_ << fmt::format("{}{:>4} | {}\n", l == current ? "=>" : "  ", l, sourceLine(c, l));
}

void CellConsole::backtrace() {
  const std::size_t c = session_.current();
  const runtime::RunView v = session_.view(c);
  const vm::Image& image = *session_.cell().robot(c).spec().image;
  const auto frame = [&](std::uint32_t line, std::uint32_t instruction) {
    std::string text(trimmed(sourceLine(c, line)));
    if (text.empty()) text = vm::instructionText(image, instruction);
    return fmt::format("{:<16} {}", fmt::format("line {} @{}", line, instruction + 1), text);
  };
  out_ << "#0  " << frame(v.line, v.instruction) << '\n';
  std::size_t depth = 1;
  for (auto f = v.callStack.rbegin(); f != v.callStack.rend(); ++f, ++depth)
    out_ << fmt::format("#{:<3}", depth) << frame(f->line, f->gosub) << '\n';
}

}  // namespace rs::debug
