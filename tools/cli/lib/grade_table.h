// The table `robotsim test --spec` ends with (docs/testing.md, "Grading"):
// one row per program with its points out of the most it could earn, the
// scenarios it passed, and for each scenario its points and the program's
// simulated time in it; as aligned text, as CSV (a column per scenario) and
// as JSON.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/testrun/test_file.h"

namespace rs::cli {

struct ScenarioGrade {
  std::string name;
  std::int64_t points = 0, maxPoints = 0;  ///< hundredths
  vm::Micros time = 0;                     ///< the program's simulated time in this scenario
  testrun::TestStatus status = testrun::TestStatus::Passed;
  bool ran = false;  ///< the program compiled and ran in it (else its time is shown as "-")
};

struct GradeRow {
  std::string file;
  std::size_t passed = 0, total = 0;
  std::int64_t points = 0, maxPoints = 0;  ///< hundredths, over its scenarios
  std::vector<ScenarioGrade> scenarios = {};  ///< in the scenario file's order
  std::string firstProblem = {};
};

/// The results of one grading run (in the files' order, each file's
/// scenarios together) as rows.
std::vector<GradeRow> gradeRows(const std::vector<testrun::TestResult>& results);

/// The table as text: a line naming the scenarios and their points, a
/// header, a row per program. Names are made safe to print.
std::string gradeText(const std::vector<testrun::TestResult>& results);

/// The table as CSV (RFC 4180 quoting): file, points, max_points, passed,
/// scenarios, then `points [NAME]` and `simulated_seconds [NAME]` for each
/// scenario, then first_problem.
std::string gradeCsv(const std::vector<testrun::TestResult>& results);

/// The rows for --format=json's `programs`.
nlohmann::json gradeJson(const std::vector<testrun::TestResult>& results);

}  // namespace rs::cli
