// `expect: trace FILE`: the run's text trace (as `robotsim run --trace`
// prints it) against a golden file, compared as the trace is written: a
// run of 100 million instructions keeps the golden file and the line being
// compared, not its gigabytes of trace. A golden file lives under its
// test's folder (the program's, or the scenario file's): `--update` writes
// nowhere else, and a test reads nothing else through it.
#pragma once

#include <cstddef>
#include <streambuf>
#include <string>
#include <string_view>

#include "diag/result.h"

namespace rs::testrun {

/// The path of the golden file `name` of the test `testFile`: relative to
/// the test's folder and inside it once symbolic links are followed; else a
/// failure with no place (diag::refusal) that says where it leads.
diag::Result<std::string> goldenFile(const std::string& testFile, const std::string& name);

/// Whether a golden file's name, as written, stays under the test's folder
/// (relative, no `..` that leaves it): checked when the line is read.
bool staysUnderFolder(std::string_view name);

/// A stream buffer that compares the bytes written to it with `golden` as
/// they come, and keeps only the line where they first differ.
class TraceComparer final : public std::streambuf {
 public:
  explicit TraceComparer(std::string_view golden) : golden_(golden) {}
  /// After the run: every byte matched and none is missing.
  bool same() const { return !differs_ && pos_ == golden_.size(); }
  /// When not same(): the first line that differs (1-based) and that line
  /// in the golden file and in the trace (a long one cut to its start).
  std::size_t line() const { return line_ + 1; }
  std::string expected() const;
  std::string got() const;

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;

 private:
  void differAt(char c);

  std::string_view golden_;
  std::size_t pos_ = 0;        // bytes that matched
  std::size_t line_ = 0;       // newlines among them
  std::size_t lineStart_ = 0;  // where the line being compared starts
  bool differs_ = false;
  bool capturing_ = false;  // the rest of the trace's differing line
  std::string got_;
};

}  // namespace rs::testrun
