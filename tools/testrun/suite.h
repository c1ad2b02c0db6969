// Many tests: the files under the paths given (folders searched for `.rsp`
// programs, recursively, in name order), narrowed by a filter and to one
// shard of N, run on several threads with the results handed out in the
// files' order whatever the number of threads.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "tools/testrun/test_file.h"

namespace rs::testrun {

struct Selection {
  std::vector<std::string> files;        ///< sorted, each once
  std::vector<diag::Diagnostic> errors;  ///< paths that do not exist or cannot be listed
  /// Grading: the links refused (tools/testrun/submissions.h), which are in
  /// `files` too, each with its problem.
  std::map<std::string, diag::Diagnostic> refused;
};

/// `filter`: keep files whose path contains it ("" keeps all). `shard` K of
/// `shards` N (1-based): keep the files whose path hashes to K (FNV-1a of
/// the path modulo N), so a file's shard never depends on the others.
/// Folders give `.rsp` programs and `.rstest` files; `grading` (--spec),
/// `.rsp` programs only, each confined to its folder (findSubmissions).
Selection selectTests(const std::vector<std::string>& paths, const std::string& filter, std::uint32_t shard,
                      std::uint32_t shards, bool grading = false);

/// The shard (1..shards) a path belongs to.
std::uint32_t shardOf(const std::string& path, std::uint32_t shards);

/// Runs every file of the selection on `jobs` threads (counting coverage
/// when asked), or, with a `spec` scenario file, its scenarios against
/// every file (a refused one is an error, never read); `report` is called
/// once per result, in the files' order, from the calling thread.
void runTests(const Selection& selection, const RunnerOptions& options, unsigned jobs, const std::string& spec,
              const std::function<void(const TestResult&)>& report);

/// JUnit XML: one testsuite per file, one testcase per scenario (or the
/// program's own expectations); a failure or an error element with every
/// problem as `file:line:col: message`.
std::string junitXml(const std::vector<TestResult>& results);

}  // namespace rs::testrun
