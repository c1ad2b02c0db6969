// One robot's trace in a cell of several (runtime/run/cell_run.h): the
// run's own trace writer into a buffer, each line then given the robot's
// label (text: "left: ...", JSON: a "robot" field) on its way out, so that
// the robots' lines interleave as they happen. `run --cell --trace` prints
// it; `robotsim test` compares a cell's golden trace with it.
#pragma once

#include <cstdint>
#include <ostream>
#include <sstream>
#include <string>

#include "runtime/run/run.h"
#include "runtime/run/trace.h"

namespace rs::runtime {

class LabelledTrace final : public vm::StepObserver {
 public:
  LabelledTrace(std::ostream& out, TraceFormat format, const Run& run, std::string label)
      : out_(out), json_(format == TraceFormat::Json), label_(std::move(label)), writer_(buffer_, format, run) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  /// After the run: what the writer says at the end.
  void finish();

 private:
  void flush();
  std::ostream& out_;
  bool json_;
  std::string label_;
  std::ostringstream buffer_;
  TraceWriter writer_;
};

}  // namespace rs::runtime
