#include "tools/cli/lib/cell_run_command.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "base/seconds.h"
#include "base/text.h"
#include "launch/cell_controllers.h"
#include "launch/cell_programs.h"
#include "launch/run_diagnostics.h"
#include "launch/run_request.h"
#include "runtime/run/cell_run.h"
#include "runtime/run/labelled_trace.h"
#include "runtime/run/trace.h"
#include "tools/cli/lib/cell_profile.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/report.h"
#include "tools/cli/lib/run_warnings.h"
#include "vm/io_lines.h"
#include "vm/stop_reason.h"

namespace rs::cli {

namespace {

using Json = nlohmann::ordered_json;

std::string_view endName(const runtime::CellRun& cell, std::size_t p) {
  const runtime::Run& run = cell.robot(p);
  if (cell.end(p) == runtime::RobotEnd::Stopped) return "stopped";
  if (!run.outcome()) return "running";
  return vm::stopReasonName(run.outcome()->reason);
}

void printRobotText(std::ostream& out, const runtime::CellRun& cell, std::size_t p) {
  const runtime::Run& run = cell.robot(p);
  const vm::Image& im = *run.spec().image;
  const vm::Machine& m = run.rig().machine();
  std::string where;
  if (run.outcome() && !run.outcome()->ok()) where = fmt::format(" at line {}", im.lines[run.outcome()->index]);
  else if (cell.end(p) == runtime::RobotEnd::Stopped) where = fmt::format(" at line {}", run.view().line);
  out << fmt::format("robot {}: {} on {}: {}{}\n", base::safeText(cell.label(p)), base::safeText(im.sourceName),
                     base::safeText(im.robotName), endName(cell, p), where);
  out << fmt::format("  simulated time  {} s\n", base::formatSeconds(cell.endTime(p)));
  out << fmt::format("  instructions    {} executed\n", run.interpreter().steps());
  std::string motors;
  const auto pos = m.positions();
  for (std::size_t i = 0; i < pos.size(); ++i) motors += fmt::format("{}{}={}", i ? "  " : "", im.motors[i].letter, pos[i]);
  out << fmt::format("  motors          {}\n", motors);
  if (const auto tcp = run.rig().tcp()) out << fmt::format("  tool centre     {}\n", runtime::pointText(*tcp));
  out << fmt::format("  outputs         {}\n", runtime::lampText(m.outputs()));
  out << fmt::format("  inputs          {}\n", runtime::lampText(m.inputs()));
  std::string vars;
  for (std::size_t i = 0; i < im.variables.size(); ++i)
    vars += fmt::format("{}{}={}", i ? "  " : "", base::safeText(im.variables[i]), run.interpreter().variables()[i]);
  out << fmt::format("  variables       {}\n", vars.empty() ? "none" : vars);
}

Json robotJson(const runtime::CellRun& cell, std::size_t p, const std::string& file) {
  const runtime::Run& run = cell.robot(p);
  Json j = {{"name", cell.label(p)}, {"program", file}, {"status", endName(cell, p)}};
  j["time"] = static_cast<double>(cell.endTime(p)) / 1e6;
  j["steps"] = run.interpreter().steps();
  j["motors"] = motorsJson(run);
  if (const auto tcp = run.rig().tcp()) j["tcp"] = runtime::roundedPoint(*tcp);
  addLinesAndVariablesJson(j, run);
  return j;
}

Json diagnosticsJson(std::span<const diag::Diagnostic> diags) {
  Json out = Json::array();
  for (const diag::Diagnostic& d : diags) out.push_back(diagnosticJson(d));
  return out;
}

void printErrorJson(std::ostream& out, std::span<const diag::Diagnostic> diags) {
  out << Json{{"status", "error"}, {"robots", Json::array()}, {"diagnostics", diagnosticsJson(diags)}}.dump(
             -1, ' ', false, nlohmann::json::error_handler_t::replace)
      << '\n';
}

void printSummary(std::ostream& out, const runtime::CellRun& cell, const vm::RunOutcome& outcome,
                  const launch::CellPrograms& programs, std::span<const diag::Diagnostic> diags, bool json,
                  bool checkOk, const std::vector<std::optional<runtime::Profile>>& profiles) {
  const bool ok = outcome.ok() && !diag::hasErrors(diags);
  if (json) {
    Json j;
    j["status"] = ok ? vm::stopReasonName(vm::StopReason::End) : "error";
    j["time"] = static_cast<double>(cell.clock()) / 1e6;
    Json robots = Json::array();
    for (std::size_t p = 0; p < cell.size(); ++p) {
      robots.push_back(robotJson(cell, p, programs.files[p]));
      if (profiles[p]) robots.back()["profile"] = cellProfileJson(cell, p, *profiles[p]);
    }
    j["robots"] = robots;
    addCellJson(j, cell.robot(0));
    j["diagnostics"] = diagnosticsJson(diags);
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    return;
  }
  if (checkOk) {  // check: one line per robot, as a check of one program says
    for (std::size_t p = 0; p < cell.size(); ++p)
      out << fmt::format("robot {}: {}: ok ({} instructions executed, {} s simulated)\n",
                         base::safeText(cell.label(p)), base::safeText(cell.robot(p).spec().image->sourceName),
                         cell.robot(p).interpreter().steps(), base::formatSeconds(cell.endTime(p)));
    return;
  }
  out << fmt::format("run of cell {}: {}\n", base::safeText(cell.cell().name),
                     outcome.ok() ? vm::stopReasonName(vm::StopReason::End) : vm::stopReasonName(outcome.reason));
  out << fmt::format("  simulated time  {} s\n", base::formatSeconds(cell.clock()));
  for (std::size_t p = 0; p < cell.size(); ++p) printRobotText(out, cell, p);
  std::ostringstream lines;
  printCellLines(lines, cell.robot(0));
  if (!lines.str().empty()) out << "cell:\n" << lines.str();
}

}  // namespace

std::vector<diag::Diagnostic> cellRunDiagnostics(const runtime::CellRun& cell, const vm::RunOutcome& outcome,
                                                 runtime::CollisionMode collisions) {
  std::vector<diag::Diagnostic> out;
  for (std::size_t p = 0; p < cell.size(); ++p) {
    const runtime::Run& run = cell.robot(p);
    const std::string& file = run.spec().image->sourceName;
    std::vector<diag::Diagnostic> said = launch::runDiagnostics(run, collisions, file);
    for (diag::Diagnostic& d : said)
      if (d.severity == diag::Severity::Error) d.hint += fmt::format("{}robot {} stopped the cell", d.hint.empty() ? "" : "; ", cell.label(p));
    out.insert(out.end(), said.begin(), said.end());
  }
  if (!outcome.ok() && !cell.failed()) {
    // The cell stopped them all: one error, at the first waiting robot's line.
    for (std::size_t p = 0; p < cell.size(); ++p) {
      if (cell.end(p) != runtime::RobotEnd::Stopped) continue;
      const runtime::Run& run = cell.robot(p);
      out.push_back({run.spec().image->sourceName, {run.view().line, 1}, diag::Severity::Error, outcome.message,
                     outcome.reason == vm::StopReason::Deadlock ? "deadlock" : "",
                     outcome.reason == vm::StopReason::Deadlock ? launch::kCellDeadlockHint : ""});
      break;
    }
  }
  return out;
}

std::optional<int> runCellIfSeveral(const RunCommandOptions& o, bool check, std::ostream& out, std::ostream& err,
                                    std::shared_ptr<const launch::LoadedCell>* readCell) {
  launch::ProgramRequest request = o.program;
  std::vector<std::string> assignments = o.programs;
  std::error_code ec;
  if (launch::isProgramAssignment(request.file) && !std::filesystem::exists(request.file, ec))
    assignments.insert(assignments.begin(), request.file), request.file.clear();
  if (request.cell.empty()) {
    if (request.file.empty() || !assignments.empty()) {
      err << "robotsim: error: which program? give a program file, or --cell CELL to run every PROGRAM its ROBOT "
             "lines name (LABEL=FILE gives or overrides one)\n";
      return kExitBadInput;
    }
    return std::nullopt;
  }
  launch::CellPrograms programs;
  const auto sourceOf = [&programs](const std::string& file) { return programs.sourceOf(file); };
  if (!launch::assignCellPrograms(request, assignments, programs)) {
    // A program alone on a cell that does not load: the run of one says why, as always.
    if (!request.file.empty() && assignments.empty()) return std::nullopt;
    std::vector<diag::Diagnostic> all = programs.allDiagnostics();
    launch::printDiagnostics(err, all, sourceOf, request.maxErrors, {});
    if (o.format == "json") printErrorJson(out, all);
    return kExitBadInput;
  }
  if (programs.programs.empty() && !request.file.empty()) {
    if (readCell)
      *readCell = std::make_shared<const launch::LoadedCell>(
          launch::LoadedCell{programs.cell, programs.cellLoad.descriptions, programs.cellLoad.diagnostics});
    return std::nullopt;
  }
  if (programs.programs.size() == 1) {
    // One robot has a program: the run of one, as always.
    if (!request.file.empty()) return std::nullopt;
    RunCommandOptions one = o;
    one.program.file = programs.files[0], one.program.robot = programs.labels[0], one.programs.clear();
    // --device LABEL=DEVICE naming that robot is its --device.
    for (std::string* arg : {&one.serial.device, &one.serial.logFile})
      if (arg->starts_with(programs.labels[0] + "=")) arg->erase(0, programs.labels[0].size() + 1);
    return runOrCheck(one, check, out, err);
  }
  launch::compileAssignedPrograms(request, programs);
  // check: a program that does not compile is checked alone, each in its file.
  if (check && !programs.ok()) return std::nullopt;
  // Each program's load read the cell again: its warnings are said once.
  std::vector<diag::Diagnostic> diags = programs.diagnosticsOnce();
  // --strict: a compile warning fails the check before anything runs.
  const bool strict = check && o.strict;
  const bool compileFailed = strict && promoteWarnings(diags);
  // A profile reads each robot's log: --max-steps then defaults as for one robot's.
  std::optional<runtime::CellRunSpec> spec =
      compileFailed ? std::nullopt
                    : launch::prepareCellRun(programs, o.run, diags,
                                             o.profile ? kProfileMaxSteps : vm::RunLimits{}.maxSteps);
  if (spec && o.profile) spec->log = true;
  launch::printDiagnostics(err, diags, sourceOf, request.maxErrors, {});
  if (!spec) {
    if (o.format == "json") printErrorJson(out, diags);
    return kExitBadInput;
  }

  // Each robot named by --device drives its own controller; opened last,
  // once everything else is known to be right, and kept until the run is gone.
  std::vector<std::unique_ptr<rhino::RhinoMachine>> controllers;
  if (o.serial.active()) {
    std::vector<diag::Diagnostic> problems;
    const std::optional<std::vector<launch::SerialRequest>> devices =
        launch::cellDevices(o.serial, programs, problems);
    std::optional<std::vector<std::unique_ptr<rhino::RhinoMachine>>> opened;
    if (devices) opened = launch::openCellControllers(*devices, programs, spec->limits.maxTime, problems);
    launch::printDiagnostics(err, problems, sourceOf, request.maxErrors, {});
    if (!opened) {
      if (o.format == "json") printErrorJson(out, problems);
      return devices ? kExitRunFailed : kExitBadInput;
    }
    controllers = std::move(*opened);
    for (std::size_t p = 0; p < controllers.size(); ++p) spec->programs[p].follower = controllers[p].get();
  }
  runtime::CellRun cell(*spec);
  std::vector<std::unique_ptr<runtime::LabelledTrace>> traces;
  if (!o.trace.empty())
    for (std::size_t p = 0; p < cell.size(); ++p) {
      traces.push_back(std::make_unique<runtime::LabelledTrace>(
          out, o.trace == "json" ? runtime::TraceFormat::Json : runtime::TraceFormat::Text, cell.robot(p), cell.label(p)));
      cell.observe(p, *traces.back());
    }
  const vm::RunOutcome outcome = cell.runToEnd();
  for (auto& t : traces) t->finish();
  std::vector<diag::Diagnostic> said = cellRunDiagnostics(cell, outcome, spec->collisions);
  const bool failedStrict = strict && promoteWarnings(said);
  printRunWarnings(err, said, programs.loaded.front());
  diags.insert(diags.end(), said.begin(), said.end());

  const bool ok = outcome.ok() && !diag::hasErrors(diags);
  const std::vector<std::optional<runtime::Profile>> profiles =
      o.profile ? cellProfiles(cell) : std::vector<std::optional<runtime::Profile>>(cell.size());
  printSummary(out, cell, outcome, programs, diags, o.format == "json", check && ok, profiles);
  if (o.profile && o.format != "json") printCellProfiles(out, cell, profiles);
  return ok && !failedStrict ? kExitOk : kExitRunFailed;
}

}  // namespace rs::cli
