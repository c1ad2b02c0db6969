#include "tools/debug/console.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <sstream>

#include "base/ascii.h"
#include "base/near_names.h"
#include "base/seconds.h"
#include "base/text.h"
#include "compiler/stimuli/stimuli_text.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::debug {

struct Console::Command {
  std::string_view name;
  std::string_view shortForm;
  std::string_view usage;
  std::string_view summary;
};

const std::vector<Console::Command>& Console::commands() {
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
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Command& c : commands()) n.emplace_back(c.name);
    return n;
  }();
  return names;
}

Console::Console(DebugSession& session, const diag::SourceFile* source, std::ostream& out)
    : session_(session), source_(source), out_(out) {}

namespace {

std::string joined(std::span<const std::string_view> w) {
  std::string s;
  for (std::string_view x : w) s += (s.empty() ? "" : " ") + std::string(x);
  return s;
}

std::optional<std::uint64_t> count(std::string_view text) {
  std::uint64_t n = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
  return n;
}

std::string shown(std::string_view text) {
  std::string s = base::safeText(text.substr(0, 60));
  if (text.size() > 60) s += "...";
  return s;
}

diag::Result<vm::Micros> seconds(std::string_view text) {
  return stimuli::text::parseSeconds(text);
}

}  // namespace

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

bool Console::execute(std::string_view line) {
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
    error(fmt::format("unknown command '{}'{}; help lists the commands", shown(word),
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
    const auto n = count(args);
    if (!n || *n == 0) error(fmt::format("'{}' is not a count: {} takes a whole number from 1", shown(args), name));
    return n && *n > 0 ? n : std::nullopt;
  };
  const auto timeArg = [&]() -> std::optional<vm::Micros> {
    if (args.empty()) {
      error(fmt::format("{} needs a time in seconds (usage: {})", name, command->usage));
      return std::nullopt;
    }
    const auto t = seconds(args);
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
  else if (name == "print") printCommand(args);
  else if (name == "watch") watchCommand(args);
  else if (name == "set") setCommand(args);
  else if (name == "list") listCommand(args);
  else if (name == "disasm") disasmCommand(args);
  else if (name == "backtrace") { if (noArgs()) backtrace(); }
  else if (name == "step") { if (const auto n = countArg()) moved(session_.step(*n)); }
  else if (name == "next") { if (noArgs()) moved(session_.next()); }
  else if (name == "finish") {
    if (noArgs()) {
      auto r = session_.finish();
      if (!r) error(r.failure().message);
      else moved(*r);
    }
  }
  else if (name == "continue") { if (noArgs()) moved(session_.resume()); }
  else if (name == "until") { if (const auto t = timeArg()) moved(session_.until(*t)); }
  else if (name == "reverse-step") { if (const auto n = countArg()) moved(session_.reverseStep(*n)); }
  else if (name == "reverse-next") { if (noArgs()) moved(session_.reverseNext()); }
  else if (name == "reverse-continue") { if (noArgs()) moved(session_.reverseContinue()); }
  else if (name == "goto-time") { if (const auto t = timeArg()) moved(session_.gotoTime(*t)); }
  return true;
}

void Console::help(std::string_view topic) {
  if (topic.empty()) {
    out_ << "commands (short forms in brackets):\n";
    for (const Command& c : commands()) {
      const std::string usage =
          c.shortForm.empty() ? std::string(c.usage) : fmt::format("{} [{}]", c.usage, c.shortForm);
      const std::string_view summary = c.summary.substr(0, c.summary.find(';'));
      if (usage.size() > 36) out_ << fmt::format("  {}\n  {:<36} {}\n", usage, "", summary);
      else out_ << fmt::format("  {:<36} {}\n", usage, summary);
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
  error(fmt::format("no command '{}'; help lists the commands", shown(topic)));
}

void Console::breakCommand(std::string_view args) {
  const std::vector<std::string_view> w = base::splitWords(args);
  std::size_t ifAt = w.size(), hitsAt = w.size();
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (base::sameName(w[i], "if") && ifAt == w.size()) ifAt = i;
    if (base::sameName(w[i], "hits") && hitsAt == w.size()) hitsAt = i;
  }
  const std::size_t placeEnd = std::min(ifAt, hitsAt);
  const std::span<const std::string_view> place(w.data(), placeEnd);
  if (place.empty()) {
    error("break needs a place: LINE, LABEL, @N, at TIME, when COND, collision, warning, sensor NAME, feeder NAME "
          "or sink NAME (help break)");
    return;
  }
  const vm::Image& image = *session_.run().spec().image;
  std::optional<Condition> condition;
  if (ifAt < w.size()) {
    const std::size_t end = hitsAt > ifAt ? hitsAt : w.size();
    auto c = parseCondition(image, ioWords(joined(std::span(w).subspan(ifAt + 1, end - ifAt - 1))));
    if (!c) return error(c.failure().message);
    condition = *c;
  }
  std::optional<HitCondition> hits;
  if (hitsAt < w.size()) {
    const std::size_t end = ifAt > hitsAt ? ifAt : w.size();
    auto h = parseHitCondition(joined(std::span(w).subspan(hitsAt + 1, end - hitsAt - 1)));
    if (!h) return error(h.failure().message);
    hits = *h;
  }
  diag::Result<int> made = diag::refusal("no place");  // every place below sets it
  std::string note;
  if (base::sameName(place[0], "at")) {
    if (place.size() != 2) return error("break at TIME takes one time in seconds, e.g. break at 2.5");
    const auto t = seconds(place[1]);
    if (!t) return error(t.failure().message);
    made = session_.breakAtTime(*t);
  } else if (base::sameName(place[0], "when")) {
    if (place.size() < 2) return error("break when needs a condition: output N on|off, input N on|off, VAR = VALUE");
    auto c = parseCondition(image, ioWords(joined(place.subspan(1))));
    if (!c) return error(c.failure().message);
    made = session_.breakWhen(*c);
  } else if (place.size() == 1 && base::sameName(place[0], "collision")) {
    made = session_.breakOnCollision();
  } else if (place.size() == 1 && base::sameName(place[0], "warning")) {
    made = session_.breakOnWarning();
  } else if (isDeviceWord(place[0]) && (place.size() > 1 || !runtime::labelInstruction(image, place[0]))) {
    auto point = parseDevicePoint(session_.run(), place);
    if (!point) return error(point.failure().message);
    made = session_.breakOnDevice(*point);
  } else if (place.size() != 1) {
    return error(fmt::format("'{}' is not a place: LINE, LABEL, @N, at TIME, when COND, collision, warning, "
                             "sensor NAME, feeder NAME or sink NAME",
                             shown(joined(place))));
  } else if (place[0].front() == '@') {
    const auto n = count(place[0].substr(1));
    if (!n || *n == 0 || *n > UINT32_MAX) return error(fmt::format("'{}': @N takes an instruction number from 1", shown(place[0])));
    made = session_.breakAtInstruction(static_cast<std::uint32_t>(*n - 1));
  } else if (const auto line = count(place[0])) {
    if (*line == 0 || *line > UINT32_MAX) return error("lines are numbered from 1");
    made = session_.breakAtLine(static_cast<std::uint32_t>(*line));
    if (const std::uint32_t at = session_.lineWithCode(static_cast<std::uint32_t>(*line)); at != 0 && at != *line)
      note = fmt::format(" (line {} has no instruction)", *line);
  } else {
    made = session_.breakAtLabel(place[0]);
  }
  if (!made) return error(made.failure().message);
  const int id = *made;
  session_.qualify(id, condition, hits);
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
    const auto id = count(w);
    if (!id || *id > INT32_MAX) error(fmt::format("'{}' is not a breakpoint number", shown(w)));
    else if (!session_.remove(static_cast<int>(*id))) error(fmt::format("no breakpoint or watch {}", *id));
    else out_ << fmt::format("deleted {}\n", *id);
  }
}

void Console::infoCommand(std::string_view args) {
  if (!(args == "breakpoints" || args == "break" || args == "b" || args == "watch" || args == "watches"))
    return error(args.empty() ? "info what? info breakpoints lists breakpoints and watches"
                              : fmt::format("info '{}': only info breakpoints is known", shown(args)));
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
  const vm::Image& image = *session_.run().spec().image;
  if (args.empty() || args == "variables") {
    if (v.variables.empty()) out_ << "the program has no variables\n";
    for (const auto& [name, value] : v.variables) out_ << fmt::format("{} = {}\n", base::safeText(name), value);
  } else if (args == "motors") {
    for (std::size_t m = 0; m < v.motors.size(); ++m)
      out_ << fmt::format("{} = {}\n", image.motors[m].letter, v.motors[m]);
  } else if (args == "tcp") {
    if (!v.tcp) out_ << "no tool centre point: the program runs without a workcell (--cell)\n";
    else out_ << fmt::format("tcp = ({:.3f}, {:.3f}, {:.3f})\n", (*v.tcp)[0], (*v.tcp)[1], (*v.tcp)[2]);
  } else if (args == "io") {
    const auto bits = [](vm::IoMask mask) {
      std::string s;
      for (int i = 1; i <= vm::kIoCount; ++i) s += vm::lineIsOn(mask, i) ? " 1" : " 0";
      return s;
    };
    out_ << fmt::format("inputs  1-{0}:{1}\noutputs 1-{0}:{2}\n", vm::kIoCount, bits(v.inputs), bits(v.outputs));
  } else if (args == "objects") {
    if (v.objects.empty()) out_ << "no objects: the program runs without a workcell (--cell), or it has none\n";
    // By the run's numbers (robotsim test's `object N`): the cell's own
    // objects 1, 2, ...; a fed part the number it was given; a feeder's
    // empty slot and a part a sink took are not in the cell.
    std::vector<const runtime::ObjectView*> present;
    for (const runtime::ObjectView& o : v.objects)
      if (o.present) present.push_back(&o);
    std::stable_sort(present.begin(), present.end(), [](auto* a, auto* b) { return a->number < b->number; });
    for (const runtime::ObjectView* p : present)
      out_ << fmt::format("{} {} at ({:.3f}, {:.3f}, {:.3f}), centre ({:.3f}, {:.3f}, {:.3f}){}{}\n", p->number,
                          base::safeText(p->name), p->at.x(), p->at.y(), p->at.z(), p->centre.x(), p->centre.y(),
                          p->centre.z(), p->held ? ", held" : "", p->moved ? ", moved" : "");
  } else if (args == "devices") {
    const std::vector<DeviceRow> rows = deviceRows(session_.run(), v);
    if (rows.empty()) out_ << "no devices: the cell has no sensors, conveyors, feeders or sinks (or no workcell: --cell)\n";
    for (const DeviceRow& row : rows) out_ << fmt::format("{:<18} {}\n", row.name, row.value);
    // Inside an instruction under way (goto-time, a collision): the run stands after it.
    if (const vm::Micros end = session_.run().rig().clock(); !rows.empty() && v.clock < end)
      out_ << fmt::format("(the devices and the parts as they are at {} s, when the instruction under way ends)\n",
                          base::formatSeconds(end));
  } else if (args == "clock") {
    out_ << fmt::format("clock = {} s (step {})\n", base::formatSeconds(v.clock), v.steps);
  } else {
    auto e = parseExpression(image, ioWords(args));
    if (!e) return error(e.failure().message);
    const Expression& x = *e;
    out_ << fmt::format("{} = {}\n", base::safeText(x.name), valueIn(v, x));
  }
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
  const auto n = count(w[1]);
  const bool on = base::sameName(w[2], "on");
  if (!n || *n > static_cast<std::uint64_t>(vm::kIoCount))
    return error(fmt::format("'{}': inputs are 1..{}", shown(w[1]), vm::kIoCount));
  if (auto problem = session_.setInput(static_cast<int>(*n), on)) return error(*problem);
  const runtime::RunView v = session_.view();
  out_ << fmt::format("input {} is {} from step {} (clock {} s) on\n", *n, on ? "on" : "off", v.steps,
                      base::formatSeconds(v.clock));
}

void Console::setVariable(std::string_view name, std::string_view value) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (ec != std::errc() || ptr != value.data() + value.size())
    return error(fmt::format("'{}' is not a whole number: set VAR = VALUE", shown(value)));
  if (auto problem = session_.setVariable(name, v)) return error(*problem);
  const runtime::RunView view = session_.view();
  out_ << fmt::format("{} = {} from step {} (clock {} s) on\n", shown(name), v, view.steps,
                      base::formatSeconds(view.clock));
}

void Console::listCommand(std::string_view args) {
  if (!source_) return error("no source text: the program was loaded from an image (disasm lists its instructions)");
  std::uint32_t centre = session_.view().line;
  if (!args.empty()) {
    const auto n = count(args);
    if (!n || *n == 0 || *n > source_->lineCount())
      return error(fmt::format("'{}': the program has lines 1 to {}", shown(args), source_->lineCount()));
    centre = static_cast<std::uint32_t>(*n);
  }
  const std::uint32_t current = session_.view().line;
  const std::uint32_t first = centre > 5 ? centre - 5 : 1;
  const std::uint32_t last = std::min(source_->lineCount(), first + 9);
  for (std::uint32_t l = first; l <= last; ++l)
    out_ << fmt::format("{}{:>4} | {}\n", l == current ? "=>" : "  ", l, sourceLine(l));
}

void Console::disasmCommand(std::string_view args) {
  const vm::Image& image = *session_.run().spec().image;
  const std::uint32_t current = session_.view().instruction;
  std::uint32_t centre = current;
  if (!args.empty()) {
    const auto n = args.front() == '@' ? count(args.substr(1)) : std::nullopt;
    if (!n || *n == 0 || *n > image.code.size())
      return error(fmt::format("'{}': disasm takes @N, N from 1 to {}", shown(args), image.code.size()));
    centre = static_cast<std::uint32_t>(*n - 1);
  }
  const std::uint32_t first = centre > 4 ? centre - 4 : 0;
  const std::uint32_t last = std::min<std::uint32_t>(static_cast<std::uint32_t>(image.code.size()) - 1, first + 9);
  for (std::uint32_t i = first; i <= last; ++i)
    out_ << (i == current ? "=>" : "  ") << vm::listingRow(image, i) << '\n';
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
