// URDF files in the editor: the reader's diagnostics at the XML lines of an
// open .urdf document (its text as the editor holds it), and the D-H table
// of the robot a program's `; cell:` directive names, shown on hover over
// the name (any cell; a URDF robot's also says where it came from).
#include <fmt/format.h>

#include "base/number_text.h"
#include "compiler/description/library.h"
#include "tools/lsp/features/features.h"
#include "tools/lsp/protocol.h"
#include "tools/lsp/uri.h"

namespace rs::lsp {

using base::formatNumber;

Json urdfDiagnostics(const Document& doc, Encoding enc, const std::vector<std::filesystem::path>& searchPath) {
  const std::string path = pathOfUri(doc.uri());
  if (path.empty()) return Json::array();
  compiler::Library library(searchPath);
  library.overlay(path, doc.text());
  (void)library.robot(path);
  return fileDiagnosticsJson(doc, enc, library.diagnostics(), path);
}

std::string cellTableHover(const ProgramContext& p) {
  const CellContext& cell = p.analysis.cell();
  if (!cell.cell || !cell.robot || !cell.robot->robot.chain) return {};
  const workcell::Robot& robot = cell.robot->robot;
  std::string out = fmt::format("cell `{}`: robot **{}**", cell.name, robot.name);
  if (robot.urdf)
    out += fmt::format(", from URDF file `{}` (root link `{}`, tip link `{}`)", robot.urdf->file, robot.urdf->rootLink,
                       robot.urdf->tipLink);
  out += "\n\n| axis | type | θ | α | a | d | home |\n|---|---|---|---|---|---|---|\n";
  const std::vector<kinematics::DhRow> rows = robot.chain->table();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const kinematics::DhRow& r = rows[i];
    const bool revolute = r.type == kinematics::JointType::Revolute;
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", i + 1, kinematics::jointTypeName(r.type),
                       revolute ? fmt::format("θ{}", i + 1) : formatNumber(r.theta), formatNumber(r.alpha),
                       formatNumber(r.a), revolute ? formatNumber(r.d) : fmt::format("d{}", i + 1), formatNumber(r.home()));
  }
  if (robot.chain->hasTool()) out += "\nand a tool frame in the last frame (`robotsim table` prints it)";
  return out;
}

}  // namespace rs::lsp
