// Execution traces: one line per executed instruction, as text or as JSON
// Lines. Both print the instruction with the disassembler's own functions.
#pragma once

#include <ostream>

#include "runtime/grasp_observer.h"
#include "model/workcell/tool_tracker.h"
#include "vm/interpreter.h"

namespace rs::cli {

enum class TraceFormat { Text, Json };

class TraceWriter final : public vm::StepObserver {
 public:
  /// With a tool tracker, each line also shows the tool centre point; with
  /// a grasp observer (which must call this writer after itself), the steps
  /// that take or let go of an object say so.
  TraceWriter(std::ostream& out, TraceFormat format, workcell::ToolTracker* tool = nullptr,
              const runtime::GraspObserver* grasp = nullptr, const workcell::Workcell* cell = nullptr)
      : out_(out), format_(format), tool_(tool), grasp_(grasp), cell_(cell) {}
  void afterStep(const vm::Interpreter& vm, std::uint32_t index) override;

 private:
  void text(const vm::Interpreter& vm, std::uint32_t index);
  void json(const vm::Interpreter& vm, std::uint32_t index);
  std::ostream& out_;
  TraceFormat format_;
  workcell::ToolTracker* tool_;
  const runtime::GraspObserver* grasp_;
  const workcell::Workcell* cell_;
  bool headerDone_ = false;
  std::size_t motorsWidth_ = 0;
};

/// "takes block (object 2)", "lets go of block (object 2)".
std::string graspText(const workcell::GraspChange& change, const workcell::Workcell& cell);

/// "1.3....." : the digit of each line that is ON, '.' for OFF.
std::string lampText(std::uint8_t bits);

/// "(757, 0, 1397)": a point with at most 2 decimals per coordinate.
std::string pointText(const std::array<double, 3>& p);
/// The same rounded to 4 decimals, for JSON.
std::array<double, 3> roundedPoint(const std::array<double, 3>& p);

}  // namespace rs::cli
