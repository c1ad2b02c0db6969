#include "testrun/evaluate.h"

#include <fmt/format.h>

#include <cmath>

#include "base/ascii.h"

namespace rs::testrun {

std::string_view statusWord(vm::StopReason reason) {
  switch (reason) {
    case vm::StopReason::End: return "finished";
    case vm::StopReason::RuntimeError: return "runtime error";
    case vm::StopReason::Deadlock: return "deadlock";
    case vm::StopReason::StepLimit: return "step limit";
    case vm::StopReason::TimeLimit: return "time limit";
    case vm::StopReason::InstantLimit: return "clock standing still";
    case vm::StopReason::Paused: return "paused";
  }
  return "finished";
}

namespace {

std::string seconds(vm::Micros t) { return vm::formatSeconds(t) + " s"; }
std::string onOff(bool on) { return on ? "ON" : "OFF"; }

class Checker {
 public:
  Checker(const runtime::Run& run, const std::string& file)
      : run_(run), image_(run.image()), log_(*run.log()), outcome_(*run.outcome()), file_(file) {}

  std::vector<diag::Diagnostic> failures;

  // Where the run ended, for messages: "at line 9 (4.175 s)".
  std::string ending() const {
    return fmt::format("at line {}, {}", image_.lines[outcome_.index], seconds(run_.clock()));
  }

  void fail(const Expectation& e, std::string message) {
    failures.push_back({file_, e.pos, diag::Severity::Error, std::move(message)});
  }

  void status(const Expectation& e) {
    const bool reasonOk = outcome_.reason == e.reason;
    const bool lineOk = e.line == 0 || image_.lines[outcome_.index] == e.line;
    if (reasonOk && lineOk) return;
    std::string want(statusWord(e.reason));
    if (e.line) want += fmt::format(" at line {}", e.line);
    std::string got(statusWord(outcome_.reason));
    got += " " + ending();
    if (!outcome_.message.empty()) got += ": " + outcome_.message;
    fail(e, fmt::format("expected the run to end: {}; it ended: {}", want, got));
  }

  void time(const Expectation& e) {
    const vm::Micros t = run_.clock();
    const bool ok = e.compare == Compare::AtMost    ? t <= e.micros
                    : e.compare == Compare::AtLeast ? t >= e.micros
                                                    : t == e.micros;
    if (ok) return;
    const std::string_view op = e.compare == Compare::AtMost ? "<=" : e.compare == Compare::AtLeast ? ">=" : "=";
    fail(e, fmt::format("expected the run's simulated time {} {}; it ended {}", op, seconds(e.micros), ending()));
  }

  void motors(const Expectation& e) {
    const auto now = run_.motors();
    for (const auto& [letter, value] : e.motors) {
      std::size_t m = 0;
      while (m < image_.motors.size() && image_.motors[m].letter != letter) ++m;
      if (m == image_.motors.size()) {
        std::string letters;
        for (const vm::MotorSpec& s : image_.motors) letters += fmt::format("{}{}", letters.empty() ? "" : " ", s.letter);
        fail(e, fmt::format("the robot has no motor {} (its motors: {})", letter, letters));
        continue;
      }
      if (std::abs(std::int64_t{now[m]} - value) <= e.within) continue;
      fail(e, fmt::format("expected motor {} at {}{} at the end; it is at {} {}", letter, value,
                          e.within ? fmt::format(" within {}", e.within) : "", now[m], ending()));
    }
  }

  // The output or input line's state at time t, from the log.
  bool lineAt(bool output, int number, vm::Micros t) const {
    const runtime::RunState s = runtime::stateAt(log_, t);
    return (((output ? s.outputs : s.inputs) >> (number - 1)) & 1) != 0;
  }

