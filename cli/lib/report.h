// The end-of-run summary, for people (text) and for tools (one JSON object).
#pragma once

#include <optional>
#include <ostream>
#include <vector>

#include "diag/diagnostic.h"
#include "model/workcell/grasp.h"
#include "model/workcell/tool_tracker.h"
#include "vm/interpreter.h"

namespace rs::cli {

/// What a run left behind; `outcome` is empty when nothing ran (the program
/// did not compile or load).
struct RunReport {
  std::optional<vm::RunOutcome> outcome;
  const vm::Image* image = nullptr;
  const vm::Interpreter* vm = nullptr;
  workcell::ToolTracker* tool = nullptr;  // set when the program ran on a workcell
  workcell::Grasping* grasping = nullptr;  // likewise: where its objects ended
  const workcell::Workcell* cell = nullptr;
  bool realTime = false;                  // ran on a real controller: the clock is wall time
  std::vector<diag::Diagnostic> diagnostics;  // compile + runtime
  bool ok() const;
};

void printTextSummary(std::ostream& out, const RunReport& report);
void printJsonSummary(std::ostream& out, const RunReport& report);

/// A runtime stop as a diagnostic at the instruction's source position.
diag::Diagnostic runtimeDiagnostic(const vm::Image& image, const vm::RunOutcome& outcome, const std::string& file);

}  // namespace rs::cli
