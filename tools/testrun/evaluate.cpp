#include "tools/testrun/evaluate.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string_view>

#include "base/ascii.h"
#include "base/seconds.h"
#include "base/text.h"
#include "runtime/cell/input_cause.h"
#include "vm/stop_reason.h"

namespace rs::testrun {

namespace {

std::string seconds(vm::Micros t) { return base::formatSeconds(t) + " s"; }
// A time a test wrote (`at T`, `during A..B`, `time <= T`), and the moments
// found against it: every digit written is shown ("0..0.0005 s", not
// "0.000..0.001 s").
std::string exactly(vm::Micros t) { return base::formatSecondsExactly(t) + " s"; }
std::string onOff(bool on) { return on ? "ON" : "OFF"; }
// "since 10 s: wire from sensor eye", its time with the digits it needs.
std::string inputSet(const runtime::InputChangeRecord& change) {
  return base::safeText(runtime::inputSinceText(base::formatSecondsExactly(change.at), change.cause));
}

class Checker {
 public:
  Checker(const runtime::Run& run, const RunEnd& end, const std::string& file)
      : run_(run), image_(*run.spec().image), outcome_(end.outcome), end_(end), file_(file) {}

  std::vector<diag::Diagnostic> failures;

  // Where the run ended, for messages: "at line 9, 4.175 s" (a cell's: "at 4.175 s").
  std::string ending() const {
    if (!end_.line) return "at " + seconds(end_.at);
    return fmt::format("at line {}, {}", *end_.line, seconds(end_.at));
  }

  // A robot's failures say whose they are.
  std::string said(std::string message) const {
    return end_.robot.empty() ? message : fmt::format("robot {}: {}", base::safeText(end_.robot), message);
  }
  void fail(const Expectation& e, std::string message) {
    failures.push_back({file_, e.pos, diag::Severity::Error, said(std::move(message))});
  }
  // At the column of the expectation's motor term `i` (E=100), where it was read from text.
  void failAtMotor(const Expectation& e, std::size_t i, std::string message) {
    diag::Pos pos = e.pos;
    if (i < e.motorCols.size()) pos.col = e.motorCols[i];
    failures.push_back({file_, pos, diag::Severity::Error, said(std::move(message))});
  }

  void status(const Expectation& e) {
    if (e.line && !end_.line)
      return fail(e, fmt::format("a cell of several robots ends at no one line: say whose, as in "
                                 "'LABEL.{} at line {}'",
                                 e.stopped ? "stopped" : vm::stopReasonName(e.reason), e.line));
    const bool reasonOk = e.stopped ? end_.stopped : !end_.stopped && outcome_.reason == e.reason;
    const bool lineOk = e.line == 0 || *end_.line == e.line;
    if (reasonOk && lineOk) return;
    std::string want(e.stopped ? "stopped" : vm::stopReasonName(e.reason));
    if (e.line) want += fmt::format(" at line {}", e.line);
    std::string got(end_.stopped ? "stopped" : vm::stopReasonName(outcome_.reason));
    got += " " + ending();
    if (!outcome_.message.empty()) got += ": " + outcome_.message;
    fail(e, fmt::format("expected the run to end: {}; it ended: {}", want, got));
  }

  void time(const Expectation& e) {
    const vm::Micros t = end_.at;
    const bool ok = e.compare == Compare::AtMost    ? t <= e.micros
                    : e.compare == Compare::AtLeast ? t >= e.micros
                                                    : t == e.micros;
    if (ok) return;
    const std::string_view op = e.compare == Compare::AtMost ? "<=" : e.compare == Compare::AtLeast ? ">=" : "=";
    fail(e, fmt::format("expected the run's simulated time {} {}; it ended {}{}", op, exactly(e.micros),
                        end_.line ? fmt::format("at line {}, ", *end_.line) : "at ", exactly(t)));
  }

  void motors(const Expectation& e) {
    const auto now = run_.rig().motors();
    for (std::size_t i = 0; i < e.motors.size(); ++i) {
      const auto [letter, value] = e.motors[i];
      std::size_t m = 0;
      while (m < image_.motors.size() && image_.motors[m].letter != letter) ++m;
      if (m == image_.motors.size()) {
        std::string letters;
        for (const vm::MotorSpec& s : image_.motors) letters += fmt::format("{}{}", letters.empty() ? "" : " ", s.letter);
        failAtMotor(e, i, fmt::format("the robot has no motor {} (its motors: {})", letter, letters));
        continue;
      }
      if (std::abs(std::int64_t{now[m]} - value) <= e.within) continue;
      failAtMotor(e, i, fmt::format("expected motor {} at {}{} at the end; it is at {} {}", letter, value,
                          e.within ? fmt::format(" within {}", e.within) : "", now[m], ending()));
    }
  }

