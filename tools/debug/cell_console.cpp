#include "tools/debug/cell_console.h"

#include <fmt/format.h>

#include <cctype>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/debug/device_points.h"
#include "tools/debug/expression.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::debug {

const std::vector<Command>& CellConsole::commands() {
  static const std::vector<Command> kCommands = {
      {"break", "b",
       "break [FILE:|ROBOT:]LINE|LABEL|@N|at TIME|when COND|collision|warning|sensor NAME [on|off]|feeder NAME|sink NAME "
       "[if COND] [hits N]",
       "stop before a line, a label or instruction @N of a robot's program (the current robot's, or FILE:... with "
       "FILE as given or its last part, or ROBOT:... with ROBOT its label), right after the cell's clock passes TIME, as COND on the current robot "
       "becomes true (output N on|off, input N on|off, VAR = VALUE), after the step of any robot during which it "
       "collided (--collisions warn) or its gripper closed on nothing, or after the step during which a sensor of the "
       "cell turns on or off (either edge, or the one named), a feeder feeds a part or a sink takes one; "
       "if COND: only when COND (on the current robot) holds then; hits N: from the Nth time on (== N: only the "
       "Nth, % N: every Nth)"},
      {"delete", "d", "delete [ID...]", "delete breakpoints and watches (all of them without an ID)"},
      {"info", "i", "info threads|breakpoints",
       "list the robots (threads: * marks the current one) or the breakpoints and watches"},
      {"thread", "t", "thread LABEL|N", "make a robot the current one (the one step, print, backtrace and list are about)"},
      {"step", "s", "step [N]", "run the current robot's next instruction (or N), the other robots going on in time with it"},
      {"next", "n", "next", "run the current robot's next instruction, over a GOSUB (until it returns)"},
      {"finish", "fin", "finish", "run until the current robot's subroutine returns, the others going on in time"},
      {"continue", "c", "continue", "run the cell until a breakpoint, a watch or the end"},
      {"until", "u", "until TIME", "run the cell until its clock reaches TIME seconds (breakpoints still stop it)"},
      {"reverse-step", "rs", "reverse-step [N]",
       "put the whole cell back to where the current robot was one instruction (or N) before"},
      {"reverse-next", "rn", "reverse-next", "as reverse-step, over a GOSUB of the current robot"},
      {"reverse-continue", "rc", "reverse-continue",
       "put the whole cell back to the last moment a breakpoint or watch would have stopped it, else the start"},
      {"goto-time", "gt", "goto-time TIME", "put the whole cell at the moment TIME seconds, forwards or backwards"},
      {"print", "p", "print [VAR|motors|tcp|io|objects|devices|clock|in N|out N|LETTER]",
       "show a value of the current robot, the cell's objects (as the current robot sees them: held is by its "
       "gripper), or the cell's devices (each sensor, conveyor, feeder and sink, and every part and where it is)"},
      {"watch", "w", "watch VAR|output N|input N|LETTER", "stop when a value of the current robot changes"},
      {"set", "", "set input N on|off",
       "turn an input of the current robot on or off from the cell's present moment on (a stimulus then, "
       "replayed whenever the cell runs again from its start)"},
      {"backtrace", "bt", "backtrace", "the current robot's GOSUB stack, innermost first, with lines"},
      {"list", "l", "list [LINE]", "the current robot's source around its line (or LINE)"},
      {"disasm", "da", "disasm [@N]", "the current robot's instructions around its current one, as robotsim disasm lists them"},
      {"help", "h", "help [COMMAND]", "list the commands, or explain one"},
      {"quit", "q", "quit", "leave the debugger"},
  };
  return kCommands;
}

const std::vector<std::string>& CellConsole::commandNames() {
  static const std::vector<std::string> names = commandNamesOf(commands());
  return names;
}

CellConsole::CellConsole(CellSession& session, std::vector<const diag::SourceFile*> sources, std::ostream& out)
    : session_(session), sources_(std::move(sources)), out_(out) {}

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

