#include "tools/cli/lib/test_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <thread>

#include "base/file_io.h"
#include "base/seconds.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/grade_table.h"
#include "tools/cli/lib/number_args.h"
#include "tools/cli/lib/options.h"
#include "tools/cli/lib/report.h"
#include "runtime/run/trace.h"
#include "diag/diagnostic.h"
#include "tools/testrun/suite.h"
#include "vm/interpreter.h"

namespace rs::cli {

namespace {

// "2/5" -> shard 2 of 5.
bool parseShard(const std::string& text, std::uint32_t& k, std::uint32_t& n) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return false;
  const auto whole = [](std::string_view s, std::uint32_t& v) {
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
  };
  return whole(std::string_view(text).substr(0, slash), k) && whole(std::string_view(text).substr(slash + 1), n) &&
         n >= 1 && n <= 100000 && k >= 1 && k <= n;
}

// The command's own errors go through diag::render, as every problem of
// the report does: what they quote (an option's value, a path) may hold a
// terminal escape, and render escapes it.
void printTestCommandError(std::ostream& err, const std::string& where, const std::string& message,
                           const std::string& hint = {}) {
  err << diag::render({where, {}, diag::Severity::Error, message, {}, hint}, nullptr);
}

}  // namespace

void addTestOptions(CLI::App* cmd, TestOptions& o) {
  cmd->add_option("paths", o.paths, "Programs and folders (default: the current folder)");
  cmd->add_option("--lib", o.libDirs, "Also look up description names in this directory (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--junit", o.junit, "Also write JUnit XML to this file (for CI test reports)");
  cmd->add_option("--format", o.format, "Output: text (one line per test), json, or csv (a table per program)")
      ->check(CLI::IsMember({"text", "json", "csv"}));
  cmd->add_option("--filter", o.filter, "Only the programs whose path contains this text");
  cmd->add_option("-j,--jobs", o.jobs, "Tests run at once (default: the number of cores)")
      ->transform(numberArg(rules::kJobs));
  cmd->add_option("--shard", o.shard, "Only part K of N (K/N), for spreading a suite over CI jobs");
  cmd->add_flag("--coverage", o.coverage, "Print each program with how often each line ran and which way jumps went");
  cmd->add_option("--lcov", o.lcov, "Write the coverage as an LCOV tracefile (genhtml makes pages of it)");
  cmd->add_option("--spec", o.spec,
                  fmt::format("Grade: run this scenario file (.rstest) against every program under PATH, each "
                              "confined to its folder, and end with each program's points out of the most (its "
                              "'points' lines; 1 a scenario by default) and each scenario's points and time; a run "
                              "stops at {} instructions or {} simulated seconds unless the scenario says otherwise",
                              testrun::kGradingMaxSteps, testrun::kGradingMaxSeconds));
  cmd->add_flag("--update", o.update, "Write the golden traces of 'expect: trace FILE' from the runs (not when CI is set)");
  addCollisionsOption(cmd, o.collisions);
}

