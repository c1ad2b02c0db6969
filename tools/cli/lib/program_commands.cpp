#include "tools/cli/lib/program_commands.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "base/file_io.h"
#include "base/text.h"
#include "tools/cli/lib/exit_codes.h"
#include "tools/cli/lib/options.h"
#include "diag/read_input.h"
#include "compiler/program/compiler.h"
#include "vm/disasm.h"
#include "vm/image_file.h"

namespace rs::cli {

namespace {

// tokens / ast: teaching views of the front end; they read source only.
template <typename Dump>
int sourceView(const launch::ProgramRequest& request, std::ostream& out, std::ostream& err, Dump dump) {
  const std::string& file = request.file;
  diag::Result<std::string> text = diag::readInput(file, launch::kMaxInputBytes, "cannot read file");
  if (!text) {
    err << fmt::format("{}: error: {}\n", base::safeText(file), text.failure().message);
    return kExitBadInput;
  }
  if (vm::looksLikeImage(*text)) {
    err << fmt::format("{}: error: this is a compiled image; try robotsim disasm\n", base::safeText(file));
    return kExitBadInput;
  }
  const diag::SourceFile source(file, std::move(text).value());
  diag::Diagnostics diags(file, request.maxErrors);
  out << dump(source, diags);
  launch::printDiagnostics(
      err, diags.sorted(), [&source](const std::string&) { return &source; }, request.maxErrors, diags.omitted());
  return diags.hasErrors() ? kExitBadInput : kExitOk;
}

}  // namespace

int compileCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err) {
  launch::LoadedProgram program = launch::loadProgram(o.program);
  launch::printDiagnostics(err, program.diagnostics, program);
  if (!program.ok()) return kExitBadInput;
  // The source's diagnostics are printed: free it before the image is
  // written (streamed to the file, never held as bytes beside the image).
  program.source.reset();
  std::string error;
  if (!base::writeFileAtomically(
          o.output, [&program](std::ostream& file) { return vm::writeImage(*program.image, file); }, error)) {
    err << fmt::format("{}: error: cannot write: {}\n", base::safeText(o.output), error);
    return kExitBadInput;
  }
  // With -o - the image is standard output: the note goes beside the errors.
  (o.output == "-" ? err : out) << fmt::format("{} -> {} ({} instructions)\n", base::safeText(o.program.file),
                                               base::safeText(o.output), program.image->code.size());
  return kExitOk;
}

int disasmCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err) {
  launch::LoadedProgram program = launch::loadProgram(o.program);
  launch::printDiagnostics(err, program.diagnostics, program);
  if (!program.ok()) return kExitBadInput;
  program.source.reset();  // as in compile: not held beside the listing
  out << vm::disassemble(*program.image);
  return kExitOk;
}

int tokensCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err) {
  return sourceView(o.program, out, err, [](const diag::SourceFile& s, auto& d) { return compiler::dumpTokens(s, d); });
}

// Operand counts are checked against the robot: --cell's, or the default.
int astCommand(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err) {
  compiler::Target target = launch::defaultTarget();
  if (!o.program.cell.empty()) {
    launch::LoadedProgram descriptions;
    const std::shared_ptr<const workcell::Workcell> cell = launch::loadCell(o.program, descriptions);
    if (cell && cell->robots.empty())
      descriptions.diagnostics.push_back(
          {o.program.cell, {}, diag::Severity::Error, "the workcell has no robot to run the program"});
    if (!cell || diag::hasErrors(descriptions.diagnostics)) {
      launch::printDiagnostics(err, descriptions.diagnostics, descriptions);
      return kExitBadInput;
    }
    target = launch::cellTarget(*cell);
  }
  return sourceView(o.program, out, err,
                    [&](const diag::SourceFile& s, auto& d) { return compiler::dumpAst(s, target, o.tree, d); });
}

void addCompileOptions(CLI::App* cmd, ProgramCommandOptions& o) {
  cmd->add_option("file", o.program.file, "Program source (without it: every PROGRAM of --cell, -o a folder)");
  cmd->add_option("-o,--output", o.output,
                  "Image file to write (.rsb; - for standard output; a device or FIFO is written in place; a "
                  "folder without a program file)")
      ->required();
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
}

void addDisasmOptions(CLI::App* cmd, ProgramCommandOptions& o) {
  cmd->add_option("file", o.program.file, "Program source or compiled image")->required();
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
}

void addTokensOptions(CLI::App* cmd, ProgramCommandOptions& o) {
  cmd->add_option("file", o.program.file, "Program source")->required();
  addMaxErrorsOption(cmd, o.program);
}

void addAstOptions(CLI::App* cmd, ProgramCommandOptions& o) {
  cmd->add_option("file", o.program.file, "Program source")->required();
  cmd->add_flag("--tree", o.tree, "Also print ANTLR's parse tree");
  addCellOptions(cmd, o.program);
  addMaxErrorsOption(cmd, o.program);
}

}  // namespace rs::cli