  // The times in (from, to) at which the line may have changed.
  std::vector<vm::Micros> changesIn(bool output, vm::Micros from, vm::Micros to) const {
    std::vector<vm::Micros> times;
    if (output) {
      for (const runtime::OutputChange& c : log_.outputs) {
        const vm::Micros at = log_.steps[c.step].end;
        if (at > from && at < to) times.push_back(at);
      }
    } else {
      for (const runtime::InputLevel& l : log_.inputs)
        if (l.at > from && l.at < to) times.push_back(l.at);
    }
    return times;
  }

  // Why an output or input is as it is at time t: the OUTSIG that set the
  // output last, or the instruction running while an input changed.
  std::string cause(bool output, vm::Micros t) const {
    if (output) {
      const runtime::OutputChange* last = nullptr;
      for (const runtime::OutputChange& c : log_.outputs)
        if (log_.steps[c.step].end <= t) last = &c;
      return last ? fmt::format("set by line {}", image_.lines[log_.steps[last->step].index]) : "from the start";
    }
    const runtime::RunState s = runtime::stateAt(log_, t);
    return s.step ? fmt::format("line {} running", image_.lines[log_.steps[*s.step].index]) : "before the first step";
  }

  void level(const Expectation& e) {
    const bool output = e.kind == ExpectKind::Output;
    const std::string what = fmt::format("{} {}", output ? "output" : "input", e.number);
    if (e.at) {
      const bool v = lineAt(output, e.number, *e.at);
      if (v != e.on)
        fail(e, fmt::format("expected {} {} at {}; it was {} then ({})", what, onOff(e.on), seconds(*e.at), onOff(v),
                            cause(output, *e.at)));
      return;
    }
    if (e.during) {  // from A up to B: a change at B itself ends the window
      const auto [from, to] = *e.during;
      std::vector<vm::Micros> times{from};
      for (vm::Micros t : changesIn(output, from, to)) times.push_back(t);
      for (vm::Micros t : times)
        if (lineAt(output, e.number, t) != e.on) {
          fail(e, fmt::format("expected {} {} during {}..{}; it was {} at {} ({})", what, onOff(e.on),
                              vm::formatSeconds(from), seconds(to), onOff(!e.on), seconds(t), cause(output, t)));
          return;
        }
      return;
    }
    const std::uint8_t bits = output ? run_.machine().outputs() : run_.machine().inputs();
    const bool v = ((bits >> (e.number - 1)) & 1) != 0;
    if (v != e.on) fail(e, fmt::format("expected {} {} at the end; it is {} {}", what, onOff(e.on), onOff(v), ending()));
  }

  // The first time the line turns to the state: ON, or OFF after having
  // been ON (nullopt: never).
  std::optional<vm::Micros> firstTime(const LineEvent& ev) const {
    bool was = false;
    const auto turns = [&](std::uint8_t bits) {
      const bool now = ((bits >> (ev.number - 1)) & 1) != 0;
      const bool happened = ev.on ? now : (was && !now);
      was = now;
      return happened;
    };
    if (ev.output) {
      for (const runtime::OutputChange& c : log_.outputs)
        if (turns(c.outputs)) return log_.steps[c.step].end;
    } else {
      for (const runtime::InputLevel& l : log_.inputs)
        if (turns(l.inputs)) return l.at;
    }
    return std::nullopt;
  }

  static std::string eventText(const LineEvent& ev) {
    return fmt::format("{} {} {}", ev.output ? "output" : "input", ev.number, onOff(ev.on));
  }

  void order(const Expectation& e) {
    const std::optional<vm::Micros> a = firstTime(e.first), b = firstTime(e.second);
    const std::string first = eventText(e.first), second = eventText(e.second);
    if (!a) return fail(e, fmt::format("expected {} before {}; {} never happened (the run ended {})", first, second,
                                       first, ending()));
    if (b && *b <= *a)
      fail(e, fmt::format("expected {} before {}; {} came first, at {} ({} at {})", first, second, second, seconds(*b),
                          first, seconds(*a)));
  }