int testCommand(const TestOptions& o, std::ostream& out, std::ostream& err) {
  std::uint32_t shard = 1, shards = 1;
  if (!o.shard.empty() && !parseShard(o.shard, shard, shards)) {
    printTestCommandError(err, "robotsim",
                          fmt::format("--shard takes K/N with 1 <= K <= N, e.g. 2/4, not '{}'", diag::excerpt(o.shard)),
                          "K is this job's part and N how many parts: --shard 2/4 is the second of four");
    return kExitBadInput;
  }
  if (o.update && std::getenv("CI") != nullptr) {
    printTestCommandError(err, "robotsim",
                          "--update refuses to write golden traces when CI is set: a CI run checks them");
    return kExitBadInput;
  }
  const auto started = std::chrono::steady_clock::now();
  const std::vector<std::string> paths = o.paths.empty() ? std::vector<std::string>{"."} : o.paths;
  const testrun::Selection selection = testrun::selectTests(paths, o.filter, shard, shards, !o.spec.empty());
  for (const diag::Diagnostic& d : selection.errors) err << diag::render(d, nullptr);
  if (!selection.errors.empty()) return kExitBadInput;

  const bool json = o.format == "json", csv = o.format == "csv", text = !json && !csv;
  const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::vector<testrun::TestResult> results;
  std::size_t passed = 0, failed = 0, errors = 0;
  testrun::RunnerOptions runner;
  runner.libDirs = o.libDirs;
  runner.coverage = o.coverage || !o.lcov.empty();
  runner.update = o.update;
  runner.collisions = o.collisions;
  testrun::runTests(selection, runner, jobs, o.spec, [&](const testrun::TestResult& r) {
    passed += r.status == testrun::TestStatus::Passed;
    failed += r.status == testrun::TestStatus::Failed;
    errors += r.status == testrun::TestStatus::Error;
    if (text) {
      out << fmt::format("{}{} {}", base::safeText(r.file), r.name.empty() ? "" : " [" + base::safeText(r.name) + "]",
                         testrun::statusName(r.status));
      if (r.status == testrun::TestStatus::Passed)
        out << fmt::format(" ({} expectation{}, {} s simulated{})", r.expectations, r.expectations == 1 ? "" : "s",
                           base::formatSeconds(r.simulated),
                           r.warnings.empty() ? std::string()
                                              : fmt::format(", {} warning{}", r.warnings.size(),
                                                            r.warnings.size() == 1 ? "" : "s"));
      out << '\n';
      for (const diag::Diagnostic& d : r.problems) out << diag::render(d, r.sourceOf(d.file));
      for (const diag::Diagnostic& d : r.warnings) out << diag::render(d, r.sourceOf(d.file));
      for (const std::string& golden : r.updated) out << fmt::format("  updated {}\n", base::safeText(golden));
      out.flush();
    }
    results.push_back(r);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  if (json) {
    nlohmann::json tests = nlohmann::json::array();
    for (const testrun::TestResult& r : results) {
      nlohmann::json problems = nlohmann::json::array();
      for (const diag::Diagnostic& d : r.problems) problems.push_back(nlohmann::json(diagnosticJson(d)));
      nlohmann::json warnings = nlohmann::json::array();
      for (const diag::Diagnostic& d : r.warnings) warnings.push_back(nlohmann::json(diagnosticJson(d)));
      nlohmann::json test = {{"file", r.file},
                             {"scenario", r.name},
                             {"status", testrun::statusName(r.status)},
                             {"expectations", r.expectations},
                             {"time", static_cast<double>(r.simulated) / 1e6},
                             {"steps", r.steps},
                             {"problems", problems},
                             {"warnings", warnings}};
      if (!o.spec.empty() && !r.name.empty()) {  // grading: the scenario's points
        test["points"] = static_cast<double>(r.points) / 100;
        test["max_points"] = static_cast<double>(r.maxPoints) / 100;
      }
      tests.push_back(std::move(test));
    }
    nlohmann::json summary = {{"passed", passed}, {"failed", failed}, {"errors", errors}, {"tests", tests}};
    if (!o.spec.empty()) summary["programs"] = gradeJson(results);  // grading: the table too
    out << summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  } else if (csv) {
    out << gradeCsv(results);
  } else {
    out << fmt::format("{} passed, {} failed, {} error{} in {:.2f} s\n", passed, failed, errors, errors == 1 ? "" : "s",
                       seconds);
    if (!o.spec.empty()) out << '\n' << gradeText(results);
  }
  // Each program once, over every test that ran it.
  std::vector<std::vector<testrun::ProgramCoverage>> ran;
  for (const testrun::TestResult& r : results) ran.push_back(r.coverage);
  const std::vector<testrun::ProgramCoverage> coverage = testrun::mergedCoverage(ran);
  if (o.coverage && text)
    for (const testrun::ProgramCoverage& c : coverage)
      if (c.source) out << '\n' << testrun::annotatedListing(*c.source, c.counts);
  if (!o.lcov.empty()) {
    std::string tracefile;
    for (const testrun::ProgramCoverage& c : coverage) tracefile += testrun::lcovRecord(c.file, c.counts);
    std::string error;
    if (!base::writeFileAtomically(o.lcov, tracefile, error)) {
      printTestCommandError(err, o.lcov, "cannot write: " + error);
      return kExitBadInput;
    }
  }
  if (!o.junit.empty()) {
    std::string error;
    if (!base::writeFileAtomically(o.junit, testrun::junitXml(results), error)) {
      printTestCommandError(err, o.junit, "cannot write: " + error);
      return kExitBadInput;
    }
  }
  if (errors) return kExitBadInput;
  return failed ? kExitRunFailed : kExitOk;
}

}  // namespace rs::cli
