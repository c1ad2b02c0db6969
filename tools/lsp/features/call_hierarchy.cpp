// The call hierarchy of GOSUBs: the routines are the main program (from
// the top to the first subroutine) and each subroutine (a label a GOSUB
// names, to the line before the next one, as folding.cpp folds them);
// prepareCallHierarchy finds the routine a label names or the one the
// cursor is in, incomingCalls the routines whose GOSUBs call it (each GOSUB's
// label as a range), outgoingCalls the subroutines it calls. An item
// carries its label in `data` ("" for the main program).
#include <fmt/format.h>

#include "base/ascii.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "vm/opcodes.h"

namespace rs::lsp {

namespace {

struct Routine {
  std::string_view label;  // empty: the main program
  std::uint32_t first = 1, last = 1;  // 1-based lines
  const IndexedInstruction* entry = nullptr;
};

std::vector<Routine> routinesOf(const ProgramContext& p) {
  const std::vector<IndexedInstruction>& code = p.analysis.index().instructions();
  std::vector<Routine> out;
  const auto lastLine = static_cast<std::uint32_t>(std::max<std::size_t>(p.doc.lineCount(), 1));
  Routine main{{}, 1, lastLine, code.empty() ? nullptr : &code.front()};
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> extents = subroutineExtents(p);
  if (!extents.empty()) main.last = extents.front().first > 1 ? extents.front().first - 1 : 1;
  out.push_back(main);
  std::size_t e = 0;
  for (const IndexedInstruction& in : code)
    if (!in.label.empty() && p.analysis.index().isSubroutine(in.label) && e < extents.size()) {
      out.push_back({in.label, extents[e].first, extents[e].second, &in});
      ++e;
    }
  return out;
}

const Routine* routineAtLine(const std::vector<Routine>& routines, std::uint32_t line) {
  for (auto r = routines.rbegin(); r != routines.rend(); ++r)
    if (line >= r->first && line <= r->last) return &*r;
  return nullptr;
}

const Routine* routineNamed(const std::vector<Routine>& routines, std::string_view label) {
  for (const Routine& r : routines)
    if (r.label.empty() == label.empty() && base::sameName(r.label, label)) return &r;
  return nullptr;
}

// The label of a GOSUB as written, where it is.
std::optional<Range> targetRange(const ProgramContext& p, const IndexedInstruction& in) {
  for (const Occurrence& o : p.analysis.index().occurrences())
    if (o.kind == NameKind::Label && !o.definition && o.name.data() == in.targetLabel.data()) return rangeOf(p, o);
  return std::nullopt;
}

Json routineItem(const ProgramContext& p, const Routine& r) {
  const std::uint32_t endLine = r.last - 1;
  const Range whole{{r.first - 1, 0}, {endLine, unitsOf(p.doc.line(endLine), p.enc)}};
  Range name = whole;
  if (!r.label.empty()) name = p.doc.rangeOf(r.entry->labelPos, static_cast<std::uint32_t>(r.label.size()), p.enc);
  else if (r.entry) name = p.doc.rangeOf(r.entry->pos, static_cast<std::uint32_t>(r.entry->mnemonic.size()), p.enc);
  const std::string detail = r.label.empty() ? std::string("the main program")
                                             : fmt::format("subroutine, line {}", r.entry->labelPos.line);
  return {{"name", r.label.empty() ? std::string("main program") : std::string(r.label)},
          {"kind", r.label.empty() ? symbol_kind::kModule : symbol_kind::kFunction},
          {"detail", detail},
          {"uri", p.doc.uri()},
          {"range", toJson(whole)},
          {"selectionRange", toJson(name)},
          {"data", {{"label", std::string(r.label)}}}};
}

bool isCall(const IndexedInstruction& in) { return in.known && vm::has(in.op, vm::kCalls) && !in.targetLabel.empty(); }

}  // namespace

Json prepareCallHierarchy(const ProgramContext& p, Position at) {
  const std::vector<Routine> routines = routinesOf(p);
  const Routine* r = nullptr;
  if (const Occurrence* o = occurrenceAt(p, at); o && o->kind == NameKind::Label && p.analysis.index().isSubroutine(o->name))
    r = routineNamed(routines, o->name);
  if (!r) r = routineAtLine(routines, at.line + 1);
  if (!r) return nullptr;
  return Json::array({routineItem(p, *r)});
}

Json incomingCalls(const ProgramContext& p, std::string_view label) {
  Json out = Json::array();
  if (label.empty()) return out;  // nothing calls the main program
  const std::vector<Routine> routines = routinesOf(p);
  std::vector<Json> ranges(routines.size(), Json::array());
  for (const IndexedInstruction& in : p.analysis.index().instructions()) {
    if (!isCall(in) || !base::sameName(in.targetLabel, label)) continue;
    const Routine* from = routineAtLine(routines, in.pos.line);
    const std::optional<Range> r = targetRange(p, in);
    if (from && r) ranges[static_cast<std::size_t>(from - routines.data())].push_back(toJson(*r));
  }
  for (std::size_t i = 0; i < routines.size(); ++i)
    if (!ranges[i].empty()) out.push_back({{"from", routineItem(p, routines[i])}, {"fromRanges", std::move(ranges[i])}});
  return out;
}

Json outgoingCalls(const ProgramContext& p, std::string_view label) {
  Json out = Json::array();
  const std::vector<Routine> routines = routinesOf(p);
  const Routine* from = routineNamed(routines, label);
  if (!from) return out;
  std::vector<Json> ranges(routines.size(), Json::array());
  for (const IndexedInstruction& in : p.analysis.index().instructions()) {
    if (!isCall(in) || in.pos.line < from->first || in.pos.line > from->last) continue;
    const Routine* to = routineNamed(routines, in.targetLabel);
    const std::optional<Range> r = targetRange(p, in);
    if (to && r) ranges[static_cast<std::size_t>(to - routines.data())].push_back(toJson(*r));
  }
  for (std::size_t i = 0; i < routines.size(); ++i)
    if (!ranges[i].empty()) out.push_back({{"to", routineItem(p, routines[i])}, {"fromRanges", std::move(ranges[i])}});
  return out;
}

}  // namespace rs::lsp
