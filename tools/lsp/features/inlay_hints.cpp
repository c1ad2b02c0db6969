// textDocument/inlayHint: before each instruction its number (what GOTO 3
// means: instructions are counted, not lines), and after it the simulated
// time at which it ends in the checked run (its first execution; how many
// times it ran when more than once), or where that run stopped on it. The
// run is check's, bounded (checked_run.h); while it is being made the
// hints come without times, and the server asks the client to refresh
// them once it is made.
#include <fmt/format.h>

#include "vm/stop_reason.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"

namespace rs::lsp {

Json inlayHints(const ProgramContext& p, const Range& range) {
  Json out = Json::array();
  const ProgramIndex& index = p.analysis.index();
  const CheckedRun* run = p.analysis.ok() ? p.analysis.run(kWaitForRun) : nullptr;
  if (p.analysis.ok() && !run) p.analysis.noteAnsweredWithoutRun();
  const auto first = std::lower_bound(index.instructions().begin(), index.instructions().end(), range.start.line + 1,
                                      [](const IndexedInstruction& in, std::uint32_t l) { return in.pos.line < l; });
  for (auto it = first; it != index.instructions().end() && it->pos.line <= range.end.line + 1; ++it) {
    const IndexedInstruction& in = *it;
    out.push_back({{"position", toJson(p.doc.fromPos(in.pos, p.enc))},
                   {"label", fmt::format("#{}", in.number)},
                   {"paddingRight", true}});
    if (!run || in.number - 1 >= run->times.size()) continue;
    const InstructionTimes& t = run->times[in.number - 1];
    const bool stops = run->stoppedAt() == in.number - 1;
    if (t.runs == 0 && !stops) continue;
    const std::uint32_t line = in.pos.line - 1;
    const Position end{line, unitsOf(codeOf(p.doc.line(line)), p.enc)};
    std::string label = stops ? fmt::format("stops {} ({})", formatSeconds(run->clock),
                                            vm::stopReasonName(run->outcome->reason))
                              : fmt::format("ends {}", formatSeconds(t.end));
    if (t.runs > 1 && !stops) label += fmt::format(" (first of {})", t.runs);
    out.push_back({{"position", toJson(end)}, {"label", label}, {"paddingLeft", true}});
  }
  return out;
}

}  // namespace rs::lsp
