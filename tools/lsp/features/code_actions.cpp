// textDocument/codeAction: quick fixes for the diagnostics in the range
// the client sends (by their stable codes):
//   unknown-instruction    did you mean MOVE?
//   undefined-label        did you mean loop? (the nearest label)
//   undefined-point        did you mean PICK?; add the point to POINTS
//   falls-into-subroutine  add END before the subroutine
//   unreachable-code       remove the unreachable instructions
//   numeric-target         jump to a label instead of an instruction number
//                          (this jump, or every one in the program)
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "base/ascii.h"
#include "base/near_names.h"
#include "compiler/program/ast_builder.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "vm/opcodes.h"

namespace rs::lsp {

namespace {

Json action(std::string title, const Json& diagnostic, const std::string& uri, Json edits, bool preferred = false) {
  Json a = {{"title", std::move(title)},
            {"kind", "quickfix"},
            {"diagnostics", Json::array({diagnostic})},
            {"edit", {{"changes", {{uri, std::move(edits)}}}}}};
  if (preferred) a["isPreferred"] = true;
  return a;
}

std::string wordIn(const ProgramContext& p, const Range& r) {
  const std::size_t a = p.doc.offsetOf(r.start, p.enc), b = p.doc.offsetOf(r.end, p.enc);
  return b > a ? p.doc.text().substr(a, b - a) : std::string();
}

void replaceWith(const ProgramContext& p, const Json& d, const Range& r, std::string_view word, std::string_view near,
                 Json& out) {
  if (near.empty() || near == word) return;
  out.push_back(action(fmt::format("Change '{}' to '{}'", word, near), d, p.doc.uri(),
                       Json::array({textEdit(r, std::string(near))}), true));
}

// A line that defines the missing point: 0 for each motor, or the nearest
// value in its range.
std::string pointLine(const ProgramContext& p, std::string_view name) {
  std::string line(name);
  for (const vm::MotorSpec& m : p.analysis.cell().target.motors)
    line += fmt::format(" {}", std::clamp<std::int32_t>(0, m.min, m.max));
  return line;
}

void addPoint(const ProgramContext& p, const Json& d, const std::string& name, Json& out) {
  const ProgramIndex& index = p.analysis.index();
  const std::string eol = p.doc.text().find("\r\n") != std::string::npos ? "\r\n" : "\n";
  Json edit;
  if (index.pointsHeader().line != 0) {
    const std::uint32_t after = index.points().empty() ? index.pointsHeader().line : index.points().back().pos.line;
    edit = textEdit({{after, 0}, {after, 0}}, pointLine(p, name) + eol);
    if (after >= p.doc.lineCount()) {  // the last line has no line break
      const std::uint32_t last = p.doc.lineCount() - 1;
      const Position end{last, unitsOf(p.doc.line(last), p.enc)};
      edit = textEdit({end, end}, eol + pointLine(p, name));
    }
  } else {
    const std::uint32_t last = p.doc.lineCount() - 1;
    const Position end{last, unitsOf(p.doc.line(last), p.enc)};
    const std::string before = p.doc.line(last).empty() ? "" : eol;
    edit = textEdit({end, end}, before + eol + "POINTS" + eol + pointLine(p, name) + eol);
  }
  out.push_back(action(fmt::format("Add point '{}' to POINTS", name), d, p.doc.uri(), Json::array({edit})));
}

// END inserted before the subroutine's first line; not offered when a jump
// by number would then name another instruction.
void addEnd(const ProgramContext& p, const Json& d, std::uint32_t line, Json& out) {
  const ProgramIndex& index = p.analysis.index();
  const IndexedInstruction* entry = nullptr;
  for (const IndexedInstruction& in : index.instructions())
    if ((!in.label.empty() && in.labelPos.line == line) || in.pos.line == line) {
      entry = &in;
      break;
    }
  if (!entry) return;
  for (const Occurrence& o : index.occurrences())
    if (o.kind == NameKind::Instruction && o.instruction >= entry->number) return;
  const std::string eol = p.doc.text().find("\r\n") != std::string::npos ? "\r\n" : "\n";
  out.push_back(action("Add END before the subroutine", d, p.doc.uri(),
                       Json::array({textEdit({{line - 1, 0}, {line - 1, 0}}, std::string(8, ' ') + "END" + eol)}), true));
}

// The unreachable instructions from the one at `line` on, removed when no
// instruction outside them names one of their labels.
void removeUnreachable(const ProgramContext& p, const Json& d, std::uint32_t line, Json& out) {
  const ProgramIndex& index = p.analysis.index();
  const IndexedInstruction* first = index.instructionOnLine(line);
  if (!first) return;
  const Flow flow = flowOf(index, true);
  const std::vector<IndexedInstruction>& code = index.instructions();
  std::size_t last = first->number - 1;
  while (last + 1 < code.size() && !flow.reached[last + 1]) ++last;
  const std::uint32_t fromLine = first->label.empty() ? first->pos.line : first->labelPos.line;
  const std::uint32_t toLine = code[last].pos.line;
  for (const Occurrence& o : index.occurrences()) {
    if (o.definition || (o.kind != NameKind::Label && o.kind != NameKind::Instruction)) continue;
    if (o.pos.line >= fromLine && o.pos.line <= toLine) continue;
    if (o.kind == NameKind::Instruction && o.instruction >= first->number) return;  // numbers would shift
    if (o.kind == NameKind::Label) {
      const IndexedInstruction* target = index.labelled(o.name);
      if (target && target->number >= first->number && target->number <= last + 1) return;
    }
  }
  const std::size_t removed = last + 2 - first->number;
  out.push_back(action(fmt::format("Remove the unreachable instruction{}", removed == 1 ? "" : "s"), d, p.doc.uri(),
                       Json::array({textEdit({{fromLine - 1, 0}, {toLine, 0}}, "")})));
}

std::string upperCased(std::string_view name) {
  std::string out(name);
  for (char& c : out) c = base::asciiUpper(c);
  return out;
}

// A label for instruction `number` that no label of the program has (any
// case) and no reserved word is: L7, else L7_2, L7_3, ...
std::string freshLabel(std::uint32_t number, std::set<std::string>& taken) {
  const std::string stem = fmt::format("L{}", number);
  std::string name = stem;
  for (int n = 2; taken.count(upperCased(name)) || vm::isReservedWord(name); ++n) name = fmt::format("{}_{}", stem, n);
  taken.insert(upperCased(name));
  return name;
}

// The edits that make the jumps `jumps` name labels: each target gets a
// label when it has none (at column 1, in the blanks before its
// instruction when they leave room, so the layout stays), each jump the
// target's label.
Json labelEdits(const ProgramContext& p, const std::vector<const Occurrence*>& jumps) {
  const ProgramIndex& index = p.analysis.index();
  std::set<std::string> taken;
  for (const IndexedInstruction& in : index.instructions())
    if (!in.label.empty()) taken.insert(upperCased(in.label));
  std::map<std::uint32_t, std::string> labels;  // instruction number -> its label
  Json edits = Json::array();
  for (const Occurrence* jump : jumps) {
    const IndexedInstruction* target = index.instructionNumbered(jump->instruction);
    if (!target) continue;
    auto [it, added] = labels.try_emplace(target->number);
    if (added && !target->label.empty()) it->second = std::string(target->label);
    if (added && target->label.empty()) {
      it->second = freshLabel(target->number, taken);
      const std::string_view line = p.doc.line(target->pos.line - 1);
      const Position start = p.doc.fromPos({target->pos.line, 1}, p.enc);
      const Position mnemonic = p.doc.fromPos(target->pos, p.enc);
      const std::size_t from = p.doc.offsetOf(start, p.enc) - p.doc.lineStart(start.line);
      const std::size_t to = p.doc.offsetOf(mnemonic, p.enc) - p.doc.lineStart(start.line);
      const std::string_view blanks = line.substr(from, to - from);
      const std::string label = it->second + ":";
      if (blanks.find_first_not_of(' ') == std::string_view::npos && blanks.size() > label.size())
        edits.push_back(textEdit({start, mnemonic}, label + std::string(blanks.size() - label.size(), ' ')));
      else
        edits.push_back(textEdit({start, start}, label + " "));
    }
    edits.push_back(textEdit(rangeOf(p, *jump), it->second));
  }
  return edits;
}

// The quick fixes of a jump by number: this jump to a label, and every
// jump by number in the program at once.
void labelTargets(const ProgramContext& p, const Json* d, const Range& r, Json& out) {
  const std::vector<const Occurrence*> all = numericTargets(p.analysis.index());
  const auto here = std::find_if(all.begin(), all.end(), [&](const Occurrence* o) { return rangeOf(p, *o) == r; });
  if (here == all.end()) return;
  out.push_back(action(fmt::format("Jump to a label instead of instruction {}", (*here)->instruction), *d, p.doc.uri(),
                       labelEdits(p, {*here}), true));
  if (all.size() > 1)
    out.push_back(action(fmt::format("Jump to labels instead of instruction numbers ({} jumps)", all.size()), *d,
                         p.doc.uri(), labelEdits(p, all)));
}

}  // namespace

Json codeActions(const ProgramContext& p, const Range& range, const Field& diagnostics) {
  (void)range;
  Json out = Json::array();
  const ProgramIndex& index = p.analysis.index();
  for (std::size_t i = 0; i < diagnostics.size(false); ++i) {
    const Field diagnostic = diagnostics.element(i);
    const Json& d = diagnostic.object();
    const Range r = rangeFrom(diagnostic["range"]);
    const Field codeField = diagnostic["code"];
    if (!codeField.present()) continue;
    if (!codeField.any().is_string()) {  // an integer code is none of ours; any other type is wrong
      codeField.integer();
      continue;
    }
    const std::string code = codeField.string();
    const std::string word = wordIn(p, r);
    if (code == "unknown-instruction") {
      replaceWith(p, d, r, word, compiler::closestMnemonic(word), out);
    } else if (code == "undefined-label") {
      std::vector<std::string_view> labels;
      for (const IndexedInstruction& in : index.instructions())
        if (!in.label.empty()) labels.push_back(in.label);
      replaceWith(p, d, r, word, base::nearestName(word, labels), out);
    } else if (code == "undefined-point") {
      std::vector<std::string_view> points;
      for (const IndexedPoint& point : index.points()) points.push_back(point.name);
      replaceWith(p, d, r, word, base::nearestName(word, points), out);
      addPoint(p, d, word, out);
    } else if (code == "falls-into-subroutine") {
      addEnd(p, d, r.start.line + 1, out);
    } else if (code == "unreachable-code") {
      removeUnreachable(p, d, r.start.line + 1, out);
    } else if (code == "numeric-target") {
      labelTargets(p, &d, r, out);
    }
  }
  return out;
}

}  // namespace rs::lsp
