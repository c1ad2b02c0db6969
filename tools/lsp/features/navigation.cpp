// Go to definition, find references, document highlight and rename for
// labels, points, variables (and subroutine entries, which are labels);
// a jump by number goes to the instruction of that number; the cell
// directive goes to the cell's description file.
#include <fmt/format.h>

#include "base/ascii.h"
#include "diag/source_file.h"
#include "launch/cell_directive.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"
#include "vm/opcodes.h"

namespace rs::lsp {

namespace {

bool onDirective(const ProgramContext& p, Position at) {
  const auto& d = p.analysis.directive();
  if (!d) return false;
  const Range r = p.doc.rangeOf(d->pos, d->name.size(), p.enc);
  return at.line == r.start.line && at.character >= r.start.character && at.character <= r.end.character;
}

bool validName(std::string_view name) {
  if (name.empty() || name.size() > vm::kMaxNameLength) return false;
  const auto start = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  if (!start(name[0])) return false;
  for (const char c : name)
    if (!start(c) && !(c >= '0' && c <= '9')) return false;
  return !vm::isReservedWord(name);
}

const char* kindName(NameKind k) {
  switch (k) {
    case NameKind::Label: return "label";
    case NameKind::Point: return "point";
    case NameKind::Variable: return "variable";
    case NameKind::Instruction: return "instruction";
  }
  return "name";
}

}  // namespace

Json definition(const ProgramContext& p, Position at, const std::vector<std::filesystem::path>& searchPath) {
  if (onDirective(p, at)) {
    const std::string& name = p.analysis.cell().name;
    const std::string file = findDescriptionFile(name, searchPath);
    if (file.empty()) return nullptr;
    return definitionInFile(file, name, p.enc);
  }
  // `; robot: LABEL` (issue 36): that robot's ROBOT line in the cell's file.
  if (const auto robot = launch::findRobotDirective(diag::withoutByteOrderMark(p.doc.text()))) {
    const Range r = p.doc.rangeOf(robot->pos, robot->name.size(), p.enc);
    if (at.line == r.start.line && at.character >= r.start.character && at.character <= r.end.character) {
      const std::string file = findDescriptionFile(p.analysis.cell().name, searchPath);
      return file.empty() ? Json(nullptr) : robotDefinitionInFile(file, robot->name, p.enc);
    }
  }
  const Occurrence* o = occurrenceAt(p, at);
  if (!o) return nullptr;
  if (o->kind == NameKind::Instruction) {
    const IndexedInstruction* in = p.analysis.index().instructionNumbered(o->instruction);
    if (!in) return nullptr;
    return location(p.doc.uri(), p.doc.rangeOf(in->pos, in->mnemonic.size(), p.enc));
  }
  const Occurrence* def = p.analysis.index().definitionOf(*o);
  if (!def) return nullptr;
  return location(p.doc.uri(), rangeOf(p, *def));
}

Json references(const ProgramContext& p, Position at, bool includeDeclaration) {
  const Occurrence* o = occurrenceAt(p, at);
  if (!o) return nullptr;
  Json out = Json::array();
  for (const Occurrence* use : p.analysis.index().occurrencesOf(*o))
    if (includeDeclaration || !use->definition) out.push_back(location(p.doc.uri(), rangeOf(p, *use)));
  return out;
}

Json documentHighlight(const ProgramContext& p, Position at) {
  const Occurrence* o = occurrenceAt(p, at);
  if (!o) return nullptr;
  Json out = Json::array();
  for (const Occurrence* use : p.analysis.index().occurrencesOf(*o))
    out.push_back({{"range", toJson(rangeOf(p, *use))}, {"kind", use->definition ? 3 : 2}});
  return out;
}

Reply prepareRename(const ProgramContext& p, Position at) {
  const Occurrence* o = occurrenceAt(p, at);
  if (!o || o->kind == NameKind::Instruction) return Json(nullptr);
  return Json{{"range", toJson(rangeOf(p, *o))}, {"placeholder", std::string(o->name)}};
}

Reply rename(const ProgramContext& p, Position at, const std::string& newName) {
  const Occurrence* o = occurrenceAt(p, at);
  if (!o || o->kind == NameKind::Instruction)
    return RpcError{errc::kRequestFailed, "only labels, points and variables can be renamed"};
  if (!validName(newName))
    return RpcError{errc::kRequestFailed,
                    fmt::format("'{}' cannot name a {}: a letter or '_', then letters, digits or '_' (at most {}), "
                                "and not a reserved word",
                                newName, kindName(o->kind), vm::kMaxNameLength)};
  for (const Occurrence& other : p.analysis.index().occurrences())
    if (other.kind == o->kind && base::sameName(other.name, newName) && !base::sameName(other.name, o->name))
      return RpcError{errc::kRequestFailed, fmt::format("the program already has a {} '{}'", kindName(o->kind), newName)};
  Json edits = Json::array();
  for (const Occurrence* use : p.analysis.index().occurrencesOf(*o)) edits.push_back(textEdit(rangeOf(p, *use), newName));
  return Json{{"changes", {{p.doc.uri(), std::move(edits)}}}};
}

}  // namespace rs::lsp
