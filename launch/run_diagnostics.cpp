#include "launch/run_diagnostics.h"

#include <fmt/format.h>

#include "base/seconds.h"
#include "model/workcell/model.h"
#include "runtime/run/empty_close.h"
#include "runtime/run/placing.h"

namespace rs::launch {

namespace {

// How to get past a stop, where the command line can help.
std::string_view hintFor(const vm::Image& image, const vm::RunOutcome& outcome) {
  switch (outcome.reason) {
    case vm::StopReason::StepLimit: return "allow more with --max-steps N";
    case vm::StopReason::TimeLimit: return "allow more with --max-time SECONDS";
    case vm::StopReason::KnotLimit: return "allow more with --max-knots N";
    case vm::StopReason::Deadlock: return "inputs change only by --input N=ON@SECONDS or a --stimuli file";
    case vm::StopReason::InstantLimit:
      if (outcome.message.find("; wires changed") != std::string::npos)
        return "give one of those wires AFTER SECONDS, or the loop a DELAY or a way out";
      return "give the loop a DELAY, a move or a WAITFOR, or a way out";
    case vm::StopReason::RuntimeError:
      // The main program ran on into a subroutine: its END is missing.
      if (vm::has(image.code[outcome.index].op, vm::kReturns))  // its one failure: an empty call stack
        return "did the program run on into a subroutine? an END before the subroutine stops it there";
      return "";
    default: return "";  // it ended, or it paused
  }
}

// A stop's stable code (Diagnostic::code, static text): its name as the
// run reports it, in the spelling of the compiler's codes.
std::string_view codeFor(vm::StopReason reason) {
  switch (reason) {
    case vm::StopReason::RuntimeError: return "runtime-error";
    case vm::StopReason::Deadlock: return "deadlock";
    case vm::StopReason::StepLimit: return "step-limit";
    case vm::StopReason::TimeLimit: return "time-limit";
    case vm::StopReason::InstantLimit: return "clock-standing-still";
    default: return {};  // it ended, or it paused: no diagnostic of its own
  }
}

// "sensor eye", "OUT 2", "left.OUT 1", "ON": a wire's source as its line writes it.
std::string sourceWords(const workcell::Signal& s) {
  using K = workcell::Signal::Kind;
  switch (s.kind) {
    case K::On: return "ON";
    case K::Off: return "OFF";
    case K::Sensor: return fmt::format("sensor {}", s.name);
    case K::Output:
    case K::Input:
      return fmt::format("{}{} {}", s.robot.empty() ? "" : s.robot + ".", s.kind == K::Output ? "OUT" : "IN", s.number);
  }
  return {};
}

// What drives the input a WAITFOR stopped on, when the run's robot has a
// wire to it: "input 1 is wired from sensor eye (line 7 of workcell c)",
// and for a deadlock (nothing left on the cell's clock) why it stays.
std::string wiredInputHint(const runtime::Run& run, const vm::RunOutcome& outcome) {
  const vm::Image& image = *run.spec().image;
  const workcell::Workcell* cell = run.rig().cell();
  if (!cell || outcome.index >= image.code.size()) return {};
  const vm::Op op = image.code[outcome.index].op;  // a wait on an input (WAITFOR): a = input, b = state
  if (!vm::has(op, vm::kWaits) || vm::info(op).format != vm::Format::Input) return {};
  const int input = image.code[outcome.index].a;
  const bool on = image.code[outcome.index].b != 0;
  for (const workcell::Wire& w : cell->devices.wires) {
    if (w.input != input || (!w.robot.empty() && cell->robotLabeled(w.robot) != run.rig().robotIndex())) continue;
    std::string text = fmt::format("input {} is wired from {}{} (line {} of workcell {})", input, sourceWords(w.source),
                                   w.inverted ? " INVERTED" : "", w.pos.line, cell->name);
    if (outcome.reason != vm::StopReason::Deadlock) return text;
    const std::string after = base::formatSeconds(run.rig().clock());
    using K = workcell::Signal::Kind;
    if (w.source.kind == K::On || w.source.kind == K::Off)
      return fmt::format("{}: always {}", text, (w.source.kind == K::On) != w.inverted ? "ON" : "OFF");
    if (w.source.kind != K::Sensor || w.source.sensor >= cell->devices.sensors.size()) return text;
    const bool parts = cell->devices.sensors[w.source.sensor].sees == workcell::Sensor::Sees::Parts;
    // The sensor has to turn ON (the wait's level, through INVERTED) or OFF.
    if (on != w.inverted) return fmt::format("{}; {} crosses it after {} s", text, parts ? "no part" : "nothing", after);
    return fmt::format("{}; what it sees stays there after {} s", text, after);
  }
  return {};
}

}  // namespace

diag::Diagnostic stopDiagnostic(const vm::Image& image, const vm::RunOutcome& outcome, const std::string& file) {
  const diag::Pos pos{image.lines[outcome.index], image.columns[outcome.index]};
  return {file, pos, diag::Severity::Error,
          fmt::format("{}: {} (instruction {})", vm::stopReasonName(outcome.reason), outcome.message, outcome.index + 1),
          codeFor(outcome.reason), std::string(hintFor(image, outcome))};
}

std::vector<diag::Diagnostic> runWarnings(const runtime::Run& run, runtime::CollisionMode mode,
                                          const std::string& file) {
  std::vector<diag::Diagnostic> out;
  const vm::Image& image = *run.spec().image;
  if (const runtime::CollisionWatch* watch = run.rig().collisionWatch(); watch && mode == runtime::CollisionMode::Warn)
    for (const runtime::CollisionEvent& e : run.rig().collisions()) {
      const bool known = e.instruction < image.code.size();
      const std::string seconds = base::formatSeconds(e.at);
      out.push_back({file, known ? diag::Pos{image.lines[e.instruction], image.columns[e.instruction]} : diag::Pos{},
                     diag::Severity::Warning,
                     fmt::format("collision at {} s: {} (--collisions=warn: the run went on)", seconds,
                                 watch->describe(e)),
                     "collision",
                     fmt::format("{}'robotsim render CELL --program PROG --at {} --collision-shapes' draws it; "
                                 "--collisions=error stops the run there",
                                 watch->hint(e).empty() ? std::string() : watch->hint(e) + "; ", seconds)});
    }
  for (diag::Diagnostic& w : runtime::placingWarnings(run, file)) out.push_back(std::move(w));
  if (std::optional<diag::Diagnostic> w = runtime::gripperWarning(run, file)) out.push_back(std::move(*w));
  return out;
}

std::vector<diag::Diagnostic> runDiagnostics(const runtime::Run& run, runtime::CollisionMode mode,
                                             const std::string& file) {
  std::vector<diag::Diagnostic> out;
  if (const std::optional<vm::RunOutcome> outcome = run.outcome(); outcome && !outcome->ok()) {
    diag::Diagnostic stop = stopDiagnostic(*run.spec().image, *outcome, file);
    // A collision stopped it: where its move ends in what it hit by a little, the distance to go.
    const runtime::CollisionWatch* watch = run.rig().collisionWatch();
    const auto events = run.rig().collisions();
    if (watch && mode == runtime::CollisionMode::Error && !events.empty() &&
        events.back().instruction == outcome->index && stop.hint.empty())
      stop.hint = watch->hint(events.back());
    // A WAITFOR on a wired input: what drives it, instead of (or after) --input and --max-time.
    if (const std::string wired = wiredInputHint(run, *outcome); !wired.empty()) {
      if (outcome->reason == vm::StopReason::Deadlock) stop.hint = wired;
      else if (outcome->reason == vm::StopReason::TimeLimit) stop.hint += "; " + wired;
    }
    out.push_back(std::move(stop));
  }
  for (diag::Diagnostic& w : runWarnings(run, mode, file)) out.push_back(std::move(w));
  return out;
}

}  // namespace rs::launch
