#include "tools/cli/lib/run_warnings.h"

namespace rs::cli {

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
