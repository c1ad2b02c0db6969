#include "tools/cli/lib/cell_programs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "base/text.h"
#include "tools/cli/lib/cell_run_command.h"
#include "tools/cli/lib/exit_codes.h"

namespace rs::cli {
namespace {

struct CellProgram {
  std::string label;
  std::string file;
};

// The cell's robots that name a PROGRAM, in the cell's order; an empty
// list with the reason printed when there are none (or the cell is bad).
std::optional<std::vector<CellProgram>> programsOf(const launch::ProgramRequest& request, std::ostream& err) {
  if (request.cell.empty()) {
    err << "robotsim: error: which program? give a program file, or --cell CELL to take every PROGRAM its ROBOT "
           "lines name\n";
    return std::nullopt;
  }
  launch::LoadedProgram loading;
  const std::shared_ptr<const workcell::Workcell> cell = launch::loadCell(request, loading);
  if (!cell || diag::hasErrors(loading.diagnostics)) {
    launch::printDiagnostics(err, loading.diagnostics, loading);
    return std::nullopt;
  }
  std::vector<CellProgram> out;
  for (const workcell::PlacedRobot& r : cell->robots)
    if (!r.program.empty()) out.push_back({r.labelOf(), r.program});
  if (out.empty()) {
    err << fmt::format("{}: error: no ROBOT line of workcell {} names a PROGRAM\n  hint: give the program file "
                       "(robotsim check PROG --cell CELL), or write PROGRAM FILE on a ROBOT line\n",
                       base::safeText(request.cell), base::safeText(cell->name));
    return std::nullopt;
  }
  return out;
}

}  // namespace

int checkCellPrograms(const RunCommandOptions& o, std::ostream& out, std::ostream& err) {
  // Every program compiles: they are checked running together, on one clock.
  if (const std::optional<int> code = runCellIfSeveral(o, true, out, err)) return *code;
  const auto programs = programsOf(o.program, err);
  if (!programs) return kExitBadInput;
  const bool json = o.format == "json";
  nlohmann::ordered_json robots = nlohmann::ordered_json::array();
  int worst = kExitOk;
  for (const CellProgram& p : *programs) {
    RunCommandOptions one = o;
    one.program.file = p.file;
    one.program.robot = p.label;
    std::ostringstream summary;
    if (!json) out << fmt::format("robot {}: {}\n", base::safeText(p.label), base::safeText(p.file));
    const int code = runOrCheck(one, true, json ? summary : out, err);
    worst = std::max(worst, code);
    if (!json) continue;
    nlohmann::ordered_json entry = {{"name", p.label}, {"program", p.file}};
    const auto parsed = nlohmann::ordered_json::parse(summary.str(), nullptr, false);
    if (parsed.is_object())
      for (const auto& [key, value] : parsed.items()) entry[key] = value;
    robots.push_back(std::move(entry));
  }
  if (json) out << nlohmann::ordered_json{{"robots", robots}}.dump(-1, ' ', false,
                                                                    nlohmann::json::error_handler_t::replace)
                << '\n';
  return worst;
}

int compileCellPrograms(const ProgramCommandOptions& o, std::ostream& out, std::ostream& err) {
  const auto programs = programsOf(o.program, err);
  if (!programs) return kExitBadInput;
  std::error_code ec;
  if (o.output.empty() || o.output == "-") {
    err << "-o: error: compiling every program of a cell writes one image each: -o names a folder\n";
    return kExitBadInput;
  }
  std::filesystem::create_directories(o.output, ec);
  if (ec || !std::filesystem::is_directory(o.output, ec)) {
    err << fmt::format("{}: error: not a folder to write the images into\n  hint: -o names a folder when compile "
                       "takes every PROGRAM of --cell\n",
                       base::safeText(o.output));
    return kExitBadInput;
  }
  int worst = kExitOk;
  for (const CellProgram& p : *programs) {
    ProgramCommandOptions one = o;
    one.program.file = p.file;
    one.program.robot = p.label;
    one.output = (std::filesystem::path(o.output) / std::filesystem::path(p.file).stem()).string() + ".rsb";
    worst = std::max(worst, compileCommand(one, out, err));
  }
  return worst;
}

}  // namespace rs::cli
