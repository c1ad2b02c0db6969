// textDocument/hover in programs: an instruction's help from the opcode
// table (and, for one that acts on the machine, when it ran in the checked
// run, the run `robotsim check` makes: checked_run.h), a label's instruction, a point's encoder values and the tool
// centre point they put the robot's tool at (forward kinematics of the
// program's robot), a variable's writes and reads, an instruction number.
#include <fmt/format.h>

#include <cmath>

#include "base/number_text.h"
#include "base/seconds.h"
#include "model/workcell/tool_tracker.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "vm/interpreter.h"

namespace rs::lsp {

using base::formatNumber;

namespace {

Json markdown(std::string text, const Range& range) {
  return {{"contents", {{"kind", "markdown"}, {"value", std::move(text)}}}, {"range", toJson(range)}};
}

std::string motorList(const std::vector<vm::MotorSpec>& motors) {
  std::string out;
  for (const vm::MotorSpec& m : motors) {
    const char* kind = m.kind == vm::JointKind::Revolute ? "revolute" : m.kind == vm::JointKind::Prismatic ? "prismatic" : "gripper";
    out += fmt::format("{}- `{}` {}, {}..{}, {} units/s", out.empty() ? "" : "\n", m.letter, kind, m.min, m.max, m.speed);
    // Only when set, so a constant-speed motor reads as it always did.
    if (m.acceleration > 0) out += fmt::format(", {} units/s²", m.acceleration);
    if (m.actuation > 0) out += fmt::format(", {} s a move", base::formatSeconds(m.actuation));
  }
  return out;
}

std::string whenItRan(const ProgramContext& p, const IndexedInstruction& in) {
  if (!p.analysis.ok()) return {};
  const CheckedRun* run = p.analysis.run(kWaitForRun);
  if (!run) {
    p.analysis.noteAnsweredWithoutRun();
    return "\n\nThe checked run of this version is still being made.";
  }
  const std::uint32_t i = in.number - 1;
  if (run->end == CheckedRun::End::Abandoned || i >= run->times.size()) return {};
  const InstructionTimes& t = run->times[i];
  if (run->stoppedAt() == i)
    return fmt::format("\n\nIn the checked run it stops here at {}: {}.", formatSeconds(run->clock),
                       run->outcome->message);
  if (t.runs == 0)
    return run->end == CheckedRun::End::Finished && run->outcome->ok()
               ? "\n\nIn the checked run it never runs."
               : fmt::format("\n\nIn the checked run it never runs: the run {}.", run->summary);
  std::string out = fmt::format("\n\nIn the checked run: from {} to {} (takes {})", formatSeconds(t.start),
                                formatSeconds(t.end), formatSeconds(t.end - t.start));
  if (t.runs > 1) out += fmt::format(", the first of {} times", t.runs);
  return out + ".";
}

std::string instructionHover(const ProgramContext& p, const IndexedInstruction& in) {
  if (!in.known) return fmt::format("unknown instruction `{}`", in.mnemonic);
  const vm::OpInfo& op = vm::info(in.op);
  std::string out = fmt::format("**{}** — instruction {}\n\n`{}{}`: {}\n\n{}\n\nExample: `{}`", op.name, in.number,
                                op.name, vm::info(op.format).usage, op.meaning, op.detail, op.example);
  if (op.format == vm::Format::MotorVector)
    out += fmt::format("\n\nOne value per motor of {}:\n{}", p.analysis.cell().target.robotName,
                       motorList(p.analysis.cell().target.motors));
  if (op.flags & vm::kUsesMachine) out += whenItRan(p, in);
  return out;
}

std::string pointHover(const ProgramContext& p, const Occurrence& o) {
  const IndexedPoint* point = p.analysis.index().point(o.name);
  if (!point) return fmt::format("undefined point `{}`", o.name);
  const std::vector<vm::MotorSpec>& motors = p.analysis.cell().target.motors;
  std::string values;
  for (std::size_t i = 0; i < point->values.size(); ++i)
    values += fmt::format("{}{}={}", i ? " " : "", i < motors.size() ? std::string(1, motors[i].letter) : "?",
                          point->values[i]);
  std::string out = fmt::format("**point** `{}` (line {}): {}", point->name, point->pos.line, values);
  std::string pose;  // its words one space apart
  for (const char c : point->pose)
    if (c != ' ' && c != '\t') pose += c;
    else if (!pose.empty() && pose.back() != ' ') pose += ' ';
  if (!point->pose.empty())
    out = point->values.empty()
              ? fmt::format("**point** `{}` (line {}): the tool pose `{}`, not resolved (see its diagnostic)",
                            point->name, point->pos.line, pose)
              : fmt::format("**point** `{}` (line {}): {}, resolved from the tool pose `{}`", point->name,
                            point->pos.line, values, pose);
  const std::optional<workcell::PlacedRobot>& robot = p.analysis.cell().robot;
  if (robot && point->values.size() == motors.size() &&
      point->values.size() >= static_cast<std::size_t>(robot->robot.chain->encoderCount())) {
    workcell::ToolTracker tracker(*robot);
    const std::array<double, 3> tcp = tracker.tcp(point->values);
    out += fmt::format("\n\nTool centre point of {}: ({}, {}, {})", robot->robot.name, formatNumber(tcp[0]),
                       formatNumber(tcp[1]), formatNumber(tcp[2]));
  }
  return out;
}

std::string labelHover(const ProgramContext& p, const Occurrence& o) {
  const IndexedInstruction* in = p.analysis.index().labelled(o.name);
  if (!in) return fmt::format("undefined label `{}`", o.name);
  const bool sub = p.analysis.index().isSubroutine(in->label);
  return fmt::format("**{}** `{}`: instruction {} (line {}, `{}`)", sub ? "subroutine" : "label", in->label, in->number,
                     in->pos.line, instructionText(p, *in));
}

std::string variableHover(const ProgramContext& p, const Occurrence& o) {
  std::string writes, reads;
  for (const Occurrence* use : p.analysis.index().occurrencesOf(o)) {
    const IndexedInstruction* in = p.analysis.index().instructionOnLine(use->pos.line);
    const bool write = in && in->known && (vm::info(in->op).flags & vm::kWritesVariable);
    std::string& list = write ? writes : reads;
    list += fmt::format("{}{}", list.empty() ? "" : ", ", use->pos.line);
  }
  return fmt::format("**variable** `{}`: a 32-bit integer, 0 at the start\n\nwritten on line(s) {}; read on line(s) {}",
                     o.name, writes.empty() ? "none" : writes, reads.empty() ? "none" : reads);
}

}  // namespace

Json hover(const ProgramContext& p, Position at) {
  const diag::Pos pos = p.doc.toPos(at, p.enc);
  if (const auto& d = p.analysis.directive()) {
    const Range r = p.doc.rangeOf(d->pos, d->name.size(), p.enc);
    if (at.line == r.start.line && at.character >= r.start.character && at.character <= r.end.character)
      if (std::string table = cellTableHover(p); !table.empty()) return markdown(std::move(table), r);
  }
  if (const Occurrence* o = p.analysis.index().occurrenceAt(pos)) {
    const Range range = rangeOf(p, *o);
    switch (o->kind) {
      case NameKind::Label: return markdown(labelHover(p, *o), range);
      case NameKind::Point: return markdown(pointHover(p, *o), range);
      case NameKind::Variable: return markdown(variableHover(p, *o), range);
      case NameKind::Instruction: {
        const IndexedInstruction* in = p.analysis.index().instructionNumbered(o->instruction);
        if (!in) return markdown(fmt::format("instruction {} does not exist", o->instruction), range);
        return markdown(fmt::format("instruction {}: line {}, `{}`", in->number, in->pos.line,
                                    instructionText(p, *in)),
                        range);
      }
    }
  }
  const IndexedInstruction* in = p.analysis.index().instructionOnLine(pos.line);
  if (in && in->inputPos.line == pos.line && pos.col >= in->inputPos.col &&
      pos.col <= in->inputPos.col + in->inputLength)
    return markdown(inputHover(p.analysis, in->input), p.doc.rangeOf(in->inputPos, in->inputLength, p.enc));
  if (in && pos.col >= in->pos.col && pos.col <= in->pos.col + in->mnemonic.size())
    return markdown(instructionHover(p, *in), p.doc.rangeOf(in->pos, in->mnemonic.size(), p.enc));
  return nullptr;
}

}  // namespace rs::lsp
