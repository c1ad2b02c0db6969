// Execution traces: one line per executed instruction, as text or as JSON
// Lines, and an event line for each input change (before its step's line,
// with its cause) and each collision (after it). Both print the
// instruction with the disassembler's own functions.
#pragma once

#include <ostream>

#include "runtime/run/run.h"
#include "vm/interpreter.h"

namespace rs::runtime {

enum class TraceFormat { Text, Json };

class TraceWriter final : public vm::StepObserver {
 public:
  /// Traces `run` (which must outlive the writer: pass the writer to its
  /// observe()). On a workcell each line also shows the tool centre point,
  /// and the steps that take or let go of an object say so.
  TraceWriter(std::ostream& out, TraceFormat format, const runtime::Run& run);
  bool afterStep(const vm::Interpreter& vm, std::uint32_t index) override;
  /// After the run: the collision that stopped it (a failed step is not
  /// traced as a step), as an event line.
  void finish();

 private:
  void textHeader(const vm::Interpreter& vm);
  void text(const vm::Interpreter& vm, std::uint32_t index);
  void json(const vm::Interpreter& vm, std::uint32_t index);
  std::ostream& out_;
  TraceFormat format_;
  const runtime::Run& run_;
  void collisionEvents();
  void inputEvents();
  void deviceEvent(const DeviceEvent& e);
  bool headerDone_ = false;
  std::size_t motorsWidth_ = 0;
  std::size_t collisionsShown_ = 0;
};

/// "closes on nothing (nearest: block (object 2), its centre 40 below the
/// tool centre point, which is 20 outside its box)": the trace's words for
/// a close that took nothing (runtime/run/empty_close.h words the rest).
std::string closesOnNothingText(const runtime::EmptyClose& e, const workcell::Workcell& cell);

/// "takes block (object 2)", "lets go of block (object 2)".
/// `number`: the object's number when the cell numbers its objects (0: its index + 1).
std::string graspText(const runtime::GraspEvent& event, const workcell::Workcell& cell, std::uint32_t number = 0);

/// "sensor eye ON", "feeder parts: block (object 5) at (-740, 500, 580)",
/// "sink done: takes block (object 5)": the trace's words for a device's event.
std::string deviceEventText(const DeviceEvent& e, const workcell::Workcell& cell);

/// "1.3....." : the digit of each line that is ON, '.' for OFF.
std::string lampText(std::uint8_t bits);

/// "(757, 0, 1397)": a point with at most 2 decimals per coordinate.
std::string pointText(const std::array<double, 3>& p);
/// The same rounded to 4 decimals, for JSON.
std::array<double, 3> roundedPoint(const std::array<double, 3>& p);

}  // namespace rs::runtime
