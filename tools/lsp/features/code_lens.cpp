// textDocument/codeLens: over each label, who goes there and, from the
// checked run, how long it takes. A subroutine: its GOSUBs ("2 calls"),
// any jumps to it, and the simulated time a call takes, from its GOSUB to
// its RETURN with the calls it makes ("4.2 s a call, 8.4 s in all"); a
// label: its jumps, how often the run passed it and the time spent from it
// to the next label, all passes together. Until the run is made the
// lenses come without times (and the client is asked to refresh them).
// A lens only shows: its command has no id (nothing to run).
#include <fmt/format.h>

#include "base/ascii.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "vm/opcodes.h"

namespace rs::lsp {

namespace {

std::string counted(std::uint64_t n, std::string_view one, std::string_view many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

std::string subroutineTime(const CallTimes& c) {
  if (c.calls == 0) return "not called in the run";
  if (c.shortest == c.longest)
    return c.calls == 1 ? fmt::format("{} a call", formatSeconds(c.total))
                        : fmt::format("{} a call, {} in all", formatSeconds(c.shortest), formatSeconds(c.total));
  return fmt::format("{} to {} a call, {} in all", formatSeconds(c.shortest), formatSeconds(c.longest),
                     formatSeconds(c.total));
}

// From the label's instruction up to the next labelled one.
std::string labelTime(const ProgramIndex& index, const CheckedRun& run, std::uint32_t at) {
  const std::vector<IndexedInstruction>& code = index.instructions();
  const std::uint64_t passes = run.times[at].runs;
  if (passes == 0) return "not reached in the run";
  vm::Micros spent = 0;
  for (std::uint32_t i = at; i < code.size() && i < run.times.size() && (i == at || code[i].label.empty()); ++i)
    spent += run.times[i].total;
  return fmt::format("passed {}, {} to the next label", counted(passes, "time", "times"), formatSeconds(spent));
}

}  // namespace

Json codeLenses(const ProgramContext& p) {
  Json out = Json::array();
  const ProgramIndex& index = p.analysis.index();
  const CheckedRun* run = p.analysis.ok() ? p.analysis.run(kWaitForRun) : nullptr;
  if (p.analysis.ok() && !run) p.analysis.noteAnsweredWithoutRun();
  const bool timed = run && run->end == CheckedRun::End::Finished;
  for (const IndexedInstruction& in : index.instructions()) {
    if (in.label.empty()) continue;
    std::uint64_t calls = 0, jumps = 0;
    for (const IndexedInstruction& from : index.instructions()) {
      if (!from.known || !vm::has(from.op, vm::kJumps) || !base::sameName(from.targetLabel, in.label)) continue;
      ++(vm::has(from.op, vm::kCalls) ? calls : jumps);
    }
    std::vector<std::string> parts;
    const bool subroutine = index.isSubroutine(in.label);
    if (subroutine) parts.push_back(counted(calls, "call", "calls"));
    if (jumps > 0 || !subroutine) parts.push_back(counted(jumps, "jump", "jumps"));
    const std::uint32_t at = in.number - 1;
    if (timed && at < run->times.size())
      parts.push_back(subroutine ? subroutineTime(run->calls[at]) : labelTime(index, *run, at));
    std::string title;
    for (const std::string& part : parts) title += (title.empty() ? "" : " · ") + part;
    const Range range = p.doc.rangeOf(in.labelPos, static_cast<std::uint32_t>(in.label.size()), p.enc);
    out.push_back({{"range", toJson(range)}, {"command", {{"title", title}, {"command", ""}}}});
  }
  return out;
}

}  // namespace rs::lsp
