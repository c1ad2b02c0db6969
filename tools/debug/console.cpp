#include "tools/debug/console.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <sstream>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::debug {

const std::vector<Command>& Console::commands() {
  static const std::vector<Command> kCommands = {
      {"break", "b",
       "break LINE|LABEL|@N|at TIME|when COND|collision|warning|sensor NAME [on|off]|feeder NAME|sink NAME "
       "[if COND] [hits N]",
       "stop at a place or a moment; before a LINE, a LABEL or instruction @N (numbered as disasm lists them), "
       "right after the clock passes TIME, or as COND becomes true (output N on|off, input N on|off, VAR = VALUE), "
       "at the moment of a collision (the pose at the first contact), at a warning (a gripper closing on "
       "nothing), or after the instruction during which a sensor of the cell turns on or off (either edge, or the one "
       "named), a feeder feeds a part or a sink takes one; "
       "if COND: only when COND holds then; hits N: from the Nth time on (== N: only the Nth, % N: every Nth)"},
      {"delete", "d", "delete [ID...]", "delete breakpoints and watches (all of them without an ID)"},
      {"info", "i", "info breakpoints", "list the breakpoints and watches, with their hit counts"},
      {"step", "s", "step [N]", "run one instruction (or N)"},
      {"next", "n", "next", "run one instruction, over a GOSUB (until it returns)"},
      {"finish", "fin", "finish", "run until the current subroutine returns"},
      {"continue", "c", "continue", "run until a breakpoint, a watch or the end"},
      {"until", "u", "until TIME", "run until the clock passes TIME seconds (breakpoints still stop it)"},
      {"reverse-step", "rs", "reverse-step [N]", "go back one instruction (or N)"},
      {"reverse-next", "rn", "reverse-next", "go back one instruction, over a GOSUB"},
      {"reverse-continue", "rc", "reverse-continue",
       "go back to the last breakpoint or watch; the last moment one of them would have stopped the run going "
       "forwards (hit counts aside), else the start"},
      {"goto-time", "gt", "goto-time TIME",
       "go to the moment TIME seconds; exactly, forwards or backwards: inside a move (or a DELAY) the instruction "
       "under way is the current one and motors, tcp and objects show the pose at TIME"},
      {"print", "p", "print [VAR|motors|tcp|io|objects|devices|clock|in N|out N|LETTER]",
       "show a value; a variable (all of them without an argument), the motors, the tool centre point, inputs and "
       "outputs, the workcell's objects, the cell's devices (each sensor, conveyor, feeder and sink, and every part "
       "and where it is), the clock, one input or output, one motor"},
      {"backtrace", "bt", "backtrace", "the GOSUB stack, innermost first, with lines"},
      {"list", "l", "list [LINE]", "the source around the current line (or LINE)"},
      {"disasm", "da", "disasm [@N]", "the instructions around the current one, as robotsim disasm lists them"},
      {"set", "", "set input N on|off | set VAR = VALUE",
       "turn an input on or off, or give a variable a value, from now on (going back and forth replays the change)"},
      {"watch", "w", "watch VAR|output N|input N|LETTER", "stop when a value changes"},
      {"help", "h", "help [COMMAND]", "list the commands, or explain one"},
      {"quit", "q", "quit", "leave the debugger"},
  };
  return kCommands;
}

const std::vector<std::string>& Console::commandNames() {
  static const std::vector<std::string> names = commandNamesOf(commands());
  return names;
}

Console::Console(DebugSession& session, const diag::SourceFile* source, std::ostream& out)
    : session_(session), source_(source), out_(out) {}

void Console::error(std::string_view message) { out_ << "error: " << message << '\n'; }

std::string Console::sourceLine(std::uint32_t line) const {
  if (!source_ || line == 0 || line > source_->lineCount()) return {};
  return base::safeText(source_->line(line));
}

void Console::showStop(const Stop& stop) {
  const runtime::RunView v = session_.view();
  if (stop.reason != StopReason::Step) out_ << stop.message << '\n';
  if (!stop.note.empty()) out_ << stop.note << '\n';
  out_ << fmt::format("line {} @{}, step {}, clock {} s{}\n", v.line, v.instruction + 1, v.steps,
                      base::formatSeconds(v.clock), v.finished ? " (the run is over)" : "");
  const std::string text = sourceLine(v.line);
  if (!text.empty()) out_ << fmt::format("{:>5} | {}\n", v.line, text);
  else out_ << fmt::format("{:>5} | {}\n", v.line, vm::instructionText(*session_.run().spec().image, v.instruction));
}