  // What set an output or a variable ("set by line 10"), or which line was
  // running when an input was as it was and what set the input ("line 9
  // running; ON since 10.000 s: wire from sensor eye", the trace's words).
  static std::string cause(ExpectKind kind, const WatchedMoment& m) {
    if (kind == ExpectKind::Input) {
      std::string running = m.line ? fmt::format("line {} running", *m.line) : "before the first step";
      if (m.change) running += fmt::format("; {} {}", onOff(m.value != 0), inputSet(*m.change));
      return running;
    }
    if (kind == ExpectKind::Variable) return m.line ? fmt::format("set by line {}", *m.line) : "never set yet";
    return m.line ? fmt::format("set by line {}", *m.line) : "from the start";
  }

  void level(const Expectation& e, const WatchAnswer& a) {
    const bool output = e.kind == ExpectKind::Output;
    const std::string what = fmt::format("{} {}", output ? "output" : "input", e.number);
    if (e.at) {
      const WatchedMoment& m = *a.moment;
      if ((m.value != 0) != e.on)
        fail(e, fmt::format("expected {} {} at {}; it was {} then ({})", what, onOff(e.on), exactly(*e.at),
                            onOff(m.value != 0), cause(e.kind, m)));
      return;
    }
    if (e.during) {  // from A up to B: a change at B itself ends the window
      const auto [from, to] = *e.during;
      if (const std::optional<WatchedMoment>& m = a.moment)
        fail(e, fmt::format("expected {} {} during {}..{}; it was {} at {} ({})", what, onOff(e.on),
                            base::formatSecondsExactly(from), exactly(to), onOff(!e.on), exactly(m->at),
                            cause(e.kind, *m)));
      return;
    }
    const std::uint8_t bits = output ? run_.rig().machine().outputs() : run_.rig().machine().inputs();
    const bool v = ((bits >> (e.number - 1)) & 1) != 0;
    if (v == e.on) return;
    std::string set;  // what made an input so
    if (const runtime::InputChangeRecord* last = output ? nullptr : run_.rig().lastInputChange(e.number);
        last && last->cause.on == v)
      set = " (" + inputSet(*last) + ")";
    fail(e, fmt::format("expected {} {} at the end; it is {} {}{}", what, onOff(e.on), onOff(v), ending(), set));
  }

  static std::string eventText(const LineEvent& ev) {
    return fmt::format("{} {} {}", ev.output ? "output" : "input", ev.number, onOff(ev.on));
  }

  void order(const Expectation& e, const WatchAnswer& w) {
    const std::optional<vm::Micros> a = w.first, b = w.second;
    const std::string first = eventText(e.first), second = eventText(e.second);
    if (!a) return fail(e, fmt::format("expected {} before {}; {} never happened (the run ended {})", first, second,
                                       first, ending()));
    if (b && *b <= *a)
      fail(e, fmt::format("expected {} before {}; {} came first, at {} ({} at {})", first, second, second, seconds(*b),
                          first, seconds(*a)));
  }

  // Motors move in straight lines from one encoder value to another, so the
  // ends of its moves are the farthest a motor went.
  void motorBound(const Expectation& e, const WatchAnswer& w) {
    const auto [letter, bound] = e.motors.front();
    std::size_t m = 0;
    while (m < image_.motors.size() && image_.motors[m].letter != letter) ++m;
    if (m == image_.motors.size()) return failAtMotor(e, 0, fmt::format("the robot has no motor {}", letter));
    if (!w.beyond) return;
    const WatchedMove& move = *w.beyond;
    fail(e, fmt::format("expected motor {} never {} {}; it moved to {} at line {} ({}..{})", letter,
                        e.on ? "above" : "below", bound, move.to, move.line, base::formatSeconds(move.start),
                        seconds(move.end)));
  }

