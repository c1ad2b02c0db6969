#include "runtime/run/placing.h"

#include <fmt/format.h>

#include <cmath>

#include "base/number_text.h"
#include "base/text.h"

namespace rs::runtime {

namespace {

std::string placingNumber(double v) { return base::formatNumber(v, 2); }

diag::Pos placingPos(const vm::Image& image, std::uint32_t index) {
  return index < image.lines.size() ? diag::Pos{image.lines[index], image.columns[index]} : diag::Pos{};
}

}  // namespace

std::string objectText(const workcell::Workcell& cell, std::size_t o, std::uint32_t number) {
  return fmt::format("{} (object {})", base::safeText(cell.objects[o].shape.name), number ? number : o + 1);
}

std::string supportText(const GraspEvent& e, const workcell::Workcell& cell) {
  switch (e.on) {
    case workcell::Settled::On::Object: return objectText(cell, e.support, e.supportNumber);
    case workcell::Settled::On::Belt: return "the belt of " + objectText(cell, e.support, e.supportNumber);
    case workcell::Settled::On::Floor: return "the floor";
    case workcell::Settled::On::Nothing: break;
  }
  return "nothing";
}

std::string settleText(const GraspEvent& e, const workcell::Workcell& cell) {
  if (!e.settled()) return "stays where it was let go: nothing under it";
  const std::string on = "settles on " + supportText(e, cell);
  if (placingNumber(e.drop) == "0") return on;
  return e.drop > 0 ? fmt::format("{}, dropped {}", on, placingNumber(e.drop))
                    : fmt::format("{}, raised {} out of it", on, placingNumber(-e.drop));
}

std::string fixtureCloseText(const EmptyClose& e, const workcell::Workcell& cell) {
  return fmt::format("closes round {}, a fixture: takes nothing", e.fixture ? objectText(cell, *e.fixture) : "?");
}

std::string longDropText(const GraspEvent& e, const workcell::Workcell& cell) {
  return fmt::format("{} dropped {} onto {}: it was let go above it", objectText(cell, e.object, e.number), placingNumber(e.drop),
                     supportText(e, cell));
}

std::vector<diag::Diagnostic> placingWarnings(const Run& run, const std::string& file) {
  std::vector<diag::Diagnostic> out;
  const World* world = run.rig().world();
  if (!world) return out;
  const vm::Image& image = *run.spec().image;
  const workcell::Workcell& cell = world->cell();
  for (const auto& [index, e] : run.rig().fixtureCloses())
    out.push_back({file, placingPos(image, index), diag::Severity::Warning,
                   fmt::format("the gripper closed round {}, a fixture, and took nothing: fixtures are never taken",
                               e.fixture ? objectText(cell, *e.fixture) : "?"),
                   "gripper-closed-on-fixture",
                   "only a PART is taken: put the tool centre point inside the part's box when the gripper closes"});
  for (const auto& [index, e] : run.rig().longDrops())
    out.push_back({file, placingPos(image, index), diag::Severity::Warning, longDropText(e, cell), "part-dropped",
                   fmt::format("open the gripper with the part on its support: {} lower", placingNumber(e.drop))});
  return out;
}

}  // namespace rs::runtime
