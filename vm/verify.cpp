#include "vm/verify.h"

#include <fmt/format.h>

#include "vm/motor_range.h"

namespace rs::vm {

namespace {

constexpr std::size_t kMaxMotors = 26;

bool validState(std::uint16_t state) { return state <= 1; }

std::string checkMotors(const Image& image) {
  if (image.motors.empty() || image.motors.size() > kMaxMotors)
    return fmt::format("motor table has {} motors (1..{} allowed)", image.motors.size(), kMaxMotors);
  for (std::size_t i = 0; i < image.motors.size(); ++i) {
    const MotorSpec& m = image.motors[i];
    if (m.letter < 'A' || m.letter > 'Z') return fmt::format("motor {} has no letter A..Z", i + 1);
    for (std::size_t j = 0; j < i; ++j)
      if (image.motors[j].letter == m.letter) return fmt::format("motor letter {} appears twice", m.letter);
    if (m.kind > JointKind::Gripper) return fmt::format("motor {} has an unknown joint kind", m.letter);
    if (m.min > m.max) return fmt::format("motor {} range {}..{} is empty", m.letter, m.min, m.max);
    if (m.min > 0 || m.max < 0)
      return fmt::format("motor {} range {}..{} does not include 0, where every motor starts", m.letter, m.min, m.max);
    if (m.speed <= 0) return fmt::format("motor {} speed {} is not positive", m.letter, m.speed);
    if (!(m.precision > 0.0 && m.precision < 1e9))
      return fmt::format("motor {} precision is not a positive number", m.letter);
    if (m.acceleration < 0 || m.acceleration > kMaxAcceleration)
      return fmt::format("motor {} acceleration {} is outside 0..{}", m.letter, m.acceleration, kMaxAcceleration);
    if (m.acceleration > 0 && m.speed / m.acceleration >= kMaxSecondsToSpeed)
      return fmt::format("motor {} takes {} s or more to reach its speed", m.letter, kMaxSecondsToSpeed);
    if (m.actuation < 0 || m.actuation > kMaxActuation)
      return fmt::format("motor {} actuation time {} us is outside 0..{}", m.letter, m.actuation, kMaxActuation);
    if (m.actuation > 0 && m.kind != JointKind::Gripper)
      return fmt::format("motor {} has an actuation time but is not a gripper", m.letter);
  }
  return {};
}

// Checks one instruction's operands by its format: every field the format
// uses is in range, every field it does not use is zero.
std::string checkOperands(const Image& image, const Instr& in) {
  const std::size_t n = image.code.size();
  const auto target = [&](std::int32_t t) { return t >= 0 && static_cast<std::size_t>(t) < n; };
  const auto constants = [&](std::int32_t first, std::size_t count) {
    return first >= 0 && static_cast<std::size_t>(first) + count <= image.constants.size();
  };
  switch (info(in.op).format) {
    case Format::None:
      if (in.a || in.b || in.c || in.d) return "unused operand fields are not zero";
      return {};
    case Format::MotorVector:
      if (in.a || in.d) return "unused operand fields are not zero";
      if (in.b != image.motors.size())
        return fmt::format("moves {} motors, the image has {}", in.b, image.motors.size());
      if (!constants(in.c, in.b)) return fmt::format("constant index {} out of bounds", in.c);
      if (!has(in.op, kRelative))
        for (std::size_t i = 0; i < in.b; ++i)
          if (!inRange(image.motors[i], image.constants[in.c + i]))
            return fmt::format("motor {} target {} outside its range", image.motors[i].letter,
                               image.constants[in.c + i]);
      return {};
    case Format::Point:
      if (in.c || in.d) return "unused operand fields are not zero";
      if (in.a > kPointKeepsGripper) return fmt::format("point flags {} unknown", in.a);
      if (in.b >= image.points.size()) return fmt::format("point index {} out of bounds", in.b);
      return {};
    case Format::Target:
      if (in.a || in.b || in.c) return "unused operand fields are not zero";
      if (!target(in.d)) return fmt::format("jump target {} outside the code", in.d);
      return {};
    case Format::InputJump:
      if (in.c) return "unused operand fields are not zero";
      if (!isIoLine(in.a)) return fmt::format("input {} outside 1..{}", in.a, kIoCount);
      if (!validState(in.b)) return fmt::format("state {} is neither ON nor OFF", in.b);
      if (!target(in.d)) return fmt::format("jump target {} outside the code", in.d);
      return {};
    case Format::Output:
    case Format::Input:
      if (in.c || in.d) return "unused operand fields are not zero";
      if (!isIoLine(in.a)) return fmt::format("line {} outside 1..{}", in.a, kIoCount);
      if (!validState(in.b)) return fmt::format("state {} is neither ON nor OFF", in.b);
      return {};
    case Format::VarCompare:
      if (in.a > 2) return fmt::format("comparison {} unknown", in.a);
      if (in.b >= image.variables.size()) return fmt::format("variable slot {} out of bounds", in.b);
      if (!target(in.d)) return fmt::format("jump target {} outside the code", in.d);
      return {};
    case Format::VarValue:
      if (in.a || in.d) return "unused operand fields are not zero";
      if (in.b >= image.variables.size()) return fmt::format("variable slot {} out of bounds", in.b);
      return {};
    case Format::Triple:
      if (in.a || in.b || in.d) return "unused operand fields are not zero";
      if (!constants(in.c, 3)) return fmt::format("constant index {} out of bounds", in.c);
      return {};
    case Format::Millis:
      if (in.a || in.b || in.d) return "unused operand fields are not zero";
      if (in.c < 0 || in.c > kMaxDelayMillis) return fmt::format("delay {} ms out of range", in.c);
      return {};
    case Format::Distance:
      if (in.a || in.b || in.d) return "unused operand fields are not zero";
      if (in.c < 1 || in.c > kMaxToolDistance) return fmt::format("distance {} outside 1..{}", in.c, kMaxToolDistance);
      return {};
  }
  return "unknown operand format";
}

std::string checkTables(const Image& image) {
  if (image.code.empty()) return "the image has no code";
  if (image.lines.size() != image.code.size() || image.columns.size() != image.code.size())
    return fmt::format("line table has {} entries for {} instructions", image.lines.size(), image.code.size());
  for (std::size_t i = 0; i < image.code.size(); ++i)
    if (image.lines[i] == 0 || image.columns[i] == 0) return fmt::format("instruction {} has no source position", i + 1);
  if (image.callDepthLimit < 1 || image.callDepthLimit > kMaxCallDepth)
    return fmt::format("call depth limit {} outside 1..{}", image.callDepthLimit, kMaxCallDepth);
  for (const Point& p : image.points) {
    if (p.values.size() != image.motors.size())
      return fmt::format("point {} has {} values for {} motors", p.name, p.values.size(), image.motors.size());
    for (std::size_t i = 0; i < p.values.size(); ++i)
      if (!inRange(image.motors[i], p.values[i]))
        return fmt::format("point {} value {} outside motor {} range", p.name, p.values[i], image.motors[i].letter);
  }
  for (std::size_t i = 0; i < image.labels.size(); ++i) {
    if (image.labels[i].index >= image.code.size()) return fmt::format("label {} outside the code", image.labelName(i));
    if (i > 0 && image.labels[i].index < image.labels[i - 1].index) return "labels are not sorted";
  }
  return {};
}

}  // namespace

VerifyError verify(const Image& image) {
  if (std::string e = checkMotors(image); !e.empty()) return {e};
  if (std::string e = checkTables(image); !e.empty()) return {e};
  for (std::size_t i = 0; i < image.code.size(); ++i) {
    const Instr& in = image.code[i];
    if (static_cast<std::size_t>(in.op) >= kOpCount)
      return {fmt::format("instruction {}: unknown opcode {}", i + 1, static_cast<int>(in.op))};
    if (std::string e = checkOperands(image, in); !e.empty())
      return {fmt::format("instruction {} ({}): {}", i + 1, info(in.op).name, e)};
  }
  return {};
}

}  // namespace rs::vm
