#include "tools/debug/command_line.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "base/ascii.h"
#include "base/near_names.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/debug/input_causes.h"
#include "vm/disasm.h"
#include "vm/io_lines.h"

namespace rs::debug {

std::vector<std::string> commandNamesOf(std::span<const Command> commands) {
  std::vector<std::string> n;
  for (const Command& c : commands) n.emplace_back(c.name);
  return n;
}

CommandLine readCommand(std::string_view line, std::span<const Command> commands) {
  CommandLine r;
  line = trimmed(line);
  if (line.empty() || line.front() == '#') {
    r.blank = true;
    return r;
  }
  const std::size_t space = line.find_first_of(" \t");
  const std::string_view word = line.substr(0, space);
  r.args = space == std::string_view::npos ? std::string_view() : trimmed(line.substr(space));
  for (const Command& c : commands)
    if (c.is(word)) r.command = &c;
  if (!r.command) {
    const std::vector<std::string> names = commandNamesOf(commands);  // nearestName's answer points into it
    const std::string_view near = base::nearestName(word, names);
    r.error = fmt::format("unknown command '{}'{}; help lists the commands", shownText(word),
                          near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near));
  }
  return r;
}

void printHelp(std::ostream& out, std::span<const Command> commands, std::string_view topic, std::string_view heading) {
  if (topic.empty()) {
    out << heading << '\n';
    for (const Command& c : commands) {
      const std::string usage =
          c.shortForm.empty() ? std::string(c.usage) : fmt::format("{} [{}]", c.usage, c.shortForm);
      const std::string_view summary = c.summary.substr(0, c.summary.find(';'));
      if (usage.size() > 36) out << fmt::format("  {}\n  {:<36} {}\n", usage, "", summary);
      else out << fmt::format("  {:<36} {}\n", usage, summary);
    }
    out << "help COMMAND explains one\n";
    return;
  }
  for (const Command& c : commands)
    if (c.is(topic)) {
      out << fmt::format("{}{}\n  {}\n", c.usage, c.shortForm.empty() ? "" : fmt::format("  (short: {})", c.shortForm),
                         c.summary);
      return;
    }
  out << fmt::format("error: no command '{}'; help lists the commands\n", shownText(topic));
}

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

std::string joinedWords(std::span<const std::string_view> words) {
  std::string s;
  for (std::string_view x : words) s += (s.empty() ? "" : " ") + std::string(x);
  return s;
}

bool Arguments::none() const {
  if (args_.empty()) return true;
  out_ << fmt::format("error: {} takes no argument (usage: {})\n", command_.name, command_.usage);
  return false;
}

std::optional<std::uint64_t> Arguments::count() const {
  if (args_.empty()) return 1;
  const auto n = wholeCount(args_);
  if (!n || *n == 0)
    out_ << fmt::format("error: '{}' is not a count: {} takes a whole number from 1\n", shownText(args_), command_.name);
  return n && *n > 0 ? n : std::nullopt;
}

std::optional<vm::Micros> Arguments::time() const {
  if (args_.empty()) {
    out_ << fmt::format("error: {} needs a time in seconds (usage: {})\n", command_.name, command_.usage);
    return std::nullopt;
  }
  const auto t = parseSeconds(args_);
  if (!t) {
    out_ << "error: " << t.failure().message << '\n';
    return std::nullopt;
  }
  return std::optional<vm::Micros>(*t);
}

diag::Result<BreakWords> readBreak(const vm::Image& image, std::string_view args) {
  const std::vector<std::string_view> w = base::splitWords(args);
  std::size_t ifAt = w.size(), hitsAt = w.size();
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (base::sameName(w[i], "if") && ifAt == w.size()) ifAt = i;
    if (base::sameName(w[i], "hits") && hitsAt == w.size()) hitsAt = i;
  }
  BreakWords b;
  b.place.assign(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(std::min(ifAt, hitsAt)));
  if (b.place.empty()) return b;
  if (ifAt < w.size()) {
    const std::size_t end = hitsAt > ifAt ? hitsAt : w.size();
    auto c = parseCondition(image, ioWords(joinedWords(std::span(w).subspan(ifAt + 1, end - ifAt - 1))));
    if (!c) return c.failure();
    b.condition = *c;
  }
  if (hitsAt < w.size()) {
    const std::size_t end = ifAt > hitsAt ? ifAt : w.size();
    auto h = parseHitCondition(joinedWords(std::span(w).subspan(hitsAt + 1, end - hitsAt - 1)));
    if (!h) return h.failure();
    b.hits = *h;
  }
  return b;
}

std::optional<diag::Result<MomentPlace>> readMomentPlace(const runtime::Run& run,
                                                        std::span<const std::string_view> place) {
  const vm::Image& image = *run.spec().image;
  MomentPlace m;
  if (base::sameName(place[0], "at")) {
    if (place.size() != 2) return diag::refusal("break at TIME takes one time in seconds, e.g. break at 2.5");
    auto t = parseSeconds(place[1]);
    if (!t) return t.failure();
    m.time = *t;
  } else if (base::sameName(place[0], "when")) {
    if (place.size() < 2) return diag::refusal("break when needs a condition: output N on|off, input N on|off, VAR = VALUE");
    auto c = parseCondition(image, ioWords(joinedWords(place.subspan(1))));
    if (!c) return c.failure();
    m.kind = MomentPlace::Kind::When, m.when = *c;
  } else if (place.size() == 1 && base::sameName(place[0], "collision")) {
    m.kind = MomentPlace::Kind::Collision;
  } else if (place.size() == 1 && base::sameName(place[0], "warning")) {
    m.kind = MomentPlace::Kind::Warning;
  } else if (isDeviceWord(place[0]) && (place.size() > 1 || !runtime::labelInstruction(image, place[0]))) {
    auto point = parseDevicePoint(run, place);
    if (!point) return point.failure();
    m.kind = MomentPlace::Kind::Device, m.device = *point;
  } else {
    return std::nullopt;
  }
  return diag::Result<MomentPlace>(std::move(m));
}

