// The golden traces of one test (`expect: trace FILE`): each file read
// before the run, the stream its trace is compared in as the run writes
// it, the verdict after it, and `--update`'s rewrite from the same run
// made again. A run of one robot (test_file.cpp) and a cell's run
// (cell_test.cpp) write their traces each their own way.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "base/file_io.h"
#include "tools/testrun/expectation.h"
#include "tools/testrun/golden_trace.h"
#include "tools/testrun/test_file.h"
#include "vm/interpreter.h"

namespace rs::testrun {

/// One `expect: trace FILE` of a test: its golden file, read before the
/// run, and the comparer the run's trace is written into.
struct GoldenTrace {
  const Expectation* expectation = nullptr;
  std::string path;
  base::FileRead read;
  std::unique_ptr<TraceComparer> comparer;
  std::unique_ptr<std::ostream> stream;
  /// The writers of the run's trace into `stream` (one a robot in a cell).
  std::vector<std::unique_ptr<vm::StepObserver>> writers;
};

/// The golden files of a test's trace expectations, each inside the test's
/// folder; false (the test cannot start) when one leads out of it.
bool openGoldenTraces(const ParsedExpectations& parsed, const std::string& settingsFile,
                      std::vector<GoldenTrace>& traces, TestResult& r);

/// The run made again, its text trace into the stream; `stop` is to
/// observe every step (it pauses the run once the trace is too large).
using TraceRerun = std::function<void(std::ostream&, vm::StepObserver& stop)>;

/// `expect: trace FILE`: the run's text trace must be the file's bytes;
/// --update (with `again`) writes the file instead when it differs or is
/// missing.
void judgeTrace(const GoldenTrace& t, const TraceRerun* again, const std::string& settingsFile,
                const RunnerOptions& options, TestResult& r);

}  // namespace rs::testrun
