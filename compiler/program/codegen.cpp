#include "compiler/program/codegen.h"

namespace rs::compiler {

namespace {

std::int32_t addConstants(std::vector<std::int32_t>& constants, const std::vector<Value>& values) {
  const auto first = static_cast<std::int32_t>(constants.size());
  for (const Value& v : values) constants.push_back(static_cast<std::int32_t>(v.number));
  return first;
}

}  // namespace

vm::Instr encode(const Instruction& in, std::uint16_t slot, std::uint32_t target,
                 std::vector<std::int32_t>& constants) {
  vm::Instr out;
  out.op = in.op;
  switch (vm::info(in.op).format) {
    case vm::Format::None: break;
    case vm::Format::MotorVector:
      out.b = static_cast<std::uint16_t>(in.values.size());
      out.c = addConstants(constants, in.values);
      break;
    case vm::Format::Point: out.b = slot; break;
    case vm::Format::Target: out.d = static_cast<std::int32_t>(target); break;
    case vm::Format::InputJump:
      out.a = static_cast<std::uint8_t>(in.io.number);
      out.b = in.on;
      out.d = static_cast<std::int32_t>(target);
      break;
    case vm::Format::Output:
    case vm::Format::Input:
      out.a = static_cast<std::uint8_t>(in.io.number);
      out.b = in.on;
      break;
    case vm::Format::VarCompare:
      out.a = static_cast<std::uint8_t>(in.compare);
      out.b = slot;
      out.c = static_cast<std::int32_t>(in.value.number);
      out.d = static_cast<std::int32_t>(target);
      break;
    case vm::Format::VarValue:
      out.b = slot;
      out.c = static_cast<std::int32_t>(in.value.number);
      break;
    case vm::Format::Triple: out.c = addConstants(constants, in.values); break;
    case vm::Format::Millis:
    case vm::Format::Distance: out.c = static_cast<std::int32_t>(in.value.number); break;
  }
  return out;
}

}  // namespace rs::compiler