  // Motors move in straight lines from one encoder value to another, so the
  // ends of its moves are the farthest a motor went.
  void motorBound(const Expectation& e) {
    const auto [letter, bound] = e.motors.front();
    std::size_t m = 0;
    while (m < image_.motors.size() && image_.motors[m].letter != letter) ++m;
    if (m == image_.motors.size()) return fail(e, fmt::format("the robot has no motor {}", letter));
    for (const runtime::MotorMove& move : log_.moves[m]) {
      const std::int32_t reached = e.on ? std::max(move.from, move.to) : std::min(move.from, move.to);
      if (e.on ? reached <= bound : reached >= bound) continue;
      const std::int32_t to = move.to;
      return fail(e, fmt::format("expected motor {} never {} {}; it moved to {} at line {} ({}..{})", letter,
                                 e.on ? "above" : "below", bound, to, image_.lines[log_.steps[move.step].index],
                                 vm::formatSeconds(move.start), seconds(move.end)));
    }
  }

  void pulses(const Expectation& e) {
    std::uint32_t count = 0;
    bool was = false;
    for (const runtime::OutputChange& c : log_.outputs) {
      const bool on = ((c.outputs >> (e.number - 1)) & 1) != 0;
      if (on && !was) ++count;
      was = on;
    }
    if (count != e.count)
      fail(e, fmt::format("expected output {} to turn ON {} time{}; it turned ON {} time{} (the run ended {})", e.number,
                          e.count, e.count == 1 ? "" : "s", count, count == 1 ? "" : "s", ending()));
  }

