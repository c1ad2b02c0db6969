#include "tools/teach/point_target.h"

#include <fmt/format.h>

#include "compiler/program/compiler.h"
#include "diag/source_file.h"
#include "launch/program.h"
#include "vm/opcodes.h"

namespace rs::teach {

PointTarget pointTarget(const PointsText& points, std::size_t index, const workcell::Workcell& cell) {
  PointTarget t;
  const PointRow& row = points.points()[index];
  if (!row.pose) {
    if (row.readable) t.values = row.values;
    else t.error = fmt::format("point {} (line {}) has a value that is not a whole number", row.name, row.line + 1);
    return t;
  }
  // The program MOVEP would be: a MOVEP to the point, then the rows up to
  // it. `fileLine` takes each line of that program back to the file's.
  std::string source = fmt::format("        MOVEP {}\n        END\nPOINTS\n", row.name);
  std::vector<std::size_t> fileLine = {0, 0, 0, 0};  // 1-based; 0: not the file's
  for (std::size_t i = 0; i <= index; ++i) {
    source += points.rowText(i);
    source += '\n';
    fileLine.push_back(points.points()[i].line + 1);
  }
  const compiler::CompileResult r =
      compiler::compile(diag::SourceFile("<points>", std::move(source)), launch::cellTarget(cell));
  if (!r.ok()) {
    for (const diag::Diagnostic& d : r.diagnostics) {
      if (d.severity != diag::Severity::Error) continue;
      const std::size_t line = d.pos.line < fileLine.size() ? fileLine[d.pos.line] : 0;
      t.error = line ? fmt::format("{} (line {})", d.message, line) : d.message;
      return t;
    }
    t.error = fmt::format("point {} (line {}) cannot be resolved", row.name, row.line + 1);
    return t;
  }
  const vm::Image& image = *r.image;
  t.values = image.points[image.code[0].b].values;
  t.keepsGripper = (image.code[0].a & vm::kPointKeepsGripper) != 0;
  return t;
}

}  // namespace rs::teach
