#include "cli/lib/run_warnings.h"

#include <fmt/format.h>

#include "runtime/run/empty_close.h"

namespace rs::cli {

std::vector<diag::Diagnostic> runWarnings(const runtime::Run& run, runtime::CollisionMode mode,
                                          const std::string& file) {
  std::vector<diag::Diagnostic> out;
  const vm::Image& image = run.image();
  if (const runtime::CollisionWatch* watch = run.collisionWatch(); watch && mode == runtime::CollisionMode::Warn)
    for (const runtime::CollisionEvent& e : run.collisions()) {
      const bool known = e.instruction < image.code.size();
      const std::string seconds = vm::formatSeconds(e.at);
      out.push_back({file, known ? diag::Pos{image.lines[e.instruction], image.columns[e.instruction]} : diag::Pos{},
                     diag::Severity::Warning,
                     fmt::format("collision at {} s: {} (--collisions=warn: the run went on)", seconds,
                                 watch->describe(e.contact)),
                     "collision",
                     fmt::format("'robotsim render CELL --program PROG --at {} --collision-shapes' draws it; "
                                 "--collisions=error stops the run there",
                                 seconds)});
    }
  if (std::optional<diag::Diagnostic> w = runtime::gripperWarning(run, file)) out.push_back(std::move(*w));
  return out;
}

void printRunWarnings(std::ostream& err, const std::vector<diag::Diagnostic>& warnings,
                      const launch::LoadedProgram& program) {
  launch::printDiagnostics(
      err, warnings, [&program](const std::string& file) { return program.sourceOf(file); }, program.maxErrors, {});
}

bool promoteWarnings(std::vector<diag::Diagnostic>& diags) {
  bool promoted = false;
  for (diag::Diagnostic& d : diags)
    if (d.severity == diag::Severity::Warning) {
      d.severity = diag::Severity::Error;
      d.message += " [--strict]";
      promoted = true;
    }
  return promoted;
}

}  // namespace rs::cli
