// The thread that makes the checked runs (checked_run.h), so that the
// server's own thread goes on answering while a program runs. One job per
// document at a time: a newer job for the same document replaces one still
// waiting; one being made is abandoned by the server when the document
// changes (RunControl), and ends at its next step. Jobs are made in the
// order they came.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "tools/lsp/cell_run_plan.h"
#include "tools/lsp/json.h"
#include "tools/lsp/program_analysis.h"

namespace rs::lsp {

struct RunJob {
  std::string uri;
  std::int64_t version = 0;
  std::shared_ptr<const ProgramAnalysis> analysis;
  Json compileDiagnostics;  ///< as published for this version, to publish again with the run's
  Encoding enc = Encoding::Utf16;
  RunOptions options;
  /// The other robots' programs it runs with (active: a run of the whole
  /// cell, whose partners' runs are stored in the analyses it claimed).
  CellRunPlan plan;
};

class RunWorker {
 public:
  /// Called on the worker's thread once a job's run is made (and stored in
  /// its analysis), abandoned or not.
  using Done = std::function<void(const RunJob& job, const CheckedRun& run)>;
  explicit RunWorker(Done done);
  /// Abandons the run being made and waits for the thread.
  ~RunWorker();
  RunWorker(const RunWorker&) = delete;
  RunWorker& operator=(const RunWorker&) = delete;

  /// A job whose analysis was asked for its run (ProgramAnalysis::askForRun).
  void submit(RunJob job);
  /// Waits until no job waits or is being made (tests, benchmarks).
  void settle();
  /// The editor's bound on a run's time (checked_run.h); tests shorten it.
  void setBudget(std::chrono::milliseconds budget);

 private:
  void loop();

  Done done_;
  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<RunJob> queue_;
  std::shared_ptr<const ProgramAnalysis> running_;
  bool stopping_ = false;
  std::chrono::milliseconds budget_ = kRunBudget;
  std::thread thread_;  // last: started once everything above is ready
};

}  // namespace rs::lsp
