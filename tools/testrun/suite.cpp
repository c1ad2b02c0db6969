#include "tools/testrun/suite.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "tools/testrun/submissions.h"

namespace rs::testrun {

namespace fs = std::filesystem;

std::uint32_t shardOf(const std::string& path, std::uint32_t shards) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a, 64 bits
  for (const char c : path) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return static_cast<std::uint32_t>(h % shards) + 1;
}

Selection selectTests(const std::vector<std::string>& paths, const std::string& filter, std::uint32_t shard,
                      std::uint32_t shards, bool grading) {
  Selection s;
  std::set<std::string> found;
  const auto kept = [&](const std::string& f) {
    return (filter.empty() || f.find(filter) != std::string::npos) && (shards <= 1 || shardOf(f, shards) == shard);
  };
  if (grading) {
    SubmissionWalk walk = findSubmissions(paths);
    s.errors = std::move(walk.errors);
    for (const RefusedLink& link : walk.refused)
      if (kept(link.path)) s.refused.emplace(link.path, refusalOf(link));
    found.insert(walk.files.begin(), walk.files.end());
    for (const auto& [path, problem] : s.refused) found.insert(path);
  }
  for (const std::string& p : grading ? std::vector<std::string>() : paths) {
    std::error_code ec;
    const fs::file_status st = fs::status(p, ec);
    if (ec || !fs::exists(st)) {
      s.errors.push_back({p, {}, diag::Severity::Error, "no such file or folder"});
      continue;
    }
    if (!fs::is_directory(st)) {
      found.insert(fs::path(p).lexically_normal().string());
      continue;
    }
    fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      std::error_code fileEc;
      const fs::path ext = it->path().extension();
      if ((ext == ".rsp" || ext == ".rstest") && it->is_regular_file(fileEc))
        found.insert(it->path().lexically_normal().string());
    }
    if (ec) s.errors.push_back({p, {}, diag::Severity::Error, "cannot list: " + ec.message()});
  }
  for (const std::string& f : found)
    if (kept(f)) s.files.push_back(f);
  return s;
}

void runTests(const Selection& selection, const RunnerOptions& options, unsigned jobs, const std::string& spec,
              const std::function<void(const TestResult&)>& report) {
  const std::vector<std::string>& files = selection.files;
  const auto one = [&](const std::string& file) -> std::vector<TestResult> {
    if (const auto refused = selection.refused.find(file); refused != selection.refused.end()) {
      TestResult r;
      r.file = file;
      r.status = TestStatus::Error;
      r.problems.push_back(refused->second);
      return {r};
    }
    return spec.empty() ? runTestPath(file, options) : runScenarios(spec, file, options);
  };
  std::vector<std::optional<std::vector<TestResult>>> results(files.size());
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<std::size_t> next = 0;
  const auto work = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < files.size();) {
      std::vector<TestResult> r = one(files[i]);
      const std::lock_guard lock(mutex);
      results[i] = std::move(r);
      ready.notify_one();
    }
  };
  const unsigned threads = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(files.size())));
  std::vector<std::thread> pool;
  if (threads == 1) work();
  else
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
  // The calling thread reports in order as the results arrive.
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::unique_lock lock(mutex);
    ready.wait(lock, [&] { return results[i].has_value(); });
    std::vector<TestResult> r = std::move(*results[i]);
    results[i].reset();
    lock.unlock();
    for (const TestResult& one : r) report(one);
  }
  for (std::thread& t : pool) t.join();
}

namespace {

std::string xml(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // XML 1.0 has no place for other control characters.
        if (u < 0x20 && c != '\n' && c != '\t') out += fmt::format("\\x{:02x}", u);
        else out += c;
    }
  }
  return out;
}

std::string problemText(const diag::Diagnostic& d) {
  const std::string message =
      d.severity == diag::Severity::Warning ? "warning: " + d.message : d.message;  // problems are all errors
  std::string s = d.pos.line ? fmt::format("{}:{}:{}: {}", d.file, d.pos.line, d.pos.col, message)
                             : fmt::format("{}: {}", d.file, message);
  if (!d.hint.empty()) s += " (hint: " + d.hint + ")";
  return s;
}

}  // namespace

std::string junitXml(const std::vector<TestResult>& results) {
  std::size_t failures = 0, errors = 0;
  for (const TestResult& r : results) {
    failures += r.status == TestStatus::Failed;
    errors += r.status == TestStatus::Error;
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format("<testsuites name=\"robotsim test\" tests=\"{}\" failures=\"{}\" errors=\"{}\">\n", results.size(),
                     failures, errors);
  // One testsuite per file: its results come one after the other.
  for (std::size_t first = 0; first < results.size();) {
    std::size_t end = first;
    std::size_t suiteFailures = 0, suiteErrors = 0;
    while (end < results.size() && results[end].file == results[first].file) {
      suiteFailures += results[end].status == TestStatus::Failed;
      suiteErrors += results[end].status == TestStatus::Error;
      ++end;
    }
    const std::string name = xml(results[first].file);
    out += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\">\n", name, end - first,
                       suiteFailures, suiteErrors);
    for (std::size_t i = first; i < end; ++i) {
      const TestResult& r = results[i];
      const std::string testcase = xml(r.name.empty() ? fs::path(r.file).stem().string() : r.name);
      out += fmt::format("    <testcase classname=\"{}\" name=\"{}\"", name, testcase);
      // Warnings (a passing test may have them) go to the test's output.
      std::string warnings;
      for (const diag::Diagnostic& d : r.warnings) warnings += problemText(d) + "\n";
      const std::string systemOut =
          warnings.empty() ? std::string() : fmt::format("      <system-out>{}</system-out>\n", xml(warnings));
      if (r.status == TestStatus::Passed) {
        out += systemOut.empty() ? "/>\n" : ">\n" + systemOut + "    </testcase>\n";
        continue;
      }
      const char* element = r.status == TestStatus::Failed ? "failure" : "error";
      std::string body;
      for (const diag::Diagnostic& d : r.problems) body += problemText(d) + "\n";
      out += fmt::format(">\n      <{} message=\"{}\">{}</{}>\n{}    </testcase>\n", element,
                         r.problems.empty() ? "" : xml(problemText(r.problems.front())), xml(body), element,
                         systemOut);
    }
    out += "  </testsuite>\n";
    first = end;
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace rs::testrun
