#include "launch/run_request.h"

#include "compiler/stimuli/stimuli_text.h"

#include <fmt/format.h>

#include "base/text.h"
#include "launch/stimuli_robots.h"

namespace rs::launch {

std::string_view RunRequest::firstGiven() const {
  if (!inputs.empty()) return "--input";
  if (!stimuliFile.empty()) return "--stimuli";
  if (maxSteps) return "--max-steps";
  if (maxKnots) return "--max-knots";
  if (!maxTime.empty()) return "--max-time";
  if (!collisions.empty()) return "--collisions";
  return "";
}

bool loadStimuli(const RunRequest& request, stimuli::Stimuli& stimuli, std::vector<diag::Diagnostic>& diags) {
  bool ok = true;
  const auto add = [&](const diag::Diagnostic& e) {
    diags.push_back(e);
    ok = false;
  };
  if (!request.stimuliFile.empty()) {
    diag::Result<stimuli::Stimuli> parsed = stimuli::loadStimuliFile(request.stimuliFile);
    for (const auto& e : parsed.failures()) add(e);
    if (parsed) stimuli = std::move(parsed).value();
  }
  for (const std::string& arg : request.inputs) {
    const diag::Result<stimuli::InputChange> parsed = stimuli::parseStimulusArg(arg, "--input");
    if (parsed) stimuli.changes.push_back(*parsed);
    else add(parsed.failure());
  }
  return ok;
}

std::optional<vm::Micros> maxTimeOf(const RunRequest& request, std::vector<diag::Diagnostic>& diags) {
  if (request.maxTime.empty()) return vm::RunLimits{}.maxTime;
  const diag::Result<vm::Micros> parsed = stimuli::text::parseSeconds(request.maxTime);
  if (parsed) return *parsed;
  diags.push_back({"--max-time", {}, diag::Severity::Error, parsed.failure().message, {},
                   "a time is seconds with at most 6 decimals, from 0 to 1000000"});
  return std::nullopt;
}

std::optional<runtime::CollisionMode> collisionsOf(const RunRequest& request, std::vector<diag::Diagnostic>& diags) {
  if (request.collisions.empty()) return runtime::CollisionMode::Error;
  if (const auto mode = runtime::collisionModeByName(request.collisions)) return mode;
  diags.push_back({"--collisions", {}, diag::Severity::Error,
                   fmt::format("'{}' is not a collision mode", base::safeText(request.collisions)), {},
                   "write --collisions=error (a collision stops the run), warn (it is reported) or off"});
  return std::nullopt;
}

// One input has one source: a stimulus (a timed change or a rule's) for an
// input the cell wires is an error at the stimulus's line, the second source.
bool checkWiredInputs(const RunRequest& request, const workcell::Workcell* cell, const stimuli::Stimuli& stimuli,
                      std::vector<diag::Diagnostic>& diags) {
  if (!cell) return true;
  bool ok = true;
  std::vector<bool> reported(vm::kIoCount + 1, false);
  const auto check = [&](int input, std::uint32_t line, const char* what) {
    if (input < 1 || input > vm::kIoCount || reported[static_cast<std::size_t>(input)]) return;
    for (const workcell::Wire& w : cell->devices.wires) {
      const bool driven = w.robot.empty() || cell->robotLabeled(w.robot) == cell->drivenRobotIndex();
      if (w.input != input || !driven) continue;
      reported[static_cast<std::size_t>(input)] = true, ok = false;
      const std::string file = line ? request.stimuliFile : std::string("--input");
      diags.push_back({file, line ? diag::Pos{line, 1} : diag::Pos{}, diag::Severity::Error,
                       fmt::format("input {} has a second source: this {}, and the WIRE at line {} of workcell {}",
                                   input, what, w.pos.line, base::safeText(cell->name)),
                       {},
                       fmt::format("one input has one source: drop this {} or wire another input than {}", what,
                                   input)});
      return;
    }
  };
  for (const stimuli::InputChange& c : stimuli.changes) check(c.input, c.line, "stimulus");
  for (const stimuli::ReactiveRule& r : stimuli.rules) check(r.input, r.line, "rule");
  return ok;
}

namespace {

// What every run reads from the request, each problem a diagnostic.
struct RequestParts {
  std::optional<vm::Micros> maxTime;
  bool stimuliOk = false;
  std::optional<runtime::CollisionMode> collisions;
  bool ok() const { return maxTime && stimuliOk && collisions; }
};

RequestParts readRequest(const RunRequest& request, stimuli::Stimuli& stimuli, std::vector<diag::Diagnostic>& diags) {
  RequestParts parts;
  parts.maxTime = maxTimeOf(request, diags);
  parts.stimuliOk = loadStimuli(request, stimuli, diags);
  parts.collisions = collisionsOf(request, diags);
  return parts;
}

vm::RunLimits limitsOf(const RunRequest& request, vm::Micros maxTime, std::uint64_t defaultMaxSteps) {
  vm::RunLimits limits;
  limits.maxSteps = request.maxSteps.value_or(defaultMaxSteps);
  limits.maxKnots = request.maxKnots.value_or(vm::RunLimits{}.maxKnots);
  limits.maxTime = maxTime;
  return limits;
}

}  // namespace

std::optional<runtime::RunSpec> prepareRun(const LoadedProgram& program, const RunRequest& request,
                                           std::vector<diag::Diagnostic>& diags, std::uint64_t defaultMaxSteps) {
  runtime::RunSpec spec;
  spec.image = program.image;
  spec.cell = program.cell;
  const RequestParts parts = readRequest(request, spec.stimuli, diags);
  const bool robotsOk =
      parts.stimuliOk && placeStimuliOnRobots(program.cell.get(), request.stimuliFile, spec.stimuli, diags);
  const bool wiresOk = robotsOk && checkWiredInputs(request, program.cell.get(), spec.stimuli, diags);
  if (!parts.ok() || !wiresOk || !program.image) return std::nullopt;
  spec.collisions = *parts.collisions;
  spec.limits = limitsOf(request, *parts.maxTime, defaultMaxSteps);
  return spec;
}

std::optional<runtime::CellRunSpec> prepareCellRun(const CellPrograms& programs, const RunRequest& request,
                                                   std::vector<diag::Diagnostic>& diags, std::uint64_t defaultMaxSteps) {
  runtime::CellRunSpec spec;
  spec.cell = programs.cell;
  spec.programs = programs.programs;
  const RequestParts parts = readRequest(request, spec.stimuli, diags);
  std::vector<bool> running(programs.cell ? programs.cell->robots.size() : 0, false);
  for (const runtime::CellProgram& p : spec.programs)
    if (p.robot < running.size()) running[p.robot] = true;
  const bool robotsOk =
      parts.stimuliOk && placeStimuliOnRobots(programs.cell.get(), request.stimuliFile, spec.stimuli, diags, &running);
  if (!parts.ok() || !robotsOk || !programs.ok()) return std::nullopt;
  if (const std::string problem = runtime::checkCellRunSpec(spec); !problem.empty()) {
    diags.push_back({request.stimuliFile.empty() ? std::string("--stimuli") : request.stimuliFile, {},
                     diag::Severity::Error, problem});
    return std::nullopt;
  }
  spec.collisions = *parts.collisions;
  spec.limits = limitsOf(request, *parts.maxTime, defaultMaxSteps);
  return spec;
}

}  // namespace rs::launch