bool Console::execute(std::string_view text) {
  const CommandLine line = readCommand(text, commands());
  if (line.blank) return true;
  if (!line.command) {
    error(line.error);
    return true;
  }
  const std::string_view name = line.command->name;
  const std::string_view args = line.args;
  const Arguments a(*line.command, args, out_);
  if (name == "quit") return false;
  if (name == "help") printHelp(out_, commands(), args, "commands (short forms in brackets):");
  else if (name == "break") breakCommand(args);
  else if (name == "delete") deleteCommand(args);
  else if (name == "info") infoCommand(args);
  else if (name == "print") printCommand(args);
  else if (name == "watch") watchCommand(args);
  else if (name == "set") setCommand(args);
  else if (name == "list") listCommand(args);
  else if (name == "disasm") disasmCommand(args);
  else if (name == "backtrace") { if (a.none()) backtrace(); }
  else if (name == "step") { if (const auto n = a.count()) moved(session_.step(*n)); }
  else if (name == "next") { if (a.none()) moved(session_.next()); }
  else if (name == "finish") {
    if (a.none()) {
      auto r = session_.finish();
      if (!r) error(r.failure().message);
      else moved(*r);
    }
  }
  else if (name == "continue") { if (a.none()) moved(session_.resume()); }
  else if (name == "until") { if (const auto t = a.time()) moved(session_.until(*t)); }
  else if (name == "reverse-step") { if (const auto n = a.count()) moved(session_.reverseStep(*n)); }
  else if (name == "reverse-next") { if (a.none()) moved(session_.reverseNext()); }
  else if (name == "reverse-continue") { if (a.none()) moved(session_.reverseContinue()); }
  else if (name == "goto-time") { if (const auto t = a.time()) moved(session_.gotoTime(*t)); }
  return true;
}

void Console::breakCommand(std::string_view args) {
  const vm::Image& image = *session_.run().spec().image;
  auto words = readBreak(image, args);
  if (!words) return error(words.failure().message);
  const std::span<const std::string_view> place = words->place;
  if (place.empty()) {
    error("break needs a place: LINE, LABEL, @N, at TIME, when COND, collision, warning, sensor NAME, feeder NAME "
          "or sink NAME (help break)");
    return;
  }
  diag::Result<int> made = diag::refusal("no place");  // every place below sets it
  std::string note;
  if (auto moment = readMomentPlace(session_.run(), place)) {
    if (!*moment) return error(moment->failure().message);
    const MomentPlace& m = **moment;
    if (m.kind == MomentPlace::Kind::Time) made = session_.breakAtTime(m.time);
    else if (m.kind == MomentPlace::Kind::When) made = session_.breakWhen(m.when);
    else if (m.kind == MomentPlace::Kind::Collision) made = session_.breakOnCollision();
    else if (m.kind == MomentPlace::Kind::Warning) made = session_.breakOnWarning();
    else made = session_.breakOnDevice(m.device);
  } else if (place.size() != 1) {
    return error(fmt::format("'{}' is not a place: LINE, LABEL, @N, at TIME, when COND, collision, warning, "
                             "sensor NAME, feeder NAME or sink NAME",
                             shownText(joinedWords(place))));
  } else if (place[0].front() == '@') {
    const auto n = wholeCount(place[0].substr(1));
    if (!n || *n == 0 || *n > UINT32_MAX) return error(fmt::format("'{}': @N takes an instruction number from 1", shownText(place[0])));
    made = session_.breakAtInstruction(static_cast<std::uint32_t>(*n - 1));
  } else if (const auto line = wholeCount(place[0])) {
    if (*line == 0 || *line > UINT32_MAX) return error("lines are numbered from 1");
    made = session_.breakAtLine(static_cast<std::uint32_t>(*line));
    if (const std::uint32_t at = session_.lineWithCode(static_cast<std::uint32_t>(*line)); at != 0 && at != *line)
      note = fmt::format(" (line {} has no instruction)", *line);
  } else {
    made = session_.breakAtLabel(place[0]);
  }
  if (!made) return error(made.failure().message);
  const int id = *made;
  session_.qualify(id, words->condition, words->hits);
  for (const Breakpoint& b : session_.breakpoints())
    if (b.id == id) out_ << fmt::format("breakpoint {}: {}{}\n", id, b.describe(), note);
}

