#include "vm/disasm.h"

#include <algorithm>
#include <fmt/format.h>

#include "base/text.h"

namespace rs::vm {

namespace {

std::string_view onOff(std::uint16_t state) { return state ? "ON" : "OFF"; }

std::string values(const std::int32_t* first, std::size_t count) {
  std::string s;
  for (std::size_t i = 0; i < count; ++i) s += fmt::format("{}{}", i ? " " : "", first[i]);
  return s;
}

std::string millisText(std::int32_t ms) {
  std::string s = fmt::format("{}.{:03}", ms / 1000, ms % 1000);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

using base::safeText;  // every name comes from the image: printed escaped

// Jump targets are written as 1-based instruction numbers, as in programs.
std::string operands(const Image& im, const Instr& in) {
  const std::int32_t* k = im.constants.data();
  switch (info(in.op).format) {
    case Format::None: return {};
    case Format::MotorVector: return values(k + in.c, in.b);
    case Format::Point: return safeText(im.points[in.b].name);
    case Format::Target: return fmt::format("{}", in.d + 1);
    case Format::InputJump: return fmt::format("{} {} {}", in.a, onOff(in.b), in.d + 1);
    case Format::Output:
    case Format::Input: return fmt::format("{} {}", in.a, onOff(in.b));
    case Format::VarCompare:
      return fmt::format("{} {} {} {}", safeText(im.variables[in.b]), kCompareSymbols[in.a], in.c, in.d + 1);
    case Format::VarValue: return fmt::format("{} {}", safeText(im.variables[in.b]), in.c);
    case Format::Triple: return values(k + in.c, 3);
    case Format::Millis: return millisText(in.c);
    case Format::Distance: return fmt::format("{}", in.c);
  }
  return {};
}

}  // namespace

std::string_view labelAt(const Image& image, std::uint32_t index) {
  const auto it = std::lower_bound(image.labels.begin(), image.labels.end(), index,
                                   [](const Label& l, std::uint32_t i) { return l.index < i; });
  return it != image.labels.end() && it->index == index ? image.labelName(*it) : std::string_view();
}

std::string instructionText(const Image& image, std::uint32_t index) {
  const Instr& in = image.code[index];
  const std::string ops = operands(image, in);
  return ops.empty() ? std::string(info(in.op).name) : fmt::format("{:<8}{}", info(in.op).name, ops);
}

std::string instructionComment(const Image& image, std::uint32_t index) {
  const Instr& in = image.code[index];
  if (info(in.op).flags & kJumps) {
    const auto t = static_cast<std::uint32_t>(in.d);
    const std::string_view label = labelAt(image, t);
    return fmt::format("-> {} (line {}{}{})", t + 1, image.lines[t], label.empty() ? "" : ", ", safeText(label));
  }
  if (in.op == Op::MoveP) {
    const Point& p = image.points[in.b];
    // A motor the move leaves as it is (the gripper, for a pose without GRIP) is written "=".
    std::string targets;
    for (std::size_t m = 0; m < p.values.size(); ++m)
      targets += fmt::format("{}{}", m ? " " : "",
                             (in.a & kPointKeepsGripper) && image.motors[m].kind == JointKind::Gripper
                                 ? std::string("=")
                                 : std::to_string(p.values[m]));
    return fmt::format("{} = {}{}", safeText(p.name), targets,
                       p.origin.empty() ? "" : fmt::format(" (from {})", safeText(p.origin)));
  }
  return {};
}

std::string listingRow(const Image& image, std::uint32_t i) {
  const std::uint32_t line = image.lines[i];
  const std::string lineText = (i > 0 && line == image.lines[i - 1]) ? "   |" : fmt::format("{:4}", line);
  std::string row = fmt::format("  {:04}  {}  {:<8}  {}", i + 1, lineText, safeText(labelAt(image, i)),
                                instructionText(image, i));
  if (std::string c = instructionComment(image, i); !c.empty()) row = fmt::format("{:<62} ; {}", row, c);
  return row;
}

std::string disassemble(const Image& image) {
  std::string out = fmt::format("; {} ({} instructions, {} constants, {} variables, {} points)\n",
                                image.sourceName.empty() ? "<image>" : safeText(image.sourceName), image.code.size(),
                                image.constants.size(), image.variables.size(), image.points.size());
  out += fmt::format("; robot {}: motors", image.robotName.empty() ? "-" : safeText(image.robotName));
  for (const MotorSpec& m : image.motors) out += fmt::format(" {}[{}..{}]", m.letter, m.min, m.max);
  out += "\n;\n; instr  line  label     instruction                          ; refers to\n";
  for (std::uint32_t i = 0; i < image.code.size(); ++i) {
    out += listingRow(image, i);
    out += '\n';
  }
  if (!image.points.empty()) {
    out += ";\n; points\n";
    for (const Point& p : image.points)
      out += p.origin.empty()
                 ? fmt::format(";   {:<10} {}\n", safeText(p.name), values(p.values.data(), p.values.size()))
                 : fmt::format(";   {:<10} {:<24} ; from {}\n", safeText(p.name),
                               values(p.values.data(), p.values.size()), safeText(p.origin));
  }
  if (!image.variables.empty()) {
    out += ";\n; variables\n";
    for (std::size_t i = 0; i < image.variables.size(); ++i)
      out += fmt::format(";   slot {}  {}\n", i, safeText(image.variables[i]));
  }
  return out;
}

}  // namespace rs::vm
