#include "lsp/program_analysis.h"

#include <fmt/format.h>

#include "runtime/run/run.h"

namespace rs::lsp {

namespace {

// Notes when each instruction first starts and ends, and how often it runs.
class Timer final : public vm::StepObserver {
 public:
  explicit Timer(std::vector<InstructionTimes>& times) : times_(times) {}
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override {
    const vm::Micros now = vm.machine().now();
    if (index < times_.size()) {
      InstructionTimes& t = times_[index];
      if (t.runs++ == 0) t.start = before_, t.end = now;
    }
    before_ = now;
    return false;
  }

 private:
  std::vector<InstructionTimes>& times_;
  vm::Micros before_ = 0;
};

std::string outcomeText(const vm::RunOutcome& outcome, vm::Micros clock) {
  switch (outcome.reason) {
    case vm::StopReason::End: return fmt::format("finished at {}", formatSeconds(clock));
    case vm::StopReason::RuntimeError: return fmt::format("stopped by an error at {}", formatSeconds(clock));
    case vm::StopReason::Deadlock:
      return fmt::format("waits forever for an input at {} (no stimuli in the default run)", formatSeconds(clock));
    case vm::StopReason::StepLimit:
    case vm::StopReason::TimeLimit:
    case vm::StopReason::InstantLimit:
    case vm::StopReason::Paused:
      return fmt::format("still running at {} after {} instructions (the editor's run stops there)",
                         formatSeconds(clock), kHintRunSteps);
  }
  return {};
}

}  // namespace

std::string formatSeconds(vm::Micros t) {
  std::string s = fmt::format("{}.{:06}", t / 1'000'000, t % 1'000'000);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s + " s";
}

ProgramAnalysis::ProgramAnalysis(std::string path, std::string text, std::shared_ptr<const CellContext> cell,
                                 std::optional<launch::CellDirective> directive)
    : source_(std::move(path), std::move(text)), index_(source_), cell_(std::move(cell)),
      directive_(std::move(directive)) {
  compiled_ = compiler::compile(source_, cell_->target, kMaxDiagnostics, index_);
  index_.finish();
}

const DefaultRun& ProgramAnalysis::defaultRun() const {
  if (run_) return *run_;
  run_.emplace();
  if (!compiled_.image) return *run_;
  runtime::RunSpec spec;
  spec.image = std::make_shared<const vm::Image>(*compiled_.image);
  spec.cell = cell_->cell;
  spec.limits.maxSteps = kHintRunSteps;
  spec.limits.maxTime = kHintRunTime;
  spec.limits.maxStepsPerInstant = kHintRunSteps;
  // Times only: collision checks cost in proportion to each move's length,
  // which would make a hint's bounded run unbounded in work (and a
  // collision would end the run before the lines after it get a time).
  spec.collisions = runtime::CollisionMode::Off;
  run_->times.resize(spec.image->code.size());
  Timer timer(run_->times);
  runtime::Run run(std::move(spec));
  run.observe(timer);
  const vm::RunOutcome outcome = run.runToEnd();
  run_->outcome = outcomeText(outcome, run.clock());
  return *run_;
}

}  // namespace rs::lsp