  void variable(const Expectation& e) {
    for (std::size_t s = 0; s < image_.variables.size(); ++s) {
      if (!base::sameName(image_.variables[s], e.name)) continue;
      const auto slot = static_cast<std::uint32_t>(s);
      const auto writtenBy = [&](vm::Micros t) {  // the line of the last write at or before t
        const runtime::VariableWrite* last = nullptr;
        for (const runtime::VariableWrite& w : log_.variables)
          if (w.slot == slot && log_.steps[w.step].end <= t) last = &w;
        return last ? fmt::format("set by line {}", image_.lines[log_.steps[last->step].index]) : "never set yet";
      };
      if (e.at) {
        const std::int32_t v = runtime::variableAt(log_, slot, *e.at);
        if (v != e.value)
          fail(e, fmt::format("expected variable {} = {} at {}; it was {} then ({})", image_.variables[s], e.value,
                              seconds(*e.at), v, writtenBy(*e.at)));
        return;
      }
      if (e.during) {
        const auto [from, to] = *e.during;
        std::vector<vm::Micros> times{from};
        for (const runtime::VariableWrite& w : log_.variables)
          if (const vm::Micros at = log_.steps[w.step].end; w.slot == slot && at > from && at < to) times.push_back(at);
        for (const vm::Micros t : times)
          if (const std::int32_t v = runtime::variableAt(log_, slot, t); v != e.value)
            return fail(e, fmt::format("expected variable {} = {} during {}..{}; it was {} at {} ({})",
                                       image_.variables[s], e.value, vm::formatSeconds(from), seconds(to), v,
                                       seconds(t), writtenBy(t)));
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
    if (run_.world()) return true;
    fail(e, "the run has no workcell: name one with '; test: cell NAME'");
    return false;
  }

  void tcp(const Expectation& e) {
    if (!needsCell(e)) return;
    const std::optional<std::array<double, 3>> at = run_.tcp();
    if (!at) return fail(e, "the robot has no kinematic chain, so no tool centre point");
    if (distance(*at, e.point) > e.tolerance)
      fail(e, fmt::format("expected the tool centre point at {} within {}; it is at {} {}", point(e.point),
                          e.tolerance, point(*at), ending()));
  }

  // Objects by name (any of them with that name), or by number (1-based).
  std::vector<runtime::ObjectView> objectsNamed(const Expectation& e, const std::vector<runtime::ObjectView>& all) {
    std::vector<runtime::ObjectView> found;
    std::size_t number = 0;
    const bool byNumber = !e.name.empty() && e.name.find_first_not_of("0123456789") == std::string::npos &&
                          e.name.size() < 6 && (number = std::stoul(e.name)) >= 1 && number <= all.size();
    for (std::size_t i = 0; i < all.size(); ++i)
      if (byNumber ? i + 1 == number : base::sameName(all[i].name, e.name)) found.push_back(all[i]);
    if (found.empty()) fail(e, fmt::format("the workcell has no object '{}'", e.name));
    return found;
  }

  void object(const Expectation& e) {
    if (!needsCell(e)) return;
    const std::vector<runtime::ObjectView> all = run_.objects();
    const std::vector<runtime::ObjectView> found = objectsNamed(e, all);
    if (found.empty()) return;
    if (e.kind == ExpectKind::ObjectHeld) {
      for (const runtime::ObjectView& o : found)
        if (o.held == e.on) return;
      fail(e, fmt::format("expected {} {}held at the end; it is {}held {}", e.name, e.on ? "" : "not ",
                          e.on ? "not " : "", ending()));
      return;
    }
    std::string where;
    for (const runtime::ObjectView& o : found) {
      const std::array<double, 3> at{o.at.x(), o.at.y(), o.at.z()};
      if (distance(at, e.point) <= e.tolerance) return;
      where += (where.empty() ? "" : ", ") + point(at);
    }
    fail(e, fmt::format("expected {} at {} within {} at the end; {} at {} (the run ended {})", e.name, point(e.point),
                        e.tolerance, found.size() == 1 ? "it is" : "they are", where, ending()));
  }

  // "collides with NAME [at line N]": a collision one of whose parts is a
  // link, gripper part or object of that name (or "floor"), by a move of
  // that line; "no collision": none at all.
  void collision(const Expectation& e) {
    if (!needsCell(e)) return;
    const runtime::CollisionWatch* watch = run_.collisionWatch();
    if (!watch) return fail(e, "the run checked no collisions (--collisions=off)");
    const auto events = run_.collisions();
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

 private:
  const runtime::Run& run_;
  const vm::Image& image_;
  const runtime::RunLog& log_;
  vm::RunOutcome outcome_;
  const std::string& file_;
};

}  // namespace

std::vector<diag::Diagnostic> evaluate(const runtime::Run& run, const std::vector<Expectation>& expectations,
                                       const std::string& file, bool impliedFinished) {
  Checker c(run, file);
  if (impliedFinished && !run.outcome()->ok()) {
    Expectation finished;
    finished.kind = ExpectKind::Status;
    finished.reason = vm::StopReason::End;
    const vm::RunOutcome o = *run.outcome();
    finished.pos = {run.image().lines[o.index], run.image().columns[o.index]};
    c.status(finished);
  }
  for (const Expectation& e : expectations) {
    switch (e.kind) {
      case ExpectKind::Status: c.status(e); break;
      case ExpectKind::Time: c.time(e); break;
      case ExpectKind::Motors: c.motors(e); break;
      case ExpectKind::Output:
      case ExpectKind::Input: c.level(e); break;
      case ExpectKind::Pulses: c.pulses(e); break;
      case ExpectKind::Order: c.order(e); break;
      case ExpectKind::MotorBound: c.motorBound(e); break;
      case ExpectKind::Variable: c.variable(e); break;
      case ExpectKind::Tcp: c.tcp(e); break;
      case ExpectKind::ObjectAt:
      case ExpectKind::ObjectHeld: c.object(e); break;
      case ExpectKind::NoCollision:
      case ExpectKind::CollidesWith: c.collision(e); break;
      case ExpectKind::CompileError:
      case ExpectKind::Trace: break;  // not a property of the run alone (testrun/test_file.cpp)
    }
  }
  return c.failures;
}

}  // namespace rs::testrun
