#include "tools/testrun/expectation.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "base/ascii.h"
#include "compiler/stimuli/stimuli_text.h"
#include "tools/testrun/expectation_words.h"
#include "tools/testrun/golden_trace.h"
#include "vm/io_lines.h"
#include "vm/stop_reason.h"

namespace rs::testrun {

namespace {

using words::blank;
using words::columnOf;
using words::is;
using words::LineReader;
using words::Word;
using words::wordsOf;

// The stops an expectation names, in the order its error lists them: every
// reason that ends a run (a new one fails to compile until it is here),
// each said with the run's words of vm/stop_reason.h's table.
constexpr std::array kStatusReasons{vm::StopReason::End,          vm::StopReason::Deadlock,
                                    vm::StopReason::StepLimit,    vm::StopReason::TimeLimit,
                                    vm::StopReason::InstantLimit, vm::StopReason::KnotLimit,
                                    vm::StopReason::RuntimeError};
constexpr bool namesEveryEnd() {
  for (int r = 0; vm::isOver(static_cast<vm::StopReason>(r)); ++r)
    if (std::find(kStatusReasons.begin(), kStatusReasons.end(), static_cast<vm::StopReason>(r)) == kStatusReasons.end())
      return false;
  return true;
}
static_assert(namesEveryEnd(), "an expectation must be able to name every way a run ends");

// The other subjects, after the stops in the error's list.
constexpr std::string_view kOtherSubjects =
    "time, motors, motor, output, input, variable, tcp, object, trace, no collision, collides with, sensor, conveyor, "
    "feeder, sink";

std::vector<std::string_view> phraseOf(vm::StopReason reason) {
  std::vector<std::string_view> words;
  std::string_view name = vm::stopReasonName(reason);
  for (std::size_t space; (space = name.find(' ')) != std::string_view::npos; name.remove_prefix(space + 1))
    words.push_back(name.substr(0, space));
  words.push_back(name);
  return words;
}

const std::string& subjects() {
  static const std::string list = [] {
    std::string out;
    for (vm::StopReason reason : kStatusReasons) out += fmt::format("{}, ", vm::stopReasonName(reason));
    return out + std::string(kOtherSubjects);
  }();
  return list;
}

// A stop's first word that also begins another subject ('time'): only the
// whole phrase makes it the stop.
bool beginsOtherSubject(std::string_view word) {
  for (std::string_view rest = kOtherSubjects; !rest.empty();) {
    const std::size_t comma = rest.find(", ");
    const std::string_view subject = rest.substr(0, comma);
    if (base::sameName(subject.substr(0, subject.find(' ')), word)) return true;
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 2);
  }
  return false;
}

// `at line N` after a status: where the run must stop.
bool stopLine(LineReader& r, Expectation& e) {
  if (!r.accept("at")) return true;
  std::int64_t line = 0;
  if (!r.keyword("line") || !r.integer("a line number", line, 1, UINT32_MAX)) return false;
  e.line = static_cast<std::uint32_t>(line);
  return true;
}

// A stop by its words: the first word names it (and the rest must follow),
// unless that word begins another subject too.
bool status(LineReader& r, Expectation& e) {
  for (vm::StopReason reason : kStatusReasons) {
    const std::vector<std::string_view> phrase = phraseOf(reason);
    bool named = r.acceptPhrase(phrase);
    if (!named && !beginsOtherSubject(phrase.front()) && r.accept(phrase.front())) {
      named = true;
      for (std::size_t i = 1; i < phrase.size() && named; ++i) named = r.keyword(phrase[i]);
      if (!named) return false;
    }
    if (named) return e.kind = ExpectKind::Status, e.reason = reason, stopLine(r, e);
  }
  return false;
}

// at T | during A..B (optional)
bool moment(LineReader& r, Expectation& e) {
  if (r.accept("at")) {
    vm::Micros t = 0;
    if (!r.seconds("a time in seconds", t)) return false;
    e.at = t;
    return true;
  }
  if (!r.accept("during")) return true;
  const std::optional<Word> w = r.take("a window A..B in seconds");
  if (!w) return false;
  const std::size_t dots = w->text.find("..");
  const diag::Result<vm::Micros> a = stimuli::text::parseSeconds(w->text.substr(0, dots));
  const diag::Result<vm::Micros> b =
      stimuli::text::parseSeconds(dots == std::string_view::npos ? std::string_view() : w->text.substr(dots + 2));
  if (dots == std::string_view::npos || !a || !b || *b < *a)
    return r.failAt(w->col, fmt::format("expected a window A..B in seconds with A <= B (e.g. 2..5.5), got '{}'", w->text));
  e.during = {*a, *b};
  return true;
}

bool withinNumber(LineReader& r, double& tolerance) { return !r.accept("within") || r.real("a tolerance", tolerance); }

// sensor|conveyor|feeder|sink NAME count [<=|>=|=] N, the device's kind already read.
bool deviceCount(LineReader& r, Expectation& e, DeviceKind kind) {
  e.kind = ExpectKind::DeviceCount;
  e.device = kind;
  const std::optional<Word> name = r.take("a device name");
  if (!name) return false;
  e.name = name->text;
  e.nameCol = name->col;
  if (!r.keyword("count")) return false;
  if (r.accept("<=")) e.compare = Compare::AtMost;
  else if (r.accept(">=")) e.compare = Compare::AtLeast;
  else {
    r.accept("=");  // `count 10` is `count = 10`
    e.compare = Compare::Equal;
  }
  std::int64_t n = 0;
  if (!r.integer("a count", n, 0, UINT32_MAX)) return false;
  e.count = static_cast<std::uint32_t>(n);
  return r.end();
}

bool subject(LineReader& r, Expectation& e);

// What a robot's prefix may not stand before: the cell's own things.
std::string_view cellsOwn(ExpectKind kind) {
  switch (kind) {
    case ExpectKind::ObjectAt: return "an object's place is the cell's";
    case ExpectKind::DeviceCount: return "a device's count is the cell's";
    case ExpectKind::Trace: return "the trace is the whole run's";
    default: return {};
  }
}

// `LABEL.` before the subject names the robot of a cell the expectation is about.
bool expectation(LineReader& r, Expectation& e) {
  if (const std::optional<Word> label = r.robotPrefix()) {
    e.robot = label->text;
    e.robotCol = label->col;
  }
  if (r.accept("stopped")) {
    e.kind = ExpectKind::Status;
    e.stopped = true;
    if (e.robot.empty())
      return r.failAt(e.pos.col, "'stopped' is a robot's end in a cell of several robots (another robot stopped "
                                 "the cell): write LABEL.stopped");
    return stopLine(r, e) && r.end();
  }
  if (!subject(r, e)) return false;
  if (const std::string_view own = cellsOwn(e.kind); !e.robot.empty() && !own.empty())
    return r.failAt(e.robotCol, fmt::format("{}, not a robot's: write it without '{}.'", own, e.robot));
  return true;
}

bool subject(LineReader& r, Expectation& e) {
  const Word* first = r.peek();
  if (!first) return r.fail(fmt::format("expected what to expect: {}", subjects()));
  if (status(r, e)) return r.end();
  if (r.error()) return false;
  if (r.accept("time")) {
    e.kind = ExpectKind::Time;
    if (r.accept("<=")) e.compare = Compare::AtMost;
    else if (r.accept(">=")) e.compare = Compare::AtLeast;
    else if (r.accept("=")) e.compare = Compare::Equal;
    else return r.fail("expected <=, >= or = after 'time'");
    return r.seconds("a time in seconds", e.micros) && r.end();
  }
  if (r.accept("motors")) {
    e.kind = ExpectKind::Motors;
    while (const Word* w = r.peek()) {
      if (is(*w, "within")) break;
      const std::size_t eq = w->text.find('=');
      std::int32_t v = 0;
      // Only "X=..." has a value to read: no pointer past a '=' that is not there.
      const char* end = w->text.data() + w->text.size();
      const char* begin = eq == 1 ? w->text.data() + 2 : end;
      const auto parsed = eq == 1 ? std::from_chars(begin, end, v) : std::from_chars_result{begin, std::errc::invalid_argument};
      if (eq != 1 || parsed.ec != std::errc() || parsed.ptr != end)
        return r.fail(fmt::format("expected a motor and its encoder value, e.g. E=100, got '{}'", w->text));
      e.motors.emplace_back(base::asciiUpper(w->text[0]), v);
      e.motorCols.push_back(w->col);
      r.take("");
    }
    if (e.motors.empty()) return r.fail("expected at least one motor and its value, e.g. E=100");
    double within = 0;
    if (!withinNumber(r, within)) return false;
    if (within < 0 || within > 1e9 || within != std::floor(within))
      return r.fail("the tolerance of motors is a whole number of encoder units");
    e.within = static_cast<std::int32_t>(within);
    return r.end();
  }
  if (r.accept("trace")) {
    e.kind = ExpectKind::Trace;
    const std::optional<Word> file = r.take("a golden trace file");
    if (!file) return false;
    if (!staysUnderFolder(file->text))
      return r.failAt(file->col, fmt::format("a golden trace lives under the test's folder: name it relative to the "
                                             "folder, without '..' leading out, not '{}'",
                                             diag::excerpt(file->text)));
    e.name = file->text;
    return r.end();
  }
  if (r.accept("motor")) {
    e.kind = ExpectKind::MotorBound;
    const std::optional<Word> letter = r.take("a motor letter");
    if (!letter) return false;
    if (letter->text.size() != 1 || !std::isalpha(static_cast<unsigned char>(letter->text[0])))
      return r.failAt(letter->col, fmt::format("expected a motor letter such as E, got '{}'", letter->text));
    if (!r.keyword("never")) return false;
    if (r.accept("above")) e.on = true;
    else if (r.accept("below")) e.on = false;
    else return r.fail("expected 'above' or 'below' after 'never'");
    std::int64_t bound = 0;
    if (!r.integer("an encoder value", bound, INT32_MIN, INT32_MAX)) return false;
    e.motors.emplace_back(base::asciiUpper(letter->text[0]), static_cast<std::int32_t>(bound));
    e.motorCols.push_back(letter->col);
    return r.end();
  }
  if (r.accept("output") || r.accept("input")) {
    const bool output = is(*first, "output");
    e.kind = output ? ExpectKind::Output : ExpectKind::Input;
    std::int64_t n = 0;
    if (!r.integer(output ? "an output number" : "an input number", n, 1, vm::kIoCount)) return false;
    e.number = static_cast<int>(n);
    if (output && r.accept("pulses")) {
      e.kind = ExpectKind::Pulses;
      std::int64_t k = 0;
      if (!r.integer("a number of pulses", k, 0, UINT32_MAX)) return false;
      e.count = static_cast<std::uint32_t>(k);
      if (!r.accept("times") && !r.accept("time")) return r.fail("expected 'times' after the number of pulses");
      return r.end();
    }
    if (!r.onOff(e.on)) return false;
    if (r.accept("before")) {
      e.kind = ExpectKind::Order;
      e.first = {output, e.number, e.on};
      // `before right.output 1 on`: another robot's line, in a cell of several.
      if (const std::optional<Word> other = r.robotPrefix()) {
        e.secondRobot = other->text;
        e.secondRobotCol = other->col;
      }
      const bool secondOutput = r.accept("output");
      if (!secondOutput && !r.keyword("input")) return false;
      std::int64_t m = 0;
      if (!r.integer(secondOutput ? "an output number" : "an input number", m, 1, vm::kIoCount)) return false;
      e.second = {secondOutput, static_cast<int>(m), true};
      return r.onOff(e.second.on) && r.end();
    }
    return moment(r, e) && r.end();
  }
  if (r.accept("variable")) {
    e.kind = ExpectKind::Variable;
    const std::optional<Word> name = r.take("a variable name");
    if (!name) return false;
    e.name = name->text;
    std::int64_t v = 0;
    return r.keyword("=") && r.integer("a value", v, INT32_MIN, INT32_MAX) &&
           (e.value = static_cast<std::int32_t>(v), moment(r, e)) && r.end();
  }
  if (r.accept("tcp")) {
    e.kind = ExpectKind::Tcp;
    return r.real("x", e.point[0]) && r.real("y", e.point[1]) && r.real("z", e.point[2]) &&
           withinNumber(r, e.tolerance) && r.end();
  }
  if (r.accept("no")) {
    e.kind = ExpectKind::NoCollision;
    return r.keyword("collision") && r.end();
  }
  if (r.accept("collides")) {
    e.kind = ExpectKind::CollidesWith;
    if (!r.keyword("with")) return false;
    const std::optional<Word> name = r.take("what it collides with: a link, an object or floor");
    if (!name) return false;
    e.name = name->text;
    return stopLine(r, e) && r.end();
  }
  if (r.accept("sensor")) return deviceCount(r, e, DeviceKind::Sensor);
  if (r.accept("conveyor")) return deviceCount(r, e, DeviceKind::Conveyor);
  if (r.accept("feeder")) return deviceCount(r, e, DeviceKind::Feeder);
  if (r.accept("sink")) return deviceCount(r, e, DeviceKind::Sink);
  if (r.accept("object")) {
    const std::optional<Word> name = r.take("an object name");
    if (!name) return false;
    e.name = name->text;
    e.centre = r.accept("centre");
    if (e.centre && !r.keyword("at")) return false;
    if (e.centre || r.accept("at")) {
      e.kind = ExpectKind::ObjectAt;
      return r.real("x", e.point[0]) && r.real("y", e.point[1]) && r.real("z", e.point[2]) &&
             withinNumber(r, e.tolerance) && r.end();
    }
    e.kind = ExpectKind::ObjectHeld;
    e.on = !r.accept("not");
    return r.keyword("held") && r.end();
  }
  return r.fail(fmt::format("unknown expectation '{}': expect one of {}", first->text, subjects()));
}

bool setting(LineReader& r, TestSettings& s) {
  const Word* first = r.peek();
  if (!first) return r.fail("expected a setting: cell, robot, stimuli, input, max-time, max-steps or max-knots");
  const auto value = [&](std::string_view what, std::string& into) {
    const std::optional<Word> w = r.take(what);
    if (!w) return false;
    into = w->text;
    return r.end();
  };
  if (r.accept("cell")) return value("a workcell or robot (file or library name)", s.cell);
  if (r.accept("robot")) return value("the label of a robot of the cell", s.robot);
  if (r.accept("stimuli")) return value("a stimuli file", s.stimuliFile);
  if (r.accept("max-time")) return value("seconds", s.maxTime);
  if (r.accept("input")) {
    std::string arg;
    if (!value("an input change N=ON@SECONDS", arg)) return false;
    s.inputs.push_back(arg);
    return true;
  }
  if (r.accept("max-steps")) {
    std::int64_t n = 0;
    if (!r.integer("a number of instructions", n, 1, std::int64_t{1} << 62)) return false;
    s.maxSteps = static_cast<std::uint64_t>(n);
    return r.end();
  }
  if (r.accept("max-knots")) {
    std::int64_t n = 0;
    if (!r.integer("a number of straight-line knots", n, 1, std::int64_t{1} << 62)) return false;
    s.maxKnots = static_cast<std::uint64_t>(n);
    return r.end();
  }
  return r.fail(
      fmt::format("unknown setting '{}': cell, robot, stimuli, input, max-time, max-steps or max-knots", first->text));
}

}  // namespace

