#include "compiler/codegen.h"

namespace rs::compiler {

namespace {

std::int32_t addConstants(vm::Image& image, const std::vector<Value>& values) {
  const auto first = static_cast<std::int32_t>(image.constants.size());
  for (const Value& v : values) image.constants.push_back(static_cast<std::int32_t>(v.number));
  return first;
}

vm::Instr encode(const Instruction& in, const Resolution& res, vm::Image& image) {
  const std::size_t i = in.number - 1;
  vm::Instr out;
  out.op = in.op;
  switch (vm::info(in.op).format) {
    case vm::Format::None: break;
    case vm::Format::MotorVector:
      out.b = static_cast<std::uint16_t>(in.values.size());
      out.c = addConstants(image, in.values);
      break;
    case vm::Format::Point: out.b = res.slot[i]; break;
    case vm::Format::Target: out.d = static_cast<std::int32_t>(res.target[i]); break;
    case vm::Format::InputJump:
      out.a = static_cast<std::uint8_t>(in.io.number);
      out.b = in.on;
      out.d = static_cast<std::int32_t>(res.target[i]);
      break;
    case vm::Format::Output:
    case vm::Format::Input:
      out.a = static_cast<std::uint8_t>(in.io.number);
      out.b = in.on;
      break;
    case vm::Format::VarCompare:
      out.a = static_cast<std::uint8_t>(in.compare);
      out.b = res.slot[i];
      out.c = static_cast<std::int32_t>(in.value.number);
      out.d = static_cast<std::int32_t>(res.target[i]);
      break;
    case vm::Format::VarValue:
      out.b = res.slot[i];
      out.c = static_cast<std::int32_t>(in.value.number);
      break;
    case vm::Format::Triple: out.c = addConstants(image, in.values); break;
    case vm::Format::Millis: out.c = static_cast<std::int32_t>(in.value.number); break;
  }
  return out;
}

}  // namespace

vm::Image generate(const Program& program, const Resolution& resolution, const Target& target,
                   std::string sourceName) {
  vm::Image image;
  image.sourceName = std::move(sourceName);
  image.robotName = target.robotName;
  image.callDepthLimit = target.callDepthLimit;
  image.motors = target.motors;
  image.code.reserve(program.instructions.size());
  image.lines.reserve(program.instructions.size());
  image.columns.reserve(program.instructions.size());
  for (const Instruction& in : program.instructions) {
    image.code.push_back(encode(in, resolution, image));
    image.lines.push_back(in.pos.line);
    image.columns.push_back(in.pos.col);
    if (!in.label.empty()) image.labels.push_back({in.number - 1, std::string(in.label)});
  }
  for (std::string_view v : resolution.variables) image.variables.emplace_back(v);
  for (const PointDef& p : program.points) {
    vm::Point point{std::string(p.name), {}};
    for (const Value& v : p.values) point.values.push_back(static_cast<std::int32_t>(v.number));
    image.points.push_back(std::move(point));
  }
  return image;
}

}  // namespace rs::compiler