bool printRunValue(std::ostream& out, const runtime::Run& run, const runtime::RunView& v, std::string_view args,
                   vm::Micros devicesAt) {
  const vm::Image& image = *run.spec().image;
  if (args.empty() || args == "variables") {
    if (v.variables.empty()) out << "the program has no variables\n";
    for (const auto& [name, value] : v.variables) out << fmt::format("{} = {}\n", base::safeText(name), value);
  } else if (args == "motors") {
    for (std::size_t m = 0; m < v.motors.size(); ++m) out << fmt::format("{} = {}\n", image.motors[m].letter, v.motors[m]);
  } else if (args == "tcp") {
    if (!v.tcp) out << "no tool centre point: the program runs without a workcell (--cell)\n";
    else out << fmt::format("tcp = ({:.3f}, {:.3f}, {:.3f})\n", (*v.tcp)[0], (*v.tcp)[1], (*v.tcp)[2]);
  } else if (args == "io") {
    const auto bits = [](vm::IoMask mask) {
      std::string s;
      for (int i = 1; i <= vm::kIoCount; ++i) s += vm::lineIsOn(mask, i) ? " 1" : " 0";
      return s;
    };
    out << fmt::format("inputs  1-{0}:{1}\noutputs 1-{0}:{2}\n", vm::kIoCount, bits(v.inputs), bits(v.outputs));
    // What set each input that something changed (the trace's words).
    for (int i = 1; i <= vm::kIoCount; ++i) {
      const bool on = vm::lineIsOn(v.inputs, i);
      if (const std::string note = inputCauseNote(run, i, on); !note.empty())
        out << fmt::format("input {} {} {}\n", i, on ? "ON" : "OFF", note);
    }
  } else if (args == "objects") {
    if (v.objects.empty()) out << "no objects: the program runs without a workcell (--cell), or it has none\n";
    // By the run's numbers (robotsim test's `object N`): the cell's own
    // objects 1, 2, ...; a fed part the number it was given; a feeder's
    // empty slot and a part a sink took are not in the cell.
    std::vector<const runtime::ObjectView*> present;
    for (const runtime::ObjectView& o : v.objects)
      if (o.present) present.push_back(&o);
    std::stable_sort(present.begin(), present.end(), [](auto* a, auto* b) { return a->number < b->number; });
    for (const runtime::ObjectView* p : present)
      out << fmt::format("{} {} at ({:.3f}, {:.3f}, {:.3f}), centre ({:.3f}, {:.3f}, {:.3f}){}{}\n", p->number,
                         base::safeText(p->name), p->at.x(), p->at.y(), p->at.z(), p->centre.x(), p->centre.y(),
                         p->centre.z(), p->held ? ", held" : "", p->moved ? ", moved" : "");
  } else if (args == "devices") {
    const std::vector<DeviceRow> rows = deviceRows(run, v);
    if (rows.empty()) out << "no devices: the cell has no sensors, conveyors, feeders or sinks (or no workcell: --cell)\n";
    for (const DeviceRow& row : rows) out << fmt::format("{:<18} {}\n", row.name, row.value);
    // Inside an instruction under way (goto-time, a collision): the run stands after it;
    // a cell between two of its instants (goto-time) stands at the last one before.
    if (!rows.empty() && v.clock < devicesAt)
      out << fmt::format("(the devices and the parts as they are at {} s, when the instruction under way ends)\n",
                         base::formatSeconds(devicesAt));
    else if (!rows.empty() && v.clock > devicesAt)
      out << fmt::format("(the devices and the parts as they were at {} s, the cell's last instant before)\n",
                         base::formatSeconds(devicesAt));
  } else if (args == "clock") {
    return false;
  } else {
    auto e = parseExpression(image, ioWords(args));
    if (!e) out << "error: " << e.failure().message << '\n';
    else out << fmt::format("{} = {}{}\n", base::safeText(e->name), valueIn(v, *e), causeAside(run, *e, valueIn(v, *e)));
  }
  return true;
}

void printDisasm(std::ostream& out, const vm::Image& image, std::uint32_t current, std::string_view args) {
  std::uint32_t centre = current;
  if (!args.empty()) {
    const auto n = args.front() == '@' ? wholeCount(args.substr(1)) : std::nullopt;
    if (!n || *n == 0 || *n > image.code.size()) {
      out << fmt::format("error: '{}': disasm takes @N, N from 1 to {}\n", shownText(args), image.code.size());
      return;
    }
    centre = static_cast<std::uint32_t>(*n - 1);
  }
  const std::uint32_t first = centre > 4 ? centre - 4 : 0;
  const std::uint32_t last = std::min<std::uint32_t>(static_cast<std::uint32_t>(image.code.size()) - 1, first + 9);
  for (std::uint32_t i = first; i <= last; ++i) out << (i == current ? "=>" : "  ") << vm::listingRow(image, i) << '\n';
}

}  // namespace rs::debug
