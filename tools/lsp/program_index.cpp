#include "tools/lsp/program_index.h"

#include <algorithm>

#include "base/ascii.h"

namespace rs::lsp {

ProgramIndex::ProgramIndex(const diag::SourceFile& source) : source_(source) {}

std::uint32_t ProgramIndex::lengthAt(diag::Pos pos) const {
  const std::string_view text = source_.text();
  const std::size_t begin = source_.offsetOf(pos);
  std::size_t end = begin;
  while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != '\r' && text[end] != '\n' &&
         text[end] != ';')
    ++end;
  return static_cast<std::uint32_t>(end - begin);
}

void ProgramIndex::add(NameKind kind, bool definition, diag::Pos pos, std::string_view name, std::uint32_t instruction) {
  occurrences_.push_back({kind, definition, pos, static_cast<std::uint32_t>(name.size()), name, instruction});
}

void ProgramIndex::instruction(const compiler::Instruction& in) {
  IndexedInstruction& ix = instructions_.emplace_back();
  ix.number = in.number;
  ix.pos = in.pos;
  ix.op = in.op;
  ix.known = in.known;
  ix.label = in.label;
  ix.labelPos = in.labelPos;
  const std::string_view text = source_.text();
  const std::size_t at = source_.offsetOf(in.pos);
  ix.mnemonic = text.substr(at, lengthAt(in.pos));
  if (!in.label.empty()) add(NameKind::Label, true, in.labelPos, in.label);
  if (!in.known) return;
  const vm::Format f = vm::info(in.op).format;
  if ((f == vm::Format::Input || f == vm::Format::InputJump) && in.io.pos.line != 0) {
    ix.input = in.io.number;
    ix.inputPos = in.io.pos;
    ix.inputLength = lengthAt(in.io.pos);
    ix.inputOn = in.on;
  }
  const bool named = f == vm::Format::Point || f == vm::Format::VarCompare || f == vm::Format::VarValue;
  if (named && !in.name.empty()) {
    ix.name = in.name;
    add(f == vm::Format::Point ? NameKind::Point : NameKind::Variable, false, in.namePos, in.name);
  }
  if ((vm::info(in.op).flags & vm::kJumps) && in.target.pos.line != 0) {
    if (!in.target.label.empty()) {
      ix.targetLabel = in.target.label;
      add(NameKind::Label, false, in.target.pos, in.target.label);
    } else if (in.target.number != 0) {
      ix.targetNumber = in.target.number;
      const std::size_t begin = source_.offsetOf(in.target.pos);
      add(NameKind::Instruction, false, in.target.pos, text.substr(begin, lengthAt(in.target.pos)), in.target.number);
    }
  }
}

void ProgramIndex::point(const compiler::PointDef& p) {
  IndexedPoint& ip = points_.emplace_back();
  ip.name = p.name;
  ip.pos = p.pos;
  for (const compiler::Value& v : p.values) ip.values.push_back(static_cast<std::int32_t>(v.number));
  if (p.isPose) ip.pose = p.pose.text;
  add(NameKind::Point, true, p.pos, p.name);
}

const Occurrence* ProgramIndex::occurrenceAt(diag::Pos pos) const {
  // The last occurrence starting at or before pos.
  const auto it = std::upper_bound(occurrences_.begin(), occurrences_.end(), pos,
                                   [](diag::Pos p, const Occurrence& o) { return before(p, o.pos); });
  if (it == occurrences_.begin()) return nullptr;
  const Occurrence& o = *std::prev(it);
  if (o.pos.line != pos.line || pos.col > o.pos.col + o.length) return nullptr;
  return &o;
}

std::vector<const Occurrence*> ProgramIndex::occurrencesOf(const Occurrence& o) const {
  std::vector<const Occurrence*> out;
  for (const Occurrence& other : occurrences_) {
    if (other.kind != o.kind) continue;
    const bool same = o.kind == NameKind::Instruction ? other.instruction == o.instruction
                                                      : base::sameName(other.name, o.name);
    if (same) out.push_back(&other);
  }
  return out;
}

const Occurrence* ProgramIndex::definitionOf(const Occurrence& o) const {
  if (o.kind == NameKind::Instruction) return nullptr;
  for (const Occurrence& other : occurrences_) {
    if (other.kind != o.kind || !base::sameName(other.name, o.name)) continue;
    // A variable has no definition: its first write stands for one.
    if (other.definition) return &other;
    if (o.kind == NameKind::Variable) {
      const IndexedInstruction* in = instructionOnLine(other.pos.line);
      if (in && in->known && (vm::info(in->op).flags & vm::kWritesVariable)) return &other;
    }
  }
  return nullptr;
}

const IndexedInstruction* ProgramIndex::instructionOnLine(std::uint32_t line) const {
  const auto it = std::lower_bound(instructions_.begin(), instructions_.end(), line,
                                   [](const IndexedInstruction& in, std::uint32_t l) { return in.pos.line < l; });
  return it != instructions_.end() && it->pos.line == line ? &*it : nullptr;
}

const IndexedInstruction* ProgramIndex::instructionNumbered(std::uint32_t number) const {
  return number >= 1 && number <= instructions_.size() ? &instructions_[number - 1] : nullptr;
}

const IndexedPoint* ProgramIndex::point(std::string_view name) const {
  for (const IndexedPoint& p : points_)
    if (base::sameName(p.name, name)) return &p;
  return nullptr;
}

namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = base::asciiUpper(c);
  return out;
}

}  // namespace

void ProgramIndex::finish() {
  for (const IndexedInstruction& in : instructions_)
    if (in.known && vm::has(in.op, vm::kCalls) && !in.targetLabel.empty()) subroutines_.insert(upper(in.targetLabel));
}

bool ProgramIndex::isSubroutine(std::string_view label) const { return subroutines_.count(upper(label)) > 0; }

const IndexedInstruction* ProgramIndex::labelled(std::string_view label) const {
  for (const IndexedInstruction& in : instructions_)
    if (!in.label.empty() && base::sameName(in.label, label)) return &in;
  return nullptr;
}

}  // namespace rs::lsp