bool ParsedExpectations::expectsCompileErrors() const {
  for (const Expectation& e : expectations)
    if (e.kind == ExpectKind::CompileError) return true;
  return false;
}

bool ParsedExpectations::wantsTrace() const {
  for (const Expectation& e : expectations)
    if (e.kind == ExpectKind::Trace) return true;
  return false;
}

bool ParsedExpectations::expectsCollision() const {
  for (const Expectation& e : expectations)
    if (e.kind == ExpectKind::CollidesWith) return true;
  return false;
}

bool ParsedExpectations::statesStatus() const {
  for (const Expectation& e : expectations)
    if (e.kind == ExpectKind::Status) return true;
  return false;
}

bool readDirective(std::string_view line, std::uint32_t n, std::size_t i, const std::string& file,
                   ParsedExpectations& out) {
  const std::size_t colon = line.find(':', i);
  if (colon == std::string_view::npos) return false;
  const std::string_view head = line.substr(i, colon - i);
  const bool expect = base::sameName(head, "expect"), test = base::sameName(head, "test"),
             error = base::sameName(head, "expect-error");
  if (!expect && !test && !error) return false;
  const diag::Pos pos{n, columnOf(line, i)};
  const std::uint32_t endCol = columnOf(line, line.size());
  std::string_view text = line.substr(colon + 1);
  if (const std::size_t comment = text.find(';'); comment != std::string_view::npos && !error)
    text = text.substr(0, comment);  // a scenario file's trailing comment
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  if (error) {
    if (text.empty()) {
      out.errors.push_back({file, {n, endCol}, diag::Severity::Error,
                            "expected the text the compile error on this line must contain"});
      return true;
    }
    Expectation e;
    e.kind = ExpectKind::CompileError;
    e.pos = pos;
    e.text = text;
    e.message = text;
    out.expectations.push_back(std::move(e));
    return true;
  }
  const std::size_t end = static_cast<std::size_t>(text.data() + text.size() - line.data());
  LineReader r(wordsOf(line.substr(0, end), colon + 1), n, endCol);
  Expectation e;
  e.pos = pos;
  e.text = text;
  const bool ok = expect ? expectation(r, e) : setting(r, out.settings);
  if (!ok) {
    diag::Diagnostic d = *r.error();
    d.file = file;
    if (expect) d.hint = "docs/testing.md lists every expectation";
    out.errors.push_back(std::move(d));
  } else if (expect) {
    out.expectations.push_back(std::move(e));
  }
  return true;
}

ParsedExpectations parseExpectations(const diag::SourceFile& source) {
  ParsedExpectations out;
  for (std::uint32_t n = 1; n <= source.lineCount(); ++n) {
    const std::string_view line = source.line(n);
    const std::size_t semicolon = line.find(';');
    if (semicolon == std::string_view::npos) continue;
    std::size_t i = semicolon + 1;
    while (i < line.size() && blank(line[i])) ++i;
    readDirective(line, n, i, source.name(), out);  // or an ordinary comment
  }
  return out;
}

}  // namespace rs::testrun
