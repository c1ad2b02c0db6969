// The compiler as a library: source text in, image and diagnostics out.
// No global state and no exit(): an editor's language server can call it on
// every keystroke, and a test runner can compile many programs side by side.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/program/ast_builder.h"
#include "compiler/program/codegen.h"
#include "diag/diagnostic.h"
#include "diag/source_file.h"
#include "vm/image.h"

namespace rs::compiler {

inline constexpr std::size_t kMaxSourceBytes = std::size_t{256} << 20;  // 256 MiB

struct CompileResult {
  std::optional<vm::Image> image;        // set when there were no errors
  std::vector<diag::Diagnostic> diagnostics;   // sorted by position
  diag::Omitted omitted;                       // found beyond the first `keepDiagnostics`
  bool ok() const { return image.has_value(); }
};

/// source -> tokens -> ANTLR parse tree -> AST -> checks -> bytecode.
/// With `keepDiagnostics` > 0 only the first that many diagnostics (by
/// position) are kept; the others are counted in `omitted`.
CompileResult compile(const diag::SourceFile& source, const Target& target, std::size_t keepDiagnostics = 0);
/// The same compile, also handing every instruction, the POINTS header and
/// every point to `observer` as the checker receives them (valid during the
/// call only): a language server indexes names and references from the
/// one parse that gives its diagnostics.
CompileResult compile(const diag::SourceFile& source, const Target& target, std::size_t keepDiagnostics,
                      AstSink& observer);

/// Checks that a source can be lexed at all (size, UTF-8); returns the error.
/// `what` names the kind of file in the message ("programs are UTF-8 text").
std::optional<diag::Diagnostic> checkEncoding(const diag::SourceFile& source, std::string_view what = "programs");

/// `robotsim tokens`: one line per token the parser sees; problems go to
/// `diagnostics` (made for the source's name).
std::string dumpTokens(const diag::SourceFile& source, diag::Diagnostics& diagnostics);

/// `robotsim ast`: the AST as an indented outline; with `parseTree`, ANTLR's
/// parse tree in LISP form first.
std::string dumpAst(const diag::SourceFile& source, const Target& target, bool parseTree,
                    diag::Diagnostics& diagnostics);

}  // namespace rs::compiler
