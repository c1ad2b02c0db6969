#include "cli/lib/program_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "base/file_io.h"
#include "compiler/library.h"
#include "model/workcell/cell_file.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace rs::cli {

compiler::Target defaultTarget() {
  return {std::string(stdlib::rhinoScaraName()), stdlib::rhinoScaraMotors(), vm::kDefaultCallDepth};
}

const diag::SourceFile* LoadedProgram::sourceOf(const std::string& file) const {
  if (source && source->name() == file) return &*source;
  return descriptions ? descriptions->source(file) : nullptr;
}

void printDiagnostics(std::ostream& err, const std::vector<diag::Diagnostic>& diags, const LoadedProgram& program) {
  for (const diag::Diagnostic& d : diags) err << diag::render(d, program.sourceOf(d.file));
}

bool loadStimuli(const std::string& file, const std::vector<std::string>& inputs, runtime::Stimuli& stimuli,
                 std::vector<diag::Diagnostic>& diags) {
  bool ok = true;
  const auto add = [&](const runtime::StimuliError& e) {
    diags.push_back({e.file, {static_cast<std::uint32_t>(e.line), static_cast<std::uint32_t>(e.column)},
                     diag::Severity::Error, e.message});
    ok = false;
  };
  if (!file.empty()) {
    runtime::StimuliParse parsed = runtime::loadStimuliFile(file);
    for (const auto& e : parsed.errors) add(e);
    stimuli = std::move(parsed.stimuli);
  }
  for (const std::string& arg : inputs) {
    runtime::StimulusArgParse parsed = runtime::parseStimulusArg(arg, "--input");
    if (parsed.error) add(*parsed.error);
    if (parsed.change) stimuli.changes.push_back(*parsed.change);
  }
  return ok;
}

std::string decodeImageCell(const vm::Image& image, std::optional<workcell::Workcell>& cell) {
  workcell::CellDecode decoded = workcell::decodeCell(image.cell);
  if (!decoded.cell) return decoded.error;
  if (decoded.cell->robots.empty()) return "its cell has no robot";
  if (compiler::motorTable(decoded.cell->robots.front().robot) != image.motors)
    return "its cell's robot does not match its motor table";
  cell = std::move(decoded.cell);
  return {};
}

compiler::Target cellTarget(const workcell::Workcell& cell) {
  const workcell::Robot& robot = cell.robots.front().robot;
  return {robot.name, compiler::motorTable(robot), vm::kDefaultCallDepth};
}

LoadedProgram loadProgram(const std::string& path, const compiler::Target& target) {
  LoadedProgram result;
  base::FileRead read = base::readFile(path, kMaxInputBytes);
  if (!read.bytes) {
    result.diagnostics.push_back({path, {}, diag::Severity::Error, "cannot read file: " + read.error});
    return result;
  }
  std::optional<std::string>& bytes = read.bytes;
  if (vm::looksLikeImage(*bytes)) {
    vm::LoadResult loaded = vm::loadImage(*bytes);
    if (!loaded.error.empty())
      result.diagnostics.push_back({path, {}, diag::Severity::Error, loaded.error});
    else
      result.image = std::move(loaded.image);
    return result;
  }
  result.source.emplace(path, std::move(*bytes));
  compiler::CompileResult compiled = compiler::compile(*result.source, target);
  result.image = std::move(compiled.image);
  result.diagnostics = std::move(compiled.diagnostics);
  return result;
}

}  // namespace rs::cli
