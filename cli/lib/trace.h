// Execution traces: one line per executed instruction, as text or as JSON
// Lines. Both print the instruction with the disassembler's own functions.
#pragma once

#include <ostream>

#include "vm/interpreter.h"

namespace rs::cli {

enum class TraceFormat { Text, Json };

class TraceWriter final : public vm::StepObserver {
 public:
  TraceWriter(std::ostream& out, TraceFormat format) : out_(out), format_(format) {}
  void afterStep(const vm::Interpreter& vm, std::uint32_t index) override;

 private:
  void text(const vm::Interpreter& vm, std::uint32_t index);
  void json(const vm::Interpreter& vm, std::uint32_t index);
  std::ostream& out_;
  TraceFormat format_;
  bool headerDone_ = false;
  std::size_t motorsWidth_ = 0;
};

/// "1.3....." : the digit of each line that is ON, '.' for OFF.
std::string lampText(std::uint8_t bits);

}  // namespace rs::cli