  void pulses(const Expectation& e, const WatchAnswer& w) {
    const std::uint32_t count = w.pulses;
    if (count != e.count)
      fail(e, fmt::format("expected output {} to turn ON {} time{}; it turned ON {} time{} (the run ended {})", e.number,
                          e.count, e.count == 1 ? "" : "s", count, count == 1 ? "" : "s", ending()));
  }

  void variable(const Expectation& e, const WatchAnswer& w) {
    for (std::size_t s = 0; s < image_.variables.size(); ++s) {
      if (!base::sameName(image_.variables[s], e.name)) continue;
      if (e.at) {
        const WatchedMoment& m = *w.moment;
        if (m.value != e.value)
          fail(e, fmt::format("expected variable {} = {} at {}; it was {} then ({})", image_.variables[s], e.value,
                              exactly(*e.at), m.value, cause(e.kind, m)));
        return;
      }
      if (e.during) {
        const auto [from, to] = *e.during;
        if (const std::optional<WatchedMoment>& m = w.moment)
          fail(e, fmt::format("expected variable {} = {} during {}..{}; it was {} at {} ({})", image_.variables[s],
                              e.value, base::formatSecondsExactly(from), exactly(to), m->value, exactly(m->at),
                              cause(e.kind, *m)));
        return;
      }
      const std::int32_t v = run_.interpreter().variables()[s];
      if (v != e.value)
        fail(e, fmt::format("expected variable {} = {} at the end; it is {} {}", image_.variables[s], e.value, v,
                            ending()));
      return;
    }
    fail(e, fmt::format("the program has no variable '{}'", e.name));
  }

  static double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }

  static std::string point(const std::array<double, 3>& p) {
    return fmt::format("({:.2f}, {:.2f}, {:.2f})", p[0], p[1], p[2]);
  }

  bool needsCell(const Expectation& e) {
    if (run_.rig().world()) return true;
    fail(e, "the run has no workcell: name one with '; test: cell NAME'");
    return false;
  }

  void tcp(const Expectation& e) {
    if (!needsCell(e)) return;
    const std::optional<std::array<double, 3>> at = run_.rig().tcp();
    if (!at) return fail(e, "the robot has no kinematic chain, so no tool centre point");
    if (distance(*at, e.point) > e.tolerance)
      fail(e, fmt::format("expected the tool centre point at {} within {}; it is at {} {}", point(e.point),
                          e.tolerance, point(*at), ending()));
  }

