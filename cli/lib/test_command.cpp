#include "cli/lib/test_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "base/file_io.h"
#include "cli/lib/exit_codes.h"
#include "testrun/suite.h"
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

nlohmann::json diagnosticJson(const diag::Diagnostic& d) {
  nlohmann::json j = {{"file", d.file},
                      {"line", d.pos.line},
                      {"column", d.pos.col},
                      {"severity", diag::severityName(d.severity)},
                      {"message", d.message}};
  if (!d.hint.empty()) j["hint"] = d.hint;
  return j;
}

}  // namespace

CLI::App* addTestCommand(CLI::App& app, TestOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "test", "Check programs against the expectations written in them (folders: every .rsp, recursively)");
  cmd->add_option("paths", o.paths, "Programs and folders (default: the current folder)");
  cmd->add_option("--lib", o.libDirs, "Also look up description names in this directory (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--junit", o.junit, "Also write JUnit XML to this file (for CI test reports)");
  cmd->add_option("--format", o.format, "Output: text (one line per test) or json")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--filter", o.filter, "Only the programs whose path contains this text");
  cmd->add_option("-j,--jobs", o.jobs, "Tests run at once (default: the number of cores)")
      ->check(CLI::Range(1u, 1024u));
  cmd->add_option("--shard", o.shard, "Only part K of N (K/N), for spreading a suite over CI jobs");
  cmd->add_flag("--coverage", o.coverage, "Print each program with how often each line ran and which way jumps went");
  cmd->add_option("--lcov", o.lcov, "Write the coverage as an LCOV tracefile (genhtml makes pages of it)");
  return cmd;
}

int testCommand(const TestOptions& o, std::ostream& out, std::ostream& err) {
  std::uint32_t shard = 1, shards = 1;
  if (!o.shard.empty() && !parseShard(o.shard, shard, shards)) {
    err << fmt::format("robotsim: error: --shard takes K/N with 1 <= K <= N, e.g. 2/4, not '{}'\n", o.shard);
    return kExitBadInput;
  }
  const auto started = std::chrono::steady_clock::now();
  const std::vector<std::string> paths = o.paths.empty() ? std::vector<std::string>{"."} : o.paths;
  const testrun::Selection selection = testrun::selectTests(paths, o.filter, shard, shards);
  for (const diag::Diagnostic& d : selection.errors) err << diag::render(d, nullptr);
  if (!selection.errors.empty()) return kExitBadInput;

  const bool json = o.format == "json";
  const unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::vector<testrun::TestResult> results;
  std::size_t passed = 0, failed = 0, errors = 0;
  testrun::runTests(selection.files, o.libDirs, jobs, o.coverage || !o.lcov.empty(), [&](const testrun::TestResult& r) {
    passed += r.status == testrun::TestStatus::Passed;
    failed += r.status == testrun::TestStatus::Failed;
    errors += r.status == testrun::TestStatus::Error;
    if (!json) {
      out << fmt::format("{} {}", r.file, testrun::statusName(r.status));
      if (r.status == testrun::TestStatus::Passed)
        out << fmt::format(" ({} expectation{}, {} s simulated)", r.expectations, r.expectations == 1 ? "" : "s",
                           vm::formatSeconds(r.simulated));
      out << '\n';
      for (const diag::Diagnostic& d : r.problems) out << diag::render(d, r.sourceOf(d.file));
      out.flush();
    }
    results.push_back(r);
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  if (json) {
    nlohmann::json tests = nlohmann::json::array();
    for (const testrun::TestResult& r : results) {
      nlohmann::json problems = nlohmann::json::array();
      for (const diag::Diagnostic& d : r.problems) problems.push_back(diagnosticJson(d));
      tests.push_back({{"file", r.file},
                       {"status", testrun::statusName(r.status)},
                       {"expectations", r.expectations},
                       {"time", static_cast<double>(r.simulated) / 1e6},
                       {"steps", r.steps},
                       {"problems", problems}});
    }
    const nlohmann::json summary = {
        {"passed", passed}, {"failed", failed}, {"errors", errors}, {"tests", tests}};
    out << summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  } else {
    out << fmt::format("{} passed, {} failed, {} error{} in {:.2f} s\n", passed, failed, errors, errors == 1 ? "" : "s",
                       seconds);
  }
  if (o.coverage && !json)
    for (const testrun::TestResult& r : results)
      if (r.coverage && !r.sources.empty()) out << '\n' << testrun::annotatedListing(*r.sources.front(), *r.coverage);
  if (!o.lcov.empty()) {
    std::string tracefile;
    for (const testrun::TestResult& r : results)
      if (r.coverage) tracefile += testrun::lcovRecord(r.file, *r.coverage);
    std::string error;
    if (!base::writeFileAtomically(o.lcov, tracefile, error)) {
      err << fmt::format("{}: error: cannot write: {}\n", o.lcov, error);
      return kExitBadInput;
    }
  }
  if (!o.junit.empty()) {
    std::string error;
    if (!base::writeFileAtomically(o.junit, testrun::junitXml(results), error)) {
      err << fmt::format("{}: error: cannot write: {}\n", o.junit, error);
      return kExitBadInput;
    }
  }
  if (errors) return kExitBadInput;
  return failed ? kExitRunFailed : kExitOk;
}

}  // namespace rs::cli
