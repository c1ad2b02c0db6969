#include "cli/lib/program_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "compiler/library.h"
#include "runtime/workcell/cell_file.h"
#include "stdlib/default_robot.h"
#include "vm/image_file.h"

namespace rs::cli {

std::optional<std::string> readFile(const std::string& path, std::string& error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = "is a directory";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  std::string text;
  // Regular files: one allocation of the right size (growing by doubling
  // would copy a large program several times). Pipes and devices: as read.
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size <= kMaxInputBytes) text.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxInputBytes) {
      error = fmt::format("file is larger than {} MiB", kMaxInputBytes >> 20);
      return std::nullopt;
    }
  }
  if (in.bad()) {
    error = "read error";
    return std::nullopt;
  }
  return text;
}

bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      error = std::strerror(errno);
      return false;
    }
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      error = "write error";
      std::remove(tmp.c_str());
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    error = ec.message();
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

compiler::Target defaultTarget() {
  return {std::string(stdlib::rhinoScaraName()), stdlib::rhinoScaraMotors(), vm::kDefaultCallDepth};
}

const compiler::SourceFile* LoadedProgram::sourceOf(const std::string& file) const {
  if (source && source->name() == file) return &*source;
  return descriptions ? descriptions->source(file) : nullptr;
}

void printDiagnostics(std::ostream& err, const std::vector<compiler::Diagnostic>& diags, const LoadedProgram& program) {
  for (const compiler::Diagnostic& d : diags) err << compiler::render(d, program.sourceOf(d.file));
}

bool loadStimuli(const std::string& file, const std::vector<std::string>& inputs, runtime::Stimuli& stimuli,
                 std::vector<compiler::Diagnostic>& diags) {
  bool ok = true;
  const auto add = [&](const runtime::StimuliError& e) {
    diags.push_back({e.file, {static_cast<std::uint32_t>(e.line), static_cast<std::uint32_t>(e.column)},
                     compiler::Severity::Error, e.message});
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
  std::string error;
  std::optional<std::string> bytes = readFile(path, error);
  if (!bytes) {
    result.diagnostics.push_back({path, {}, compiler::Severity::Error, "cannot read file: " + error});
    return result;
  }
  if (vm::looksLikeImage(*bytes)) {
    vm::LoadResult loaded = vm::loadImage(*bytes);
    if (!loaded.error.empty())
      result.diagnostics.push_back({path, {}, compiler::Severity::Error, loaded.error});
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