bool CellConsole::execute(std::string_view text) {
  const CommandLine line = readCommand(text, commands());
  if (line.blank) return true;
  if (!line.command) {
    error(line.error);
    return true;
  }
  const std::string_view name = line.command->name;
  const std::string_view args = line.args;
  const Arguments a(*line.command, args, out_);
  const auto moved = [this](const diag::Result<CellStop>& r) {
    if (!r) error(r.failure().message);
    else showStop(*r);
  };
  if (name == "quit") return false;
  if (name == "help") printHelp(out_, commands(), args, "commands (short forms in brackets), on a cell of several robots:");
  else if (name == "break") breakCommand(args);
  else if (name == "delete") deleteCommand(args);
  else if (name == "info") infoCommand(args);
  else if (name == "thread") threadCommand(args);
  else if (name == "print") printCommand(args);
  else if (name == "watch") watchCommand(args);
  else if (name == "set") setCommand(args);
  else if (name == "list") listCommand(args);
  else if (name == "disasm") {
    const std::size_t c = session_.current();
    printDisasm(out_, *session_.cell().robot(c).spec().image, session_.view(c).instruction, args);
  }
  else if (name == "backtrace") { if (a.none()) backtrace(); }
  else if (name == "step") { if (const auto n = a.count()) moved(session_.step(*n)); }
  else if (name == "next") { if (a.none()) moved(session_.next()); }
  else if (name == "finish") { if (a.none()) moved(session_.finish()); }
  else if (name == "continue") { if (a.none()) showStop(session_.resume()); }
  else if (name == "until") { if (const auto t = a.time()) showStop(session_.until(*t)); }
  else if (name == "reverse-step") { if (const auto n = a.count()) showStop(session_.reverseStep(*n)); }
  else if (name == "reverse-next") { if (a.none()) showStop(session_.reverseNext()); }
  else if (name == "reverse-continue") { if (a.none()) showStop(session_.reverseContinue()); }
  else if (name == "goto-time") { if (const auto t = a.time()) showStop(session_.gotoTime(*t)); }
  return true;
}

void CellConsole::breakCommand(std::string_view args) {
  const std::size_t c = session_.current();
  const runtime::Run& run = session_.cell().robot(c);
  auto words = readBreak(*run.spec().image, args);
  if (!words) return error(words.failure().message);
  const std::span<const std::string_view> place = words->place;
  if (place.empty())
    return error("break needs a place: LINE, FILE:LINE, ROBOT:LINE, LABEL, @N, at TIME, when COND, collision, warning, "
                 "sensor NAME, feeder NAME or sink NAME (help break)");
  diag::Result<int> made = diag::refusal("no place");  // every place below sets it
  std::string note;
  if (auto moment = readMomentPlace(run, place)) {
    if (!*moment) return error(moment->failure().message);
    const MomentPlace& m = **moment;
    if (m.kind == MomentPlace::Kind::Time) made = session_.breakAtTime(m.time);
    else if (m.kind == MomentPlace::Kind::When) made = session_.breakWhen(c, m.when);
    else if (m.kind == MomentPlace::Kind::Collision) made = session_.breakOnCollision();
    else if (m.kind == MomentPlace::Kind::Warning) made = session_.breakOnWarning();
    else made = session_.breakOnDevice(m.device);
  } else if (place.size() != 1) {
    return error(fmt::format("'{}' is not a place: LINE, FILE:LINE, ROBOT:LINE, at TIME, when COND, sensor NAME, "
                             "feeder NAME or sink NAME", shownText(joinedWords(place))));
  } else {
    made = lineBreakpoint(place[0], note);
    if (!made) return error(made.failure().message);
  }
  if (!made) return error(made.failure().message);
  session_.qualify(*made, words->condition, words->hits);
  for (const CellBreakpoint& b : session_.breakpoints())
    if (b.id == *made)
      out_ << fmt::format("breakpoint {}: {}{}{}\n", b.id, session_.describe(b),
                          b.inProgram() ? fmt::format(" (robot {})", base::safeText(session_.label(b.robot))) : "",
                          note);
}

// LINE, FILE:LINE or ROBOT:LINE; `note` says when the line asked has no instruction.
diag::Result<int> CellConsole::lineBreakpoint(std::string_view args, std::string& note) {
  std::size_t robot = session_.current();
  std::string_view lineText = args;
  if (const std::size_t colon = args.rfind(':'); colon != std::string_view::npos) {
    const std::string_view who = args.substr(0, colon);
    const auto named = session_.robotNamed(who);
    if (!named) {
      std::string labels;
      for (std::size_t p = 0; p < session_.size(); ++p)
        labels += fmt::format("{}{} ({})", p ? ", " : "", base::safeText(session_.label(p)), session_.fileName(p));
      return diag::refusal(
          fmt::format("'{}' names no robot of the cell and none of its programs: {}", shownText(who), labels));
    }
    robot = *named;
    lineText = args.substr(colon + 1);
  }
  if (!lineText.empty() && lineText.front() == '@') {
    const auto n = wholeCount(lineText.substr(1));
    if (!n || *n == 0 || *n > UINT32_MAX)
      return diag::refusal(fmt::format("'{}': @N takes an instruction number from 1", shownText(lineText)));
    return session_.breakAtInstruction(robot, static_cast<std::uint32_t>(*n - 1));
  }
  const auto line = wholeCount(lineText);
  if (!line && !lineText.empty() && !std::isdigit(static_cast<unsigned char>(lineText.front()))) {
    auto made = session_.breakAtLabel(robot, lineText);
    if (made) return made;
    return diag::refusal(fmt::format("'{}' is not a line or a label of {}: its program has no label '{}'", shownText(args),
                                     session_.fileName(robot), shownText(lineText)));
  }
  if (!line || *line == 0 || *line > UINT32_MAX)
    return diag::refusal(fmt::format("'{}' is not a line: break takes LINE, FILE:LINE or ROBOT:LINE, lines from 1",
                                     shownText(args)));
  auto made = session_.breakAtLine(robot, static_cast<std::uint32_t>(*line));
  if (const std::uint32_t at = session_.lineWithCode(robot, static_cast<std::uint32_t>(*line)); made && at != *line)
    note = fmt::format(" (line {} has no instruction)", *line);
  return made;
}

