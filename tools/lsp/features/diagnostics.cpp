// textDocument/publishDiagnostics for programs: the compiler's diagnostics
// with their stable codes, hints and related places, the cell's problem
// (at the directive that named it), the server's own checks (jumps by
// number, the main program running into a subroutine), and, once its run
// is made, what the run found (checked_run.h).
#include <fmt/format.h>

#include <map>

#include "base/ascii.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"

namespace rs::lsp {

namespace {

int severityOf(diag::Severity s) {
  switch (s) {
    case diag::Severity::Error: return 1;
    case diag::Severity::Warning: return 2;
    case diag::Severity::Note: return 3;
  }
  return 1;
}

}  // namespace

Json diagnosticJson(const ProgramAnalysis& a, const std::string& uri, Encoding enc, const diag::Diagnostic& d) {
  Json out = {{"range", toJson(a.wordAt(d.pos, enc))},
              {"severity", severityOf(d.severity)},
              {"source", "robotsim"},
              {"message", d.hint.empty() ? d.message : fmt::format("{}\nhint: {}", d.message, d.hint)}};
  if (!d.code.empty()) out["code"] = d.code;
  if (!d.related.empty()) {
    Json related = Json::array();
    for (const diag::Related& r : d.related) {
      const bool here = r.file == a.source().name();
      const Range range = here ? a.wordAt(r.pos, enc) : Range{};
      related.push_back({{"location", location(here ? uri : uriOfPath(r.file), range)}, {"message", r.message}});
    }
    out["relatedInformation"] = std::move(related);
  }
  return out;
}

Json runDiagnostics(const ProgramAnalysis& a, const std::string& uri, Encoding enc, const CheckedRun& run) {
  Json out = Json::array();
  for (const diag::Diagnostic& d : run.diagnostics) out.push_back(diagnosticJson(a, uri, enc, d));
  return out;
}

Json withRunDiagnostics(Json compile, Json run) {
  Json out = Json::array();
  const auto deadlockOn = [&](const Json& line) {
    for (const Json& r : run)
      if (r.value("code", "") == "deadlock" && r["range"]["start"]["line"] == line) return true;
    return false;
  };
  for (Json& d : compile)
    if (d.value("code", "") != "input-never-on" || !deadlockOn(d["range"]["start"]["line"])) out.push_back(std::move(d));
  for (Json& d : run) out.push_back(std::move(d));
  return out;
}

namespace {

Json toLsp(const ProgramContext& p, const diag::Diagnostic& d) { return diagnosticJson(p.analysis, p.doc.uri(), p.enc, d); }

// Where the editor's text had bytes that were not UTF-8 (now U+FFFD).
std::optional<diag::Diagnostic> invalidUtf8(const ProgramContext& p) {
  if (!p.doc.hadInvalidUtf8()) return std::nullopt;
  const std::size_t at = p.doc.text().find("\xEF\xBF\xBD");
  const Position pos = p.doc.positionOf(at == std::string::npos ? 0 : at, p.enc);
  return diag::Diagnostic{p.analysis.source().name(), p.doc.toPos(pos, p.enc), diag::Severity::Error,
                          "the editor sent bytes that are not UTF-8 (each is shown as U+FFFD): programs are UTF-8 text",
                          "invalid-utf8"};
}

}  // namespace

Flow flowOf(const ProgramIndex& index, bool followCalls) {
  const std::vector<IndexedInstruction>& code = index.instructions();
  std::map<std::string, std::uint32_t> labels;  // upper-cased -> 0-based index
  for (const IndexedInstruction& in : code) {
    if (in.label.empty()) continue;
    std::string name(in.label);
    for (char& c : name) c = base::asciiUpper(c);
    labels.try_emplace(name, in.number - 1);
  }
  const auto targetOf = [&](const IndexedInstruction& in) -> std::optional<std::uint32_t> {
    if (in.targetNumber != 0) return in.targetNumber - 1;
    std::string name(in.targetLabel);
    for (char& c : name) c = base::asciiUpper(c);
    const auto it = labels.find(name);
    return it == labels.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
  };
  Flow flow{std::vector<bool>(code.size(), false), std::vector<bool>(code.size(), false)};
  for (const IndexedInstruction& in : code)
    if (in.known && vm::has(in.op, vm::kCalls))
      if (const auto t = targetOf(in); t && *t < code.size()) flow.entry[*t] = true;
  std::vector<std::uint32_t> work{0};
  while (!work.empty()) {
    const std::uint32_t i = work.back();
    work.pop_back();
    if (i >= code.size() || flow.reached[i]) continue;
    flow.reached[i] = true;
    const std::uint16_t flags = code[i].known ? vm::info(code[i].op).flags : std::uint16_t{vm::kFallsThrough};
    if (flags & vm::kFallsThrough) work.push_back(i + 1);
    if ((flags & vm::kJumps) && (followCalls || !(flags & vm::kCalls)))
      if (const auto t = targetOf(code[i])) work.push_back(*t);
  }
  return flow;
}

std::vector<const IndexedInstruction*> fallsIntoSubroutine(const ProgramIndex& index) {
  // What the main program runs, not following calls into subroutines.
  const Flow main = flowOf(index, false);
  const std::vector<IndexedInstruction>& code = index.instructions();
  std::vector<const IndexedInstruction*> out;
  for (std::size_t i = 1; i < code.size(); ++i) {
    const bool fallsOn = !code[i - 1].known || (vm::info(code[i - 1].op).flags & vm::kFallsThrough);
    if (main.entry[i] && main.reached[i - 1] && fallsOn) out.push_back(&code[i]);
  }
  return out;
}

std::vector<const Occurrence*> numericTargets(const ProgramIndex& index) {
  std::vector<const Occurrence*> out;
  for (const Occurrence& o : index.occurrences())
    if (o.kind == NameKind::Instruction && !o.definition && index.instructionNumbered(o.instruction)) out.push_back(&o);
  return out;
}

Json programDiagnostics(const ProgramContext& p) {
  Json out = Json::array();
  const ProgramAnalysis& a = p.analysis;
  if (auto bad = invalidUtf8(p)) out.push_back(toLsp(p, *bad));
  if (!a.cell().problem.empty()) {
    const auto& d = a.directive();
    const std::string message = d ? fmt::format("cell '{}': {}", d->name, a.cell().problem)
                                  : fmt::format("robotsim.cell '{}': {}", a.cell().name, a.cell().problem);
    Json j = {{"range", toJson(d ? p.doc.wordAt(d->pos, p.enc) : Range{})},
              {"severity", 1},
              {"source", "robotsim"},
              {"code", "unknown-cell"},
              {"message", message + "; checked against the default robot"}};
    out.push_back(std::move(j));
  }
  if (!a.cell().robotProblem.empty())
    out.push_back({{"range", toJson(p.doc.wordAt(a.cell().robotProblemPos, p.enc))},
                   {"severity", 1},
                   {"source", "robotsim"},
                   {"code", "unknown-robot"},
                   {"message", a.cell().robotProblem + "; checked against the cell's first robot"}});
  for (const diag::Diagnostic& d : a.compiled().diagnostics) out.push_back(toLsp(p, d));
  for (const Occurrence* o : numericTargets(a.index())) {
    diag::Diagnostic d{a.source().name(), o->pos, diag::Severity::Warning,
                       fmt::format("a jump to instruction {} by its number: an instruction added or removed before it "
                                   "makes the jump land elsewhere",
                                   o->instruction),
                       "numeric-target", fmt::format("give instruction {} a label and jump to the label (quick fix)",
                                                     o->instruction)};
    out.push_back(toLsp(p, d));
  }
  if (a.ok()) {
    for (const diag::Diagnostic& d : unendingWaits(a)) out.push_back(toLsp(p, d));
    for (const IndexedInstruction* in : fallsIntoSubroutine(a.index())) {
      const std::string what = in->label.empty() ? fmt::format("the subroutine at instruction {}", in->number)
                                                 : fmt::format("subroutine '{}'", in->label);
      diag::Diagnostic d{a.source().name(), in->label.empty() ? in->pos : in->labelPos, diag::Severity::Warning,
                         fmt::format("the main program runs on into {} (its RETURN then has no GOSUB to go back to)",
                                     what),
                         "falls-into-subroutine", "end the main program with END before the subroutine"};
      out.push_back(toLsp(p, d));
    }
  }
  if (a.compiled().omitted.any())
    out.push_back({{"range", toJson(Range{})},
                   {"severity", 3},
                   {"source", "robotsim"},
                   {"message", fmt::format("{} more errors and {} more warnings not shown", a.compiled().omitted.errors,
                                           a.compiled().omitted.warnings)}});
  return out;
}

}  // namespace rs::lsp