  // The objects an expectation names, among those in the cell at the end:
  // by number (the run's "object 5": the cell numbers its own from 1, a fed
  // part gets the next number when it is fed) or by name (every object of
  // that name, the description's or the one `AS` gives it on its OBJECT
  // line). A feeder's empty slot, or a part a sink took, is not there.
  std::vector<std::size_t> objectsNamed(const Expectation& e, const std::vector<runtime::ObjectView>& all) {
    std::vector<std::size_t> found;
    std::uint32_t number = 0;
    const bool byNumber = !e.name.empty() && e.name.find_first_not_of("0123456789") == std::string::npos &&
                          e.name.size() < 10 && (number = static_cast<std::uint32_t>(std::stoul(e.name))) >= 1;
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].present && (byNumber ? all[i].number == number
                                      : base::sameName(all[i].name, e.name) || base::sameName(all[i].as, e.name)))
        found.push_back(i);
    if (!found.empty()) return found;
    if (byNumber && run_.rig().devices())
      fail(e, fmt::format("the workcell has no object {} at the end: a part a sink took, or one never fed, is not in "
                          "the cell (the run ended {})",
                          number, ending()));
    else
      fail(e, fmt::format("the workcell has no object '{}'", e.name));
    return found;
  }

  // "object 5 (block)", "objects 2, 3 (block)": numbers and name, as the
  // run summary and the debugger show them.
  static std::string objectsLabel(const std::vector<std::size_t>& found, const std::vector<runtime::ObjectView>& all) {
    std::string numbers;
    for (std::size_t i : found) numbers += fmt::format("{}{}", numbers.empty() ? "" : ", ", all[i].number);
    return fmt::format("object{} {} ({})", found.size() == 1 ? "" : "s", numbers, base::safeText(all[found[0]].name));
  }

  void object(const Expectation& e) {
    if (!needsCell(e)) return;
    const std::vector<runtime::ObjectView> all = run_.rig().objects();
    const std::vector<std::size_t> found = objectsNamed(e, all);
    if (found.empty()) return;
    const std::string label = objectsLabel(found, all);
    if (e.kind == ExpectKind::ObjectHeld) {
      for (std::size_t i : found)
        if (all[i].held == e.on) return;
      fail(e, fmt::format("expected {} {}held at the end; {} {}held {}", label, e.on ? "" : "not ",
                          found.size() == 1 ? "it is" : "they are", e.on ? "not " : "", ending()));
      return;
    }
    std::string where;
    for (std::size_t i : found) {
      const Eigen::Vector3d& p = e.centre ? all[i].centre : all[i].at;
      const std::array<double, 3> at{p.x(), p.y(), p.z()};
      if (distance(at, e.point) <= e.tolerance) return;
      where += (where.empty() ? "" : ", ") + point(at);
    }
    const bool one = found.size() == 1;
    const std::string now = e.centre ? (one ? "its centre is" : "their centres are") : (one ? "it is" : "they are");
    fail(e, fmt::format("expected {} {}at {} within {} at the end; {} at {} (the run ended {})", label,
                        e.centre ? "centre " : "", point(e.point), e.tolerance, now, where, ending()));
  }

  // "collides with NAME [at line N]": a collision one of whose parts is a
  // link, gripper part or object of that name (or "floor"), by a move of
  // that line; "no collision": none at all.
  void collision(const Expectation& e) {
    if (!needsCell(e)) return;
    const runtime::CollisionWatch* watch = run_.rig().collisionWatch();
    if (!watch) return fail(e, "the run checked no collisions (--collisions=off)");
    const auto events = run_.rig().collisions();
    const auto lineOf = [&](const runtime::CollisionEvent& c) {
      return c.instruction < image_.lines.size() ? image_.lines[c.instruction] : 0u;
    };
    const auto described = [&](const runtime::CollisionEvent& c) {
      return fmt::format("at line {}, {}: {}", lineOf(c), seconds(c.at), watch->describe(c.contact));
    };
    if (e.kind == ExpectKind::NoCollision) {
      if (!events.empty()) fail(e, fmt::format("expected no collision; {} found, the first {}", events.size(), described(events[0])));
      return;
    }
    const auto named = [&](const workcell::BodyRef& b) {
      return b.kind == workcell::BodyKind::Floor ? base::sameName(e.name, "floor") : watch->model().nameOf(b) == e.name;
    };
    for (const runtime::CollisionEvent& c : events)
      if ((named(c.contact.a) || named(c.contact.b)) && (e.line == 0 || lineOf(c) == e.line)) return;
    fail(e, events.empty() ? fmt::format("expected a collision with {}{}; the run had none", e.name,
                                         e.line ? fmt::format(" at line {}", e.line) : "")
                           : fmt::format("expected a collision with {}{}; the run's first was {}", e.name,
                                         e.line ? fmt::format(" at line {}", e.line) : "", described(events[0])));
  }

  // "sensor eye count 10": a device's count at the end (a sensor's ON
  // edges, a conveyor's parts carried, a feeder's parts fed, a sink's parts
  // taken). A name the cell lacks is an error at the name, with the cell's
  // devices as its hint.
  void deviceCount(const Expectation& e) {
    if (!needsCell(e)) return;
    static constexpr std::array<std::string_view, 4> kKinds{"sensor", "conveyor", "feeder", "sink"};
    const std::string_view kind = kKinds[static_cast<std::size_t>(e.device)];
    const workcell::Devices& cell = run_.rig().cell()->devices;
    std::vector<std::string_view> names;
    if (e.device == DeviceKind::Sensor) for (const auto& d : cell.sensors) names.push_back(d.name);
    if (e.device == DeviceKind::Conveyor) for (const auto& d : cell.conveyors) names.push_back(d.name);
    if (e.device == DeviceKind::Feeder) for (const auto& d : cell.feeders) names.push_back(d.name);
    if (e.device == DeviceKind::Sink) for (const auto& d : cell.sinks) names.push_back(d.name);
    std::size_t d = 0;
    while (d < names.size() && !base::sameName(names[d], e.name)) ++d;
    const runtime::CellDevices* devices = run_.rig().devices();
    if (d == names.size() || !devices) {
      diag::Diagnostic bad{file_, e.pos, diag::Severity::Error,
                           fmt::format("the workcell has no {} '{}'", kind, base::safeText(e.name))};
      if (e.nameCol) bad.pos.col = e.nameCol;
      std::string list;
      const auto add = [&](std::string_view k, std::string_view n) {
        list += fmt::format("{}{} {}", list.empty() ? "" : ", ", k, base::safeText(n));
      };
      for (const auto& s : cell.sensors) add("sensor", s.name);
      for (const auto& c : cell.conveyors) add("conveyor", c.name);
      for (const auto& f : cell.feeders) add("feeder", f.name);
      for (const auto& s : cell.sinks) add("sink", s.name);
      bad.message = said(std::move(bad.message));
      bad.hint = list.empty() ? fmt::format("the workcell {} has no devices", base::safeText(run_.rig().cell()->name))
                              : "the workcell's devices: " + list;
      failures.push_back(std::move(bad));
      return;
    }
    static constexpr std::array<std::string_view, 4> kCounts{"ON edges", "parts carried", "parts fed", "parts taken"};
    const std::uint64_t got = e.device == DeviceKind::Sensor     ? devices->sensorCount(d)
                              : e.device == DeviceKind::Conveyor ? devices->carried(d)
                              : e.device == DeviceKind::Feeder   ? devices->fed(d)
                                                                 : devices->taken(d);
    const bool ok = e.compare == Compare::AtMost    ? got <= e.count
                    : e.compare == Compare::AtLeast ? got >= e.count
                                                    : got == e.count;
    if (ok) return;
    const std::string_view op = e.compare == Compare::AtMost ? "<= " : e.compare == Compare::AtLeast ? ">= " : "";
    fail(e, fmt::format("expected {} {} count {}{} ({}) at the end; it is {} (the run ended {})", kind,
                        base::safeText(names[d]), op, e.count, kCounts[static_cast<std::size_t>(e.device)], got,
                        ending()));
  }

 private:
  const runtime::Run& run_;
  const vm::Image& image_;
  vm::RunOutcome outcome_;
  const RunEnd& end_;
  const std::string& file_;
};

}  // namespace

