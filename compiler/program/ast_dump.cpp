// `robotsim ast`: the AST as an outline a student can read next to the
// source: one line per instruction with its typed operands.
#include <fmt/format.h>

#include "compiler/program/ast_builder.h"
#include "compiler/program/compiler.h"
#include "compiler/program/parse_tree.h"

namespace rs::compiler {

namespace {

std::string pos(diag::Pos p) { return fmt::format("{}:{}", p.line, p.col); }

std::string valueList(const std::vector<Value>& values) {
  std::string s;
  for (const Value& v : values) s += fmt::format("{}{}", s.empty() ? "" : ", ", v.number);
  return "[" + s + "]";
}

std::string jumpText(const JumpRef& t) {
  return t.label.empty() ? fmt::format("line {}", t.number) : fmt::format("label {}", t.label);
}

std::string operands(const Instruction& in) {
  const char* state = in.on ? "ON" : "OFF";
  switch (vm::info(in.op).format) {
    case vm::Format::None: return {};
    case vm::Format::MotorVector: return fmt::format(" values={}", valueList(in.values));
    case vm::Format::Point: return fmt::format(" point={}", in.name);
    case vm::Format::Target: return fmt::format(" target=({})", jumpText(in.target));
    case vm::Format::InputJump:
      return fmt::format(" input={} state={} target=({})", in.io.number, state, jumpText(in.target));
    case vm::Format::Output: return fmt::format(" output={} state={}", in.io.number, state);
    case vm::Format::Input: return fmt::format(" input={} state={}", in.io.number, state);
    case vm::Format::VarCompare:
      return fmt::format(" variable={} compare='{}' value={} target=({})", in.name,
                         vm::kCompareSymbols[static_cast<std::size_t>(in.compare)], in.value.number,
                         jumpText(in.target));
    case vm::Format::VarValue: return fmt::format(" variable={} value={}", in.name, in.value.number);
    case vm::Format::Triple: return fmt::format(" xyz={}", valueList(in.values));
    case vm::Format::Millis: return fmt::format(" milliseconds={}", in.value.number);
    case vm::Format::Distance: return fmt::format(" distance={}", in.value.number);
  }
  return {};
}

}  // namespace

std::string dumpAst(const diag::SourceFile& source, const Target& target, bool parseTree, diag::Diagnostics& d) {
  if (auto bad = checkEncoding(source)) {
    d.error(bad->pos, std::move(bad->message), bad->code);
    return {};
  }
  ParseTree tree(source, d);
  std::string out;
  if (parseTree) out += "parse tree:\n" + tree.toStringTree() + "\n\n";
  const Program program = buildAst(tree, target.motors, d);
  out += fmt::format("Program {} ({} instructions, {} points)\n", source.name(), program.instructions.size(),
                     program.points.size());
  for (const Instruction& in : program.instructions) {
    const std::string label = in.label.empty() ? "" : fmt::format(" label={}", in.label);
    const std::string_view name = in.known ? vm::info(in.op).name : std::string_view("<unknown>");
    out += fmt::format("  Instruction #{} @{} {}{}{}\n", in.number, pos(in.pos), name, label, operands(in));
  }
  if (program.pointsHeader.line != 0) {
    out += fmt::format("  Points @{}\n", pos(program.pointsHeader));
    for (const PointDef& p : program.points)
      out += fmt::format("    Point {} @{} values={}\n", p.name, pos(p.pos), valueList(p.values));
  }
  return out;
}

}  // namespace rs::compiler
