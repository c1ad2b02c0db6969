// The end-of-run summary, for people (text) and for tools (one JSON object).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <vector>

#include "diag/diagnostic.h"
#include "runtime/run/profile.h"
#include "runtime/run/run.h"
#include "runtime/rhino/rhino_machine.h"
#include "vm/interpreter.h"

namespace rs::cli {

/// What a run left behind; `run` is null when nothing ran (the program did
/// not compile or load), and its outcome is set once it finished.
struct RunReport {
  const runtime::Run* run = nullptr;
  bool realTime = false;                      // ran on a real controller: the clock is wall time
  std::vector<diag::Diagnostic> diagnostics;  // compile + runtime
  std::size_t maxDiagnostics = 0;             // --max-errors: the JSON lists at most this many (0 = all)
  diag::Omitted omitted;                      // found beyond those kept
  /// A serial run that ended in a controller failure: which motors' places
  /// are uncertain, which outputs were left ON.
  std::optional<rhino::FaultState> fault;
  std::optional<runtime::Profile> profile;  // --profile: where the time went
  /// The cell's lines (objects, placing, devices): a cell of several robots prints them once, not per robot.
  bool cellLines = true;
  bool ok() const;
};

void printTextSummary(std::ostream& out, const RunReport& report);
/// The cell's lines of a text summary as `run` sees the cell: its objects, how they were placed, its devices.
void printCellLines(std::ostream& out, const runtime::Run& run);
/// One diagnostic as the JSON summaries list it (file, line, column, severity, message, code, hint).
nlohmann::ordered_json diagnosticJson(const diag::Diagnostic& d);
/// A run's motors as JSON (`{"E": 0, ...}`).
nlohmann::ordered_json motorsJson(const runtime::Run& run);
/// A run's `outputs`, `inputs` and `variables`, into `j`.
void addLinesAndVariablesJson(nlohmann::ordered_json& j, const runtime::Run& run);
/// The same in JSON: `objects` and (with devices) `devices`, into `j`.
void addCellJson(nlohmann::ordered_json& j, const runtime::Run& run);
void printJsonSummary(std::ostream& out, const RunReport& report);

}  // namespace rs::cli
