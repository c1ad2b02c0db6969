#include "tools/testrun/golden_check.h"

#include <fmt/format.h>

#include "base/text.h"
#include "launch/program.h"
#include "tools/testrun/golden_trace.h"

namespace rs::testrun {

bool openGoldenTraces(const ParsedExpectations& parsed, const std::string& settingsFile,
                      std::vector<GoldenTrace>& traces, TestResult& r) {
  for (const Expectation& e : parsed.expectations) {
    if (e.kind != ExpectKind::Trace) continue;
    const diag::Result<std::string> golden = goldenFile(settingsFile, e.name);
    if (!golden) {
      r.status = TestStatus::Error;
      r.problems.push_back({settingsFile, e.pos, diag::Severity::Error, golden.failure().message, {},
                            "golden traces live under the folder of the test that names them"});
      continue;
    }
    GoldenTrace& t = traces.emplace_back();
    t.expectation = &e;
    t.path = *golden;
    t.read = base::readFile(*golden, launch::kMaxInputBytes);
    t.comparer = std::make_unique<TraceComparer>(t.read.bytes ? std::string_view(*t.read.bytes) : std::string_view());
    t.stream = std::make_unique<std::ostream>(t.comparer.get());
  }
  return r.status != TestStatus::Error;
}

namespace {

// A stream buffer that hands at most `limit` bytes on, then swallows the
// rest and says so: a golden trace is never larger than a test can read.
class CappedSink final : public std::streambuf {
 public:
  CappedSink(std::streambuf& to, std::size_t limit) : to_(to), left_(limit) {}
  bool over() const { return over_; }

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (over_ || static_cast<std::size_t>(n) > left_) return over_ = true, n;
    left_ -= static_cast<std::size_t>(n);
    return to_.sputn(s, n);
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    xsputn(&ch, 1);
    return c;
  }

 private:
  std::streambuf& to_;
  std::size_t left_;
  bool over_ = false;
};

// Pauses a run (which then ends early) once its trace is over the cap.
class StopWhenOver final : public vm::StepObserver {
 public:
  explicit StopWhenOver(const CappedSink& sink) : sink_(sink) {}
  bool afterStep(const vm::Interpreter&, std::uint32_t) override { return sink_.over(); }

 private:
  const CappedSink& sink_;
};

// --update: the run is made again (runs are deterministic, so its trace is
// the one compared) and its trace streamed into the golden file, which is
// written whole or not at all.
void rewriteGoldenTrace(const GoldenTrace& t, const TraceRerun& again, const std::string& settingsFile,
                        TestResult& r) {
  bool tooLarge = false;
  std::string error;
  const bool written = base::writeFileAtomically(
      t.path,
      [&](std::ostream& file) {
        CappedSink sink(*file.rdbuf(), launch::kMaxInputBytes);
        std::ostream out(&sink);
        StopWhenOver stop(sink);
        again(out, stop);
        tooLarge = sink.over();
        return !tooLarge;
      },
      error);
  if (written) return r.updated.push_back(t.path);
  r.problems.push_back({settingsFile, t.expectation->pos, diag::Severity::Error,
                        tooLarge ? fmt::format("cannot write {}: the trace is over {}, the most a golden trace may "
                                               "hold",
                                               t.path, base::sizeText(launch::kMaxInputBytes))
                                 : fmt::format("cannot write {}: {}", t.path, error)});
}

}  // namespace

void judgeTrace(const GoldenTrace& t, const TraceRerun* again, const std::string& settingsFile,
                const RunnerOptions& options, TestResult& r) {
  if (t.read.bytes && t.comparer->same()) return;
  if (options.update && again) return rewriteGoldenTrace(t, *again, settingsFile, r);
  const Expectation& e = *t.expectation;
  if (!t.read.bytes) {
    r.problems.push_back({settingsFile, e.pos, diag::Severity::Error,
                          fmt::format("cannot read the golden trace {}: {}", t.path, t.read.error), {},
                          "robotsim test --update writes it from the run"});
    return;
  }
  r.problems.push_back({settingsFile, e.pos, diag::Severity::Error,
                        fmt::format("the trace differs from {} at its line {}: expected '{}', got '{}'", t.path,
                                    t.comparer->line(), t.comparer->expected(), t.comparer->got()),
                        {}, "if the new run is right, robotsim test --update rewrites the golden trace"});
}

}  // namespace rs::testrun
