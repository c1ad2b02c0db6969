#include "launch/stimuli_robots.h"

#include <fmt/format.h>

#include <optional>
#include <string>

#include "base/text.h"
#include "launch/robot_choice.h"

namespace rs::launch {
namespace {

class Placer {
 public:
  Placer(const workcell::Workcell* cell, std::string_view file, std::vector<diag::Diagnostic>& diags,
         const std::vector<bool>* running)
      : cell_(cell), file_(file), diags_(diags), running_(running) {}

  // The robot a label names: the driven one (true), another (false), or none
  // (nullopt, an error reported at the label's place).
  std::optional<bool> isDriven(const std::string& label, std::uint32_t line, std::uint32_t column,
                               std::string_view what) {
    if (label.empty()) return true;
    const std::string shown = base::safeText(label);
    if (!cell_) {
      error(line, column, fmt::format("this {} names robot `{}`, but the run has no cell", what, shown),
            "name the cell (--cell CELL or a `; cell:` line), or drop the label: a run without a cell has one robot");
      return std::nullopt;
    }
    const std::size_t robot = cell_->robotLabeled(label);
    if (robot == workcell::kNoIndex) {
      error(line, column,
            fmt::format("this {} names robot `{}`, but workcell {} has no robot labelled so", what, shown,
                        base::safeText(cell_->name)),
            fmt::format("the cell's robots are {} (a ROBOT line's AS LABEL, or the description's name)",
                        robotLabelsOf(*cell_)));
      return std::nullopt;
    }
    if (running_ ? robot < running_->size() && (*running_)[robot] : robot == cell_->drivenRobotIndex()) return true;
    diags_.push_back({fileOf(line), posOf(line, column), diag::Severity::Warning,
                      fmt::format("this {} is for robot `{}`, which runs no program in this run: nothing reads it",
                                  what, shown),
                      "stimulus-for-idle-robot", fmt::format("this run drives {}", runningLabels())});
    return false;
  }

  bool ok() const { return ok_; }

 private:
  std::string runningLabels() const {
    if (!running_) return fmt::format("`{}`", base::safeText(cell_->drivenRobot()->labelOf()));
    std::string out;
    for (std::size_t r = 0; r < running_->size() && r < cell_->robots.size(); ++r)
      if ((*running_)[r]) out += fmt::format("{}`{}`", out.empty() ? "" : ", ", base::safeText(cell_->robots[r].labelOf()));
    return out;
  }
  std::string fileOf(std::uint32_t line) const { return line ? std::string(file_) : std::string("--input"); }
  static diag::Pos posOf(std::uint32_t line, std::uint32_t column) {
    return line ? diag::Pos{line, column ? column : 1} : diag::Pos{};
  }
  void error(std::uint32_t line, std::uint32_t column, std::string message, std::string hint) {
    ok_ = false;
    diags_.push_back({fileOf(line), posOf(line, column), diag::Severity::Error, std::move(message), "unknown-robot",
                      std::move(hint)});
  }

  const workcell::Workcell* cell_;
  std::string_view file_;
  std::vector<diag::Diagnostic>& diags_;
  const std::vector<bool>* running_;
  bool ok_ = true;
};

}  // namespace

bool placeStimuliOnRobots(const workcell::Workcell* cell, std::string_view stimuliFile, stimuli::Stimuli& stimuli,
                          std::vector<diag::Diagnostic>& diags, const std::vector<bool>* running) {
  Placer placer(cell, stimuliFile, diags, running);
  std::vector<stimuli::InputChange> changes;
  for (stimuli::InputChange& c : stimuli.changes) {
    const std::optional<bool> driven = placer.isDriven(c.robot, c.line, c.robotColumn, "stimulus");
    if (driven && *driven) changes.push_back(std::move(c));
  }
  std::vector<stimuli::ReactiveRule> rules;
  for (stimuli::ReactiveRule& r : stimuli.rules) {
    const std::optional<bool> output = placer.isDriven(r.outputRobot, r.line, r.outputRobotColumn, "rule's output");
    const std::optional<bool> input = placer.isDriven(r.inputRobot, r.line, r.inputRobotColumn, "rule's input");
    if (output && input && *output && *input) rules.push_back(std::move(r));
  }
  stimuli.changes = std::move(changes);
  stimuli.rules = std::move(rules);
  return placer.ok();
}

}  // namespace rs::launch