void Console::deleteCommand(std::string_view args) {
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

void Console::infoCommand(std::string_view args) {
  if (!(args == "breakpoints" || args == "break" || args == "b" || args == "watch" || args == "watches"))
    return error(args.empty() ? "info what? info breakpoints lists breakpoints and watches"
                              : fmt::format("info '{}': only info breakpoints is known", shownText(args)));
  if (session_.breakpoints().empty() && session_.watches().empty()) {
    out_ << "no breakpoints or watches\n";
    return;
  }
  out_ << "id  what\n";
  for (const Breakpoint& b : session_.breakpoints())
    out_ << fmt::format("{:<3} break {} (reached {} time{})\n", b.id, b.describe(), b.hitCount, b.hitCount == 1 ? "" : "s");
  for (const Watch& w : session_.watches())
    out_ << fmt::format("{:<3} watch {} (now {})\n", w.id, base::safeText(w.what.name), valueOf(session_.run(), w.what));
}

void Console::printCommand(std::string_view args) {
  const runtime::RunView v = session_.view();
  if (!printRunValue(out_, session_.run(), v, args, session_.run().rig().clock()))
    out_ << fmt::format("clock = {} s (step {})\n", base::formatSeconds(v.clock), v.steps);
}

void Console::watchCommand(std::string_view args) {
  if (args.empty()) return error("watch needs something to watch: VAR, output N, input N or a motor letter");
  auto e = parseExpression(*session_.run().spec().image, ioWords(args));
  if (!e) return error(e.failure().message);
  const Expression& x = *e;
  const int id = session_.watch(x);
  out_ << fmt::format("watch {}: {} (now {})\n", id, base::safeText(x.name), valueOf(session_.run(), x));
}

void Console::setCommand(std::string_view args) {
  const auto w = base::splitWords(args);
  if (w.size() == 3 && w[1] == "=" && !base::sameName(w[0], "input")) return setVariable(w[0], w[2]);
  if (w.size() != 3 || !base::sameName(w[0], "input") || !(base::sameName(w[2], "on") || base::sameName(w[2], "off")))
    return error("usage: set input N on|off, or set VAR = VALUE");
  const auto n = wholeCount(w[1]);
  const bool on = base::sameName(w[2], "on");
  if (!n || *n > static_cast<std::uint64_t>(vm::kIoCount))
    return error(fmt::format("'{}': inputs are 1..{}", shownText(w[1]), vm::kIoCount));
  if (auto problem = session_.setInput(static_cast<int>(*n), on)) return error(*problem);
  const runtime::RunView v = session_.view();
  out_ << fmt::format("input {} is {} from step {} (clock {} s) on\n", *n, on ? "on" : "off", v.steps,
                      base::formatSeconds(v.clock));
}

void Console::setVariable(std::string_view name, std::string_view value) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (ec != std::errc() || ptr != value.data() + value.size())
    return error(fmt::format("'{}' is not a whole number: set VAR = VALUE", shownText(value)));
  if (auto problem = session_.setVariable(name, v)) return error(*problem);
  const runtime::RunView view = session_.view();
  out_ << fmt::format("{} = {} from step {} (clock {} s) on\n", shownText(name), v, view.steps,
                      base::formatSeconds(view.clock));
}

void Console::listCommand(std::string_view args) {
  if (!source_) return error("no source text: the program was loaded from an image (disasm lists its instructions)");
  std::uint32_t centre = session_.view().line;
  if (!args.empty()) {
    const auto n = wholeCount(args);
    if (!n || *n == 0 || *n > source_->lineCount())
      return error(fmt::format("'{}': the program has lines 1 to {}", shownText(args), source_->lineCount()));
    centre = static_cast<std::uint32_t>(*n);
  }
  const std::uint32_t current = session_.view().line;
  const std::uint32_t first = centre > 5 ? centre - 5 : 1;
  const std::uint32_t last = std::min(source_->lineCount(), first + 9);
  for (std::uint32_t l = first; l <= last; ++l)
    out_ << fmt::format("{}{:>4} | {}\n", l == current ? "=>" : "  ", l, sourceLine(l));
}

void Console::disasmCommand(std::string_view args) {
  printDisasm(out_, *session_.run().spec().image, session_.view().instruction, args);
}

// One frame: where, and the source line (or the instruction, without source).
std::string Console::frameText(std::uint32_t line, std::uint32_t instruction) const {
  std::string text(trimmed(sourceLine(line)));
  if (text.empty()) text = vm::instructionText(*session_.run().spec().image, instruction);
  return fmt::format("{:<16} {}", fmt::format("line {} @{}", line, instruction + 1), text);
}

void Console::backtrace() {
  const runtime::RunView v = session_.view();
  out_ << "#0  " << frameText(v.line, v.instruction) << '\n';
  std::size_t depth = 1;
  for (auto f = v.callStack.rbegin(); f != v.callStack.rend(); ++f, ++depth)
    out_ << fmt::format("#{:<3}", depth) << frameText(f->line, f->gosub) << '\n';
}

}  // namespace rs::debug