void CellConsole::deleteCommand(std::string_view args) {
  if (args.empty()) {
    session_.removeAll();
    out_ << "deleted every breakpoint and watch\n";
    return;
  }
  for (std::string_view w : base::splitWords(args)) {
    const auto id = wholeCount(w);
    if (!id || *id > INT32_MAX) error(fmt::format("'{}' is not a breakpoint number", shownText(w)));
    else if (!session_.remove(static_cast<int>(*id))) error(fmt::format("no breakpoint or watch {}", *id));
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
  if (!(args == "breakpoints" || args == "break" || args == "b" || args == "watch" || args == "watches"))
    return error(args.empty() ? "info what? info threads lists the robots, info breakpoints the breakpoints and watches"
                              : fmt::format("info '{}': info threads or info breakpoints", shownText(args)));
  if (session_.breakpoints().empty() && session_.watches().empty()) {
    out_ << "no breakpoints or watches\n";
    return;
  }
  out_ << "id  what\n";
  for (const CellBreakpoint& b : session_.breakpoints()) {
    const std::string reached = fmt::format("reached {} time{}", b.hitCount, b.hitCount == 1 ? "" : "s");
    if (b.inProgram())
      out_ << fmt::format("{:<3} break {} (robot {}, {})\n", b.id, session_.describe(b),
                          base::safeText(session_.label(b.robot)), reached);
    else out_ << fmt::format("{:<3} break {} ({})\n", b.id, session_.describe(b), reached);
  }
  for (const CellWatch& w : session_.watches())
    out_ << fmt::format("{:<3} watch {} of {} (now {})\n", w.id, base::safeText(w.what.name),
                        base::safeText(session_.label(w.robot)), valueIn(session_.view(w.robot), w.what));
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
  if (!printRunValue(out_, session_.cell().robot(c), v, args, session_.cell().clock()))
    out_ << fmt::format("clock = {} s (step {} of {})\n", base::formatSeconds(v.clock), v.steps,
                        base::safeText(session_.label(c)));
}

void CellConsole::watchCommand(std::string_view args) {
  if (args.empty()) return error("watch needs something to watch: VAR, output N, input N or a motor letter");
  const std::size_t c = session_.current();
  auto e = parseExpression(*session_.cell().robot(c).spec().image, ioWords(args));
  if (!e) return error(e.failure().message);
  const int id = session_.watch(c, *e);
  out_ << fmt::format("watch {}: {} of {} (now {})\n", id, base::safeText(e->name), base::safeText(session_.label(c)),
                      valueIn(session_.view(c), *e));
}

void CellConsole::setCommand(std::string_view args) {
  const auto w = base::splitWords(args);
  if (w.size() != 3 || !base::sameName(w[0], "input") || !(base::sameName(w[2], "on") || base::sameName(w[2], "off")))
    return error("usage: set input N on|off (on a cell of several robots a variable cannot be set yet)");
  const auto n = wholeCount(w[1]);
  const bool on = base::sameName(w[2], "on");
  if (!n || *n > static_cast<std::uint64_t>(vm::kIoCount))
    return error(fmt::format("'{}': inputs are 1..{}", shownText(w[1]), vm::kIoCount));
  const std::size_t c = session_.current();
  if (auto problem = session_.setInput(c, static_cast<int>(*n), on)) return error(*problem);
  out_ << fmt::format("input {} of {} is {} from {} s on\n", *n, base::safeText(session_.label(c)), on ? "on" : "off",
                      base::formatSeconds(session_.clock()));
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
