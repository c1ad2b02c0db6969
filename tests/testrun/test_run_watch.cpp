// testrun::RunWatch, which answers a test's expectations while the run goes
// and keeps no log, against the definition it replaces: the same questions
// answered from the run's whole RunLog (runtime::stateAt, variableAt and the
// log's lists), as `robotsim test` did before. Random programs (delays of
// zero and more, outputs, variables, moves, waits, loops) with random
// stimuli (timed changes, changes and undos at one time, reactive rules with
// and without a delay) and random expectations at random moments, many of
// them on the times where things change; both must give the same answer
// every time, an input's cause included (the change that made it so).
#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <string>
#include <vector>

#include "launch/program.h"
#include "launch/run_request.h"
#include "runtime/run/run.h"
#include "tests/cli/cli_support.h"
#include "tools/testrun/run_watch.h"

namespace {

using rs::runtime::RunLog;
using rs::testrun::Expectation;
using rs::testrun::ExpectKind;
using rs::testrun::WatchAnswer;
using rs::testrun::WatchedMoment;
using rs::vm::Micros;

// ---- The reference: the questions answered from a whole RunLog. ----

bool logLineAt(const RunLog& log, bool output, int number, Micros t) {
  const rs::runtime::RunState s = rs::runtime::stateAt(log, t);
  return (((output ? s.outputs : s.inputs) >> (number - 1)) & 1) != 0;
}

// The line that set an output (or variable, in the slot) last by t, or was
// running at t for an input.
std::optional<std::uint32_t> logCause(const RunLog& log, const rs::vm::Image& image, ExpectKind kind, Micros t,
                                      std::uint32_t slot) {
  std::optional<std::uint32_t> line;
  if (kind == ExpectKind::Output) {
    for (const rs::runtime::OutputChange& c : log.outputs)
      if (log.steps[c.step].end <= t) line = image.lines[log.steps[c.step].index];
  } else if (kind == ExpectKind::Variable) {
    for (const rs::runtime::VariableWrite& w : log.variables)
      if (w.slot == slot && log.steps[w.step].end <= t) line = image.lines[log.steps[w.step].index];
  } else if (const rs::runtime::RunState s = rs::runtime::stateAt(log, t); s.step) {
    line = image.lines[log.steps[*s.step].index];
  }
  return line;
}

std::int32_t logValue(const RunLog& log, const Expectation& e, std::uint32_t slot, Micros t) {
  if (e.kind == ExpectKind::Variable) return rs::runtime::variableAt(log, slot, t);
  return logLineAt(log, e.kind == ExpectKind::Output, e.number, t) ? 1 : 0;
}

// The moments a window is checked at: its start, and every change inside.
std::vector<Micros> logWindowTimes(const RunLog& log, const Expectation& e, std::uint32_t slot) {
  const Micros from = e.during->first, to = e.during->second;  // clang 14 cannot capture bindings
  std::vector<Micros> times{from};
  const auto inside = [&](Micros at) {
    if (at > from && at < to) times.push_back(at);
  };
  if (e.kind == ExpectKind::Output)
    for (const rs::runtime::OutputChange& c : log.outputs) inside(log.steps[c.step].end);
  if (e.kind == ExpectKind::Input)
    for (const rs::runtime::InputLevel& l : log.inputs) inside(l.at);
  if (e.kind == ExpectKind::Variable)
    for (const rs::runtime::VariableWrite& w : log.variables)
      if (w.slot == slot) inside(log.steps[w.step].end);
  return times;
}

std::optional<Micros> logFirstTime(const RunLog& log, const rs::testrun::LineEvent& ev) {
  bool was = false;
  const auto turns = [&](std::uint8_t bits) {
    const bool now = ((bits >> (ev.number - 1)) & 1) != 0;
    const bool happened = ev.on ? now : (was && !now);
    was = now;
    return happened;
  };
  if (ev.output) {
    for (const rs::runtime::OutputChange& c : log.outputs)
      if (turns(c.outputs)) return log.steps[c.step].end;
  } else {
    for (const rs::runtime::InputLevel& l : log.inputs)
      if (turns(l.inputs)) return l.at;
  }
  return std::nullopt;
}

// What made input `input` read `on` at t: its last change due at or before
// t, from the log's list of changes and their causes; before those, the
// stimuli due at 0 s, which change it as the run is made (in file order,
// each one that alters it), before the log listens.
std::optional<rs::runtime::InputChangeRecord> logChange(const RunLog& log, const rs::stimuli::Stimuli& stimuli,
                                                        int input, Micros t, bool on) {
  std::optional<rs::runtime::InputChangeRecord> last;
  bool now = false;
  for (const rs::stimuli::InputChange& c : stimuli.changes)
    if (c.at == 0 && c.input == input && c.on != now) {
      now = c.on;
      last = rs::runtime::InputChangeRecord{0, {rs::runtime::InputCause::Kind::Stimulus, input, c.on, c.line, {}}};
    }
  for (const rs::runtime::InputRecord& r : log.inputChanges)
    if (r.cause.input == input && r.at <= t) last = rs::runtime::InputChangeRecord{r.at, r.cause};
  if (last && last->cause.on != on) last.reset();
  return last;
}

WatchAnswer fromLog(const RunLog& log, const rs::runtime::RunSpec& spec, const Expectation& e) {
  const rs::vm::Image& image = *spec.image;
  WatchAnswer a;
  std::uint32_t slot = 0;
  while (slot < image.variables.size() && image.variables[slot] != e.name) ++slot;
  const auto momentAt = [&](Micros t) {
    WatchedMoment m{t, logValue(log, e, slot, t), logCause(log, image, e.kind, t, slot), std::nullopt};
    if (e.kind == ExpectKind::Input) m.change = logChange(log, spec.stimuli, e.number, t, m.value != 0);
    return m;
  };
  switch (e.kind) {
    case ExpectKind::Output:
    case ExpectKind::Input:
    case ExpectKind::Variable:
      if (e.at) a.moment = momentAt(*e.at);
      if (e.during)
        for (const Micros t : logWindowTimes(log, e, slot)) {
          const WatchedMoment m = momentAt(t);
          if (e.kind == ExpectKind::Variable ? m.value != e.value : (m.value != 0) != e.on) {
            a.moment = m;
            break;
          }
        }
      break;
    case ExpectKind::Order:
      a.first = logFirstTime(log, e.first);
      a.second = logFirstTime(log, e.second);
      break;
    case ExpectKind::Pulses: {
      bool was = false;
      for (const rs::runtime::OutputChange& c : log.outputs) {
        const bool on = ((c.outputs >> (e.number - 1)) & 1) != 0;
        a.pulses += on && !was;
        was = on;
      }
      break;
    }
    case ExpectKind::MotorBound: {
      std::size_t m = 0;
      while (image.motors[m].letter != e.motors.front().first) ++m;
      for (const rs::runtime::MotorMove& move : log.moves[m]) {
        const std::int32_t reached = e.on ? std::max(move.from, move.to) : std::min(move.from, move.to);
        const std::int32_t bound = e.motors.front().second;
        if (e.on ? reached <= bound : reached >= bound) continue;
        a.beyond = rs::testrun::WatchedMove{move.to, image.lines[log.steps[move.step].index], move.start, move.end};
        break;
      }
      break;
    }
    default: break;
  }
  return a;
}

// ---- Random programs, stimuli and expectations. ----

struct WatchCase {
  std::string program, stimuli;
  std::vector<Micros> moments;  // times worth asking about
};

WatchCase randomCase(std::mt19937& rng) {
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const char* const delays[] = {"0", "0.001", "0.25", "0.5", "1"};
  WatchCase c;
  c.program = "        SET K 0\nTOP:    ADD K 1\n";
  const int length = 4 + pick(14);
  for (int i = 0; i < length; ++i) {
    switch (pick(9)) {
      case 0:
      case 1: c.program += fmt::format("        DELAY {}\n", delays[pick(5)]); break;
      case 2:
      case 3: c.program += fmt::format("        OUTSIG {} {}\n", 1 + pick(3), pick(2) ? "ON" : "OFF"); break;
      case 4:
        c.program += fmt::format("        {} {} {}\n", pick(2) ? "SET" : "ADD", pick(2) ? "N" : "M", pick(5) - 2);
        break;
      case 5:
        c.program += fmt::format("        MOVE {} 0 {} 0 0\n", (pick(2) ? 1 : -1) * 100 * pick(3), 60 * pick(2));
        break;
      case 6: c.program += fmt::format("        WAITFOR {} {}\n", 1 + pick(2), pick(2) ? "ON" : "OFF"); break;
      case 7:
        c.program +=
            fmt::format("        JMPIN {} ON SKIP{}\n        OUTSIG 3 ON\nSKIP{}:  DELAY 0\n", 1 + pick(2), i, i);
        break;
      case 8: c.program += "        MOVE -200 0 0 0 0\n        MOVE 200 0 0 0 0\n"; break;
    }
  }
  c.program += fmt::format("        JMPVAR K < {} TOP\n        END\n", 1 + pick(3));
  for (int i = 0, n = pick(7); i < n; ++i) {
    const std::string t = fmt::format("{}", 0.25 * pick(12));
    c.stimuli += fmt::format("at {} input {} {}\n", t, 1 + pick(2), pick(2) ? "on" : "off");
    if (pick(3) == 0) c.stimuli += fmt::format("at {} input {} {}\n", t, 1 + pick(2), pick(2) ? "on" : "off");
  }
  for (int i = 0, n = pick(3); i < n; ++i)
    c.stimuli += fmt::format("when output {} {} then input {} {}{}\n", 1 + pick(3), pick(2) ? "on" : "off", 1 + pick(2),
                             pick(2) ? "on" : "off", pick(2) ? "" : fmt::format(" after {}", delays[pick(5)]));
  for (int k = 0; k <= 24; ++k) c.moments.push_back(Micros{k} * 250'000);
  c.moments.push_back(1);
  c.moments.push_back(1'000);
  c.moments.push_back(750'001);
  return c;
}

std::vector<Expectation> randomExpectations(std::mt19937& rng, const std::vector<Micros>& moments) {
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const auto moment = [&] { return moments[static_cast<std::size_t>(pick(static_cast<int>(moments.size())))]; };
  std::vector<Expectation> out;
  for (int i = 0; i < 40; ++i) {
    Expectation e;
    const int what = pick(8);
    e.kind = what < 2   ? ExpectKind::Output
             : what < 4 ? ExpectKind::Input
             : what < 6 ? ExpectKind::Variable
             : what < 7 ? ExpectKind::Order
                        : ExpectKind::Pulses;
    e.number = 1 + pick(3);
    e.on = pick(2) != 0;
    e.name = pick(2) ? "N" : "M";
    e.value = pick(5) - 2;
    if (e.kind == ExpectKind::Order) {
      e.first = {pick(2) != 0, 1 + pick(3), pick(2) != 0};
      e.second = {pick(2) != 0, 1 + pick(3), pick(2) != 0};
      if (!e.first.output) e.first.number = 1 + pick(2);
      if (!e.second.output) e.second.number = 1 + pick(2);
    } else if (e.kind != ExpectKind::Pulses) {
      if (e.kind == ExpectKind::Input) e.number = 1 + pick(2);
      if (pick(2)) {
        e.at = moment();
      } else {
        const Micros a = moment(), b = moment();
        e.during = {std::min(a, b), std::max(a, b)};
      }
    }
    out.push_back(e);
  }
  for (const bool above : {true, false}) {
    Expectation e;
    e.kind = ExpectKind::MotorBound;
    e.on = above;
    e.motors = {{pick(2) ? 'E' : 'C', (above ? 1 : -1) * 60 * pick(5)}};
    out.push_back(e);
  }
  return out;
}

std::string answerText(const WatchAnswer& a) {
  std::string s;
  if (a.moment)
    s += fmt::format("moment {} value {} line {}; ", a.moment->at, a.moment->value, a.moment->line.value_or(0));
  if (a.moment && a.moment->change)
    s += fmt::format("changed at {}: {}; ", a.moment->change->at, rs::runtime::inputChangeText(a.moment->change->cause));
  if (a.first) s += fmt::format("first {}; ", *a.first);
  if (a.second) s += fmt::format("second {}; ", *a.second);
  if (a.beyond)
    s += fmt::format("beyond {} line {} {}..{}; ", a.beyond->to, a.beyond->line, a.beyond->start, a.beyond->end);
  return s + fmt::format("pulses {}", a.pulses);
}

}  // namespace

TEST_CASE("RunWatch answers every expectation as the whole RunLog does, on random runs", "[testrun]") {
  const rs::testing::TempDir dir;
  std::mt19937 rng(20261126);
  int finished = 0, stopped = 0;
  for (int round = 0; round < 150; ++round) {
    const WatchCase c = randomCase(rng);
    const std::string program = dir.write("p.rsp", c.program);
    const std::string stimuli = dir.write("p.stim", c.stimuli);
    const rs::launch::LoadedProgram loaded = rs::launch::loadProgram({program, "", {}});
    INFO(c.program << "--- stimuli:\n" << c.stimuli);
    REQUIRE(loaded.ok());
    rs::launch::RunRequest request;
    request.stimuliFile = stimuli;
    request.maxTime = "6";
    std::vector<rs::diag::Diagnostic> problems;
    std::optional<rs::runtime::RunSpec> spec = rs::launch::prepareRun(loaded, request, problems);
    REQUIRE(spec);
    spec->log = true;
    rs::runtime::Run run(std::move(*spec));
    const std::vector<Expectation> expectations = randomExpectations(rng, c.moments);
    rs::testrun::RunWatch watch(run, expectations);
    run.observe(watch);
    const rs::vm::RunOutcome outcome = run.runToEnd();
    watch.finish(outcome);
    (outcome.ok() ? finished : stopped) += 1;
    for (std::size_t i = 0; i < expectations.size(); ++i) {
      const std::vector<std::string>& names = run.spec().image->variables;
      if (expectations[i].kind == ExpectKind::Variable &&
          std::find(names.begin(), names.end(), expectations[i].name) == names.end())
        continue;  // evaluate says the program has no such variable
      const WatchAnswer want = fromLog(*run.log(), run.spec(), expectations[i]);
      const WatchAnswer& got = watch.answer(i);
      INFO("round " << round << ", expectation " << i << " (kind " << static_cast<int>(expectations[i].kind) << ")");
      CHECK(answerText(got) == answerText(want));
    }
  }
  // The rounds reach both ends: runs that finish, and runs stopped early
  // (deadlocks, runtime errors, the time limit), whose last step counts.
  CHECK(finished > 20);
  CHECK(stopped > 20);
}
