#include "tools/cli/lib/run_command.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "base/seconds.h"
#include "base/text.h"
#include "tools/cli/lib/cell_run_command.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/options.h"
#include "tools/cli/lib/profile_report.h"
#include "tools/cli/lib/report.h"
#include "tools/cli/lib/run_warnings.h"
#include "tools/cli/lib/serial_commands.h"
#include "runtime/run/trace.h"
#include "launch/run_diagnostics.h"
#include "runtime/run/run.h"

namespace rs::cli {

namespace {

// --strict: a compile warning fails the check like an error, before
// anything runs.
void promoteCompileWarnings(launch::LoadedProgram& program) {
  bool promoted = promoteWarnings(program.diagnostics);
  if (program.omitted.warnings > 0) {  // those not kept count the same
    program.omitted.errors += program.omitted.warnings;
    program.omitted.warnings = 0;
    promoted = true;
  }
  if (promoted) program.image.reset();
}

}  // namespace

int runOrCheck(const RunCommandOptions& o, bool check, std::ostream& out, std::ostream& err) {
  launch::ProgramRequest request = o.program;
  if (const std::optional<int> code = runCellIfSeveral(o, check, out, err, &request.loadedCell)) return *code;
  const bool json = o.format == "json";
  if (o.profile && o.serial.active()) {
    err << "--profile: error: a profile is computed from the simulated run's log: leave out --device\n";
    return kExitBadInput;
  }
  if (refuseSeveralDevices(o.serial, err)) return kExitBadInput;
  launch::LoadedProgram program = launch::loadProgram(request);
  const bool strict = check && o.strict;
  if (strict) promoteCompileWarnings(program);
  RunReport report;
  report.diagnostics = program.diagnostics;
  report.maxDiagnostics = program.maxErrors;
  report.omitted = program.omitted;
  // The stimuli and limits are checked even when the program did not
  // compile, so that one run reports every mistake.
  // A profile reads the run's log, about 70 bytes a step: without
  // --max-steps, such a run stops at kProfileMaxSteps (700 MB of log), not
  // at the usual 100 million.
  const std::optional<runtime::RunSpec> spec = launch::prepareRun(
      program, o.run, report.diagnostics, o.profile ? kProfileMaxSteps : vm::RunLimits{}.maxSteps);
  if (!spec || !program.ok()) {
    launch::printDiagnostics(err, report.diagnostics, program);
    if (json) printJsonSummary(out, report);
    return kExitBadInput;
  }
  launch::printDiagnostics(err, report.diagnostics, program);  // warnings (the program's and the run's)

  std::unique_ptr<runtime::Run> run;
  const rhino::RhinoMachine* controller = nullptr;  // owned by the run
  if (o.serial.active()) {
    std::vector<diag::Diagnostic> problems;
    std::unique_ptr<rhino::RhinoMachine> rhino =
        launch::openRhino(o.serial, spec->image->motors, spec->limits.maxTime, problems);
    launch::printDiagnostics(err, problems, program);
    if (!rhino) return kExitRunFailed;
    controller = rhino.get();
    run = std::make_unique<runtime::Run>(*spec, std::move(rhino));
  } else {
    runtime::RunSpec simulated = *spec;
    simulated.log = simulated.log || o.profile;  // the profile reads the log
    run = std::make_unique<runtime::Run>(simulated);
  }
  report.realTime = o.serial.active();
  std::optional<runtime::TraceWriter> trace;
  if (!o.trace.empty()) {
    trace.emplace(out, o.trace == "json" ? runtime::TraceFormat::Json : runtime::TraceFormat::Text, *run);
    run->observe(*trace);
  }
  const vm::RunOutcome outcome = run->runToEnd();
  if (trace) trace->finish();
  report.run = run.get();
  if (controller) report.fault = controller->faultState();
  const vm::Image& image = *run->spec().image;
  // The stop and the warnings of the run: the same words the editor shows (launch/run_diagnostics.h).
  // Under --strict the run's warnings fail the check (exit 1: the run is
  // what gave them).
  std::vector<diag::Diagnostic> said = launch::runDiagnostics(*run, spec->collisions, image.sourceName);
  const bool failedStrict = strict && promoteWarnings(said);
  printRunWarnings(err, said, program);
  report.diagnostics.insert(report.diagnostics.end(), said.begin(), said.end());
  if (o.profile && run->log()) report.profile = runtime::profileOf(image, *run->log());
  if (json) printJsonSummary(out, report);
  else if (!check || !report.ok()) printTextSummary(out, report);
  else out << fmt::format("{}: ok ({} instructions executed, {} s simulated)\n", base::safeText(image.sourceName),
                          outcome.steps, base::formatSeconds(run->rig().clock()));
  if (!json && report.profile) printTextProfile(out, *report.profile);
  return outcome.ok() && !failedStrict ? kExitOk : kExitRunFailed;
}

namespace {

// run and check share everything but --trace, --profile and --strict, which
// come between the program file and the rest.
void addRunLikeFile(CLI::App* cmd, RunCommandOptions& o, bool required = true) {
  CLI::Option* file = cmd->add_option("file", o.program.file, "Program source or compiled image");
  if (required) file->required();
}

void addRunLikeRest(CLI::App* cmd, RunCommandOptions& o) {
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
  cmd->add_option("--format", o.format, "Summary format: text or json")->check(CLI::IsMember({"text", "json"}));
  addRunOptions(cmd, o.run);
  addSerialOptions(cmd, o.serial);
}

}  // namespace

void addRunCommandOptions(CLI::App* cmd, RunCommandOptions& o) {
  addRunLikeFile(cmd, o, false);  // without it: every PROGRAM of --cell (cell_run_command.h)
  cmd->add_option("programs", o.programs,
                  "With --cell: LABEL=FILE gives or overrides the program of the cell's robot LABEL; every robot "
                  "with a program runs it on the cell's one clock");
  cmd->add_flag("--trace{text}", o.trace, "Print each executed instruction: --trace (text) or --trace=json");
  cmd->add_flag("--profile", o.profile,
                "Where the time went: by source line, label and subroutine, moving vs waiting vs gripper, the "
                "slowest moves (with --format=json: a \"profile\" member); --max-steps then defaults to 10000000");
  addRunLikeRest(cmd, o);
}

void addCheckCommandOptions(CLI::App* cmd, RunCommandOptions& o) {
  addRunLikeFile(cmd, o, false);  // without it: every PROGRAM of --cell (cell_programs.h)
  cmd->add_flag("--strict", o.strict,
                "Every warning fails the check: the compile's and the cell's (exit 2, nothing runs), the run's "
                "(exit 1)");
  addRunLikeRest(cmd, o);
}

}  // namespace rs::cli
