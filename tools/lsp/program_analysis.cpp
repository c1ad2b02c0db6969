#include "tools/lsp/program_analysis.h"

#include <fmt/format.h>

namespace rs::lsp {

std::string formatSeconds(vm::Micros t) {
  std::string s = fmt::format("{}.{:06}", t / 1'000'000, t % 1'000'000);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s + " s";
}

ProgramAnalysis::ProgramAnalysis(std::string path, std::string text, std::shared_ptr<const CellContext> cell,
                                 std::optional<launch::CellDirective> directive, StimuliBeside stimuli)
    : byteOrderMark_(diag::withoutByteOrderMark(text).size() != text.size()),
      source_(std::move(path), std::move(text)), index_(source_), cell_(std::move(cell)),
      directive_(std::move(directive)), stimuli_(std::move(stimuli)) {
  compiled_ = compiler::compile(source_, cell_->target, kMaxDiagnostics, index_);
  index_.finish();
  if (compiled_.image) {
    image_ = std::make_shared<const vm::Image>(std::move(*compiled_.image));
    compiled_.image.reset();
  }
}

Range ProgramAnalysis::wordAt(diag::Pos pos, Encoding enc) const {
  if (pos.line == 0 || pos.line > source_.lineCount()) return {};
  // The source dropped a byte-order mark: the editor's line 0 still has it.
  const std::uint32_t lead = pos.line == 1 && byteOrderMark_ ? (enc == Encoding::Utf8 ? 3 : 1) : 0;
  return wordRange(source_.line(pos.line), pos.line - 1, pos.col, lead, enc);
}

bool ProgramAnalysis::askForRun() const {
  const std::lock_guard<std::mutex> lock(runMutex_);
  if (runState_ != RunState::None) return false;
  runState_ = RunState::Queued;
  return true;
}

void ProgramAnalysis::runMade(CheckedRun run) const {
  {
    const std::lock_guard<std::mutex> lock(runMutex_);
    run_ = std::move(run);
    runState_ = RunState::Made;
  }
  runMadeSignal_.notify_all();
}

const CheckedRun* ProgramAnalysis::run(std::chrono::milliseconds wait) const {
  std::unique_lock<std::mutex> lock(runMutex_);
  if (runState_ == RunState::Queued && wait.count() > 0)
    runMadeSignal_.wait_for(lock, wait, [this] { return runState_ == RunState::Made; });
  return runState_ == RunState::Made ? &*run_ : nullptr;
}

}  // namespace rs::lsp