RunEnd endOf(const runtime::Run& run) {
  RunEnd end;
  end.outcome = *run.outcome();
  end.at = run.rig().clock();
  end.line = run.spec().image->lines[end.outcome.index];
  return end;
}

std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const std::vector<Expectation>& expectations,
                                       const std::string& file, bool impliedFinished, const RunWatch* watch) {
  return evaluate(run, endOf(run), expectations, file, impliedFinished, watch);
}

std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const RunEnd& end,
                                       const std::vector<Expectation>& expectations, const std::string& file,
                                       bool impliedFinished, const RunWatch* watch) {
  Checker c(run, end, file);
  if (impliedFinished && !end.outcome.ok()) {
    Expectation finished;
    finished.kind = ExpectKind::Status;
    finished.reason = vm::StopReason::End;
    const vm::RunOutcome& o = end.outcome;
    finished.pos = {run.spec().image->lines[o.index], run.spec().image->columns[o.index]};
    c.status(finished);
  }
  const WatchAnswer none;
  for (std::size_t i = 0; i < expectations.size(); ++i) {
    const Expectation& e = expectations[i];
    const WatchAnswer& a = watch ? watch->answer(i) : none;
    switch (e.kind) {
      case ExpectKind::Status: c.status(e); break;
      case ExpectKind::Time: c.time(e); break;
      case ExpectKind::Motors: c.motors(e); break;
      case ExpectKind::Output:
      case ExpectKind::Input: c.level(e, a); break;
      case ExpectKind::Pulses: c.pulses(e, a); break;
      case ExpectKind::Order: c.order(e, a); break;
      case ExpectKind::MotorBound: c.motorBound(e, a); break;
      case ExpectKind::Variable: c.variable(e, a); break;
      case ExpectKind::Tcp: c.tcp(e); break;
      case ExpectKind::ObjectAt:
      case ExpectKind::ObjectHeld: c.object(e); break;
      case ExpectKind::NoCollision:
      case ExpectKind::CollidesWith: c.collision(e); break;
      case ExpectKind::DeviceCount: c.deviceCount(e); break;
      case ExpectKind::CompileError:
      case ExpectKind::Trace: break;  // not a property of the run alone (tools/testrun/test_file.cpp)
    }
  }
  return c.failures;
}

}  // namespace rs::testrun
