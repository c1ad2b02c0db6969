#include "runtime/run/empty_close.h"

#include <fmt/format.h>

#include <array>
#include <vector>

#include "base/number_text.h"
#include "base/text.h"

namespace rs::runtime {

namespace {

// Offsets in the trace: 2 decimals at most.
std::string number(double v) { return base::formatNumber(v, 2); }

// "A", "A and B", "A, B and C".
std::string joined(const std::vector<std::string>& parts) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i)
    s += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return s;
}

// The offset's parts that do not round to 0, the vertical (y) first: it is
// the usual mistake (a grasp too high or too low). `up` and `down` name
// the vertical directions; x and z are "towards +x" and so on.
std::vector<std::string> parts(const Eigen::Vector3d& d, const char* up, const char* down, bool& horizontal) {
  std::vector<std::string> out;
  horizontal = false;
  if (number(d.y()) != "0") out.push_back(fmt::format("{} {}", number(std::abs(d.y())), d.y() > 0 ? up : down));
  for (const int axis : {0, 2}) {
    if (number(d[axis]) == "0") continue;
    out.push_back(fmt::format("{} towards {}{}", number(std::abs(d[axis])), d[axis] > 0 ? '+' : '-', axis == 0 ? 'x' : 'z'));
    horizontal = true;
  }
  return out;
}

std::string pointText(const Eigen::Vector3d& p) {
  return fmt::format("({}, {}, {})", number(p.x()), number(p.y()), number(p.z()));
}

std::string objectName(const workcell::Workcell& cell, std::size_t o) {
  return fmt::format("{} (object {})", base::safeText(cell.objects[o].shape.name), o + 1);
}

}  // namespace

std::string moveText(const Eigen::Vector3d& offset) {
  bool horizontal = false;
  return joined(parts(offset, "up", "down", horizontal));
}

std::string emptyCloseText(const EmptyClose& e, const workcell::Workcell& cell) {
  if (!e.nearest) return {};
  bool horizontal = false;
  const std::vector<std::string> p = parts(e.centre - e.tcp, "above", "below", horizontal);
  const std::string where = p.empty() ? std::string("at the tool centre point")
                                      : fmt::format("{}{} the tool centre point", joined(p), horizontal ? " of" : "");
  return fmt::format("nearest: {}, its centre {}, which is {} outside its box", objectName(cell, *e.nearest), where,
                     number(e.distance));
}

std::optional<diag::Diagnostic> gripperWarning(const Run& run, const std::string& file) {
  const World* world = run.rig().world();
  const auto first = run.rig().firstEmptyClose();
  if (!world || !first || world->takeCount() > 0) return std::nullopt;
  const vm::Image& image = *run.spec().image;
  const std::uint32_t index = first->first;
  const EmptyClose& e = first->second;
  const std::uint64_t closes = world->closeCount();
  const std::string nearest = emptyCloseText(e, world->cell());
  std::string hint = "a closing gripper takes the object whose box holds the tool centre point when the move ends";
  if (e.nearest) {
    const std::string move = moveText(e.centre - e.tcp);
    if (!move.empty())
      hint += fmt::format(": move it {} to reach the centre of {}", move, objectName(world->cell(), *e.nearest));
  }
  hint += "; robotsim where CELL --encoders ... shows where a point puts it";
  return diag::Diagnostic{
      file,
      {image.lines[index], image.columns[index]},
      diag::Severity::Warning,
      fmt::format("the gripper closed {} but never took an object; here it closed on nothing with the tool centre "
                  "point at {}{}",
                  closes == 1 ? std::string("once") : fmt::format("{} times", closes), pointText(e.tcp),
                  nearest.empty() ? "" : " (" + nearest + ")"),
      "gripper-took-nothing",
      hint};
}

}  // namespace rs::runtime
