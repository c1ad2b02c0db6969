// The language features, one file each under tools/lsp/features/. Each is a
// function from a document (and its analysis) and the request's params to
// the result's JSON; the server (server.cpp) maps method names to them.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tools/lsp/dispatcher.h"
#include "tools/lsp/document.h"
#include "tools/lsp/json.h"
#include "tools/lsp/params.h"
#include "tools/lsp/program_analysis.h"

namespace rs::lsp {

/// A program and what is known about it, in the client's encoding.
struct ProgramContext {
  const Document& doc;
  const ProgramAnalysis& analysis;
  Encoding enc;
};

/// How long a hover or an inlay hint waits for the run of the version it
/// is about when that run is still being made (then it answers without).
inline constexpr std::chrono::milliseconds kWaitForRun{250};

// diagnostics.cpp: the compiler's diagnostics (and the cell's problem,
// and the server's own checks) as LSP Diagnostic[].
Json programDiagnostics(const ProgramContext& p);
/// What the checked run found (checked_run.h), as LSP Diagnostic[]; from
/// the analysis alone, so that the run worker's thread can make them.
Json runDiagnostics(const ProgramAnalysis& a, const std::string& uri, Encoding enc, const CheckedRun& run);
/// The compile's diagnostics with the run's after them: a warning
/// `input-never-on` gives way to the run's `deadlock` error at its line
/// (the error says the same, at the instant the run got there).
Json withRunDiagnostics(Json compile, Json run);
/// One diagnostic of a program version, placed by that version's text.
Json diagnosticJson(const ProgramAnalysis& a, const std::string& uri, Encoding enc, const diag::Diagnostic& d);
/// Jumps by instruction number to an instruction that exists (the
/// server's warning `numeric-target`, and its quick fix).
std::vector<const Occurrence*> numericTargets(const ProgramIndex& index);
/// Control flow over the index: which instructions run from the first
/// (following calls into subroutines or not), which are subroutine entries.
struct Flow {
  std::vector<bool> reached;
  std::vector<bool> entry;
};
Flow flowOf(const ProgramIndex& index, bool followCalls);
/// The server's own check: the main program falls into a subroutine (the
/// RETURN would then run without a GOSUB). The instruction it falls into.
std::vector<const IndexedInstruction*> fallsIntoSubroutine(const ProgramIndex& index);

// hover.cpp
Json hover(const ProgramContext& p, Position at);

// inputs.cpp: what drives an input (issue 35): the cell's wires to it, the
// stimuli file beside the program (changes, reactive rules), or nothing.
/// Each driver of `input`, for people ("sensor eye (BEAM ...) (WIRE, line 9)").
std::vector<std::string> inputDrivers(const ProgramAnalysis& a, std::int64_t input);
/// Whether anything can ever turn `input` on.
bool inputCanTurnOn(const ProgramAnalysis& a, std::int64_t input);
/// The hover on an input number: "input 1: sensor eye (BEAM ...) ...".
std::string inputHover(const ProgramAnalysis& a, std::int64_t input);
/// The server's warning `input-never-on`: each WAITFOR n ON whose input
/// nothing can turn on (no wire, no stimulus, no reactive rule).
std::vector<diag::Diagnostic> unendingWaits(const ProgramAnalysis& a);
/// Whether a wire's robot label (empty: the cell's one robot) is the robot
/// the program runs on.
bool wiresDrivenRobot(const workcell::Workcell& cell, const std::string& robot);

// navigation.cpp: go to definition, references, highlights, rename.
Json definition(const ProgramContext& p, Position at, const std::vector<std::filesystem::path>& searchPath);
Json references(const ProgramContext& p, Position at, bool includeDeclaration);
Json documentHighlight(const ProgramContext& p, Position at);
Reply prepareRename(const ProgramContext& p, Position at);
Reply rename(const ProgramContext& p, Position at, const std::string& newName);

// symbols.cpp
Json documentSymbols(const ProgramContext& p);
/// SymbolInformation[] of a program whose names match `query`.
void workspaceSymbols(const ProgramContext& p, std::string_view query, Json& into);
/// Case-insensitive subsequence match, as editors filter.
bool fuzzyMatch(std::string_view query, std::string_view name);

// folding.cpp
Json foldingRanges(const ProgramContext& p);
/// Subroutines: [entry line, last line] (1-based), in order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> subroutineExtents(const ProgramContext& p);

// formatting.cpp
/// The program laid out in the examples' columns (label column, instruction
/// and operands, comment column; taught points in aligned columns), or
/// nothing when it cannot be done without a risk to the meaning.
std::optional<std::string> formatProgram(std::string_view text);
/// The same, with `text` already read as a source file (no copy is made).
std::optional<std::string> formatProgram(std::string_view text, const diag::SourceFile& source);
/// Documents over this size are not formatted (RequestFailed).
inline constexpr std::size_t kMaxFormattedBytes = std::size_t{64} << 20;
/// More edits than this become one edit from the first changed line to the last.
inline constexpr std::size_t kMaxFormattingEdits = 1000;
Reply formatting(const ProgramContext& p);

// completion.cpp, signature_help.cpp
/// What the line says up to the cursor.
struct LineContext {
  bool usable = false;  ///< false in a comment or after POINTS
  bool atHead = false;  ///< where an instruction goes
  std::optional<vm::Op> op;     ///< the line's instruction, when known
  std::size_t operand = 0;      ///< 0-based operand the cursor is in or before
  std::string_view partial;     ///< the word typed so far
};
LineContext lineContext(const ProgramContext& p, Position at);
/// With `snippets`, instructions complete with placeholders for operands.
Json completion(const ProgramContext& p, Position at, bool snippets);
Json signatureHelp(const ProgramContext& p, Position at);

// code_actions.cpp
/// `diagnostics`: the context's Diagnostic[] (each read with its types checked).
Json codeActions(const ProgramContext& p, const Range& range, const Field& diagnostics);

// inlay_hints.cpp
Json inlayHints(const ProgramContext& p, const Range& range);

// code_lens.cpp: over each label, its calls and jumps and the run's time.
Json codeLenses(const ProgramContext& p);

// call_hierarchy.cpp: the GOSUBs between the main program and the
// subroutines; an item's routine is named by its label ("" for the main program).
Json prepareCallHierarchy(const ProgramContext& p, Position at);
Json incomingCalls(const ProgramContext& p, std::string_view label);
Json outgoingCalls(const ProgramContext& p, std::string_view label);

// semantic_tokens.cpp
Json semanticTokensLegend();
Json semanticTokens(const ProgramContext& p);

// descriptions.cpp: .rsd and .stim files.
Json descriptionDiagnostics(const Document& doc, Encoding enc);
/// The diagnostics of `list` that are in `file`, as LSP Diagnostic objects at
/// the words of `doc` (a description's or a URDF file's).
Json fileDiagnosticsJson(const Document& doc, Encoding enc, const std::vector<diag::Diagnostic>& list,
                         const std::string& file);
Json descriptionSymbols(const Document& doc, Encoding enc);
Json descriptionHover(const Document& doc, Encoding enc, Position at, const std::vector<std::filesystem::path>& searchPath);
Json descriptionDefinition(const Document& doc, Encoding enc, Position at,
                           const std::vector<std::filesystem::path>& searchPath);
/// Where `name` is defined in the description file `file` (the line of its
/// WORKCELL, ROBOT, GRIPPER, OBJECT or LINK, the name's range); for a name
/// that is the file's path, its first workcell or robot; else its top.
Json definitionInFile(const std::string& file, const std::string& name, Encoding enc);
/// The ROBOT line labelled `label` (AS, else the description name) in a workcell of FILE, or null (issue 36).
Json robotDefinitionInFile(const std::string& file, const std::string& label, Encoding enc);
Json stimuliDiagnostics(const Document& doc, Encoding enc);
Json stimuliSymbols(const Document& doc, Encoding enc);
Json stimuliHover(const Document& doc, Encoding enc, Position at);

// urdf.cpp: .urdf files and the URDF cells programs name.
/// The URDF reader's diagnostics of the document's text, at its XML lines.
Json urdfDiagnostics(const Document& doc, Encoding enc, const std::vector<std::filesystem::path>& searchPath);
/// The D-H table of the robot a `; cell:` directive names (markdown), or "".
std::string cellTableHover(const ProgramContext& p);

// Shared helpers (features.cpp).
/// The occurrence under a position, if any.
const Occurrence* occurrenceAt(const ProgramContext& p, Position at);
Range rangeOf(const ProgramContext& p, const Occurrence& o);
/// The code part of a line: without its comment and trailing blanks.
std::string_view codeOf(std::string_view line);
/// An instruction as written: from its mnemonic to the end of its code.
std::string_view instructionText(const ProgramContext& p, const IndexedInstruction& in);

}  // namespace rs::lsp
