// Placing robots in a workcell (issue 36): each robot's label and PROGRAM
// file, and the checks of robots at home (against the cell's objects and
// against each other), split from library.cpp as one concept.
#include <sys/stat.h>

#include <fmt/format.h>

#include "base/ascii.h"
#include "diag/read_input.h"
#include "vm/image_file.h"
#include "compiler/description/library.h"
#include "model/workcell/collision_model.h"

namespace rs::compiler {

namespace fs = std::filesystem;

// The last robot placed: its label (AS, else the description's name, one
// label per robot of the cell) and its PROGRAM, a file beside the cell's
// file (relative to its folder) that exists, is a regular file (not a
// FIFO or a device) and, links followed, stays inside that folder.
bool Library::placeRobot(const PlacementDef& p, const DescriptionFile& from, workcell::Workcell& cell) {
  workcell::PlacedRobot& r = cell.robots.back();
  r.pos = p.what.pos;
  r.label = p.as.name;
  r.labelPos = p.as.pos;
  const diag::Pos labelAt = p.as.name.empty() ? p.what.pos : p.as.pos;
  for (std::size_t i = 0; i + 1 < cell.robots.size(); ++i)
    if (base::sameName(cell.robots[i].labelOf(), r.labelOf())) {
      error(from, labelAt,
            fmt::format("a second robot labelled '{}' in this workcell (the first is at line {})", r.labelOf(),
                        cell.robots[i].pos.line),
            "give each robot its own label: ROBOT NAME AT x y z AS LABEL");
      return false;
    }
  if (p.program.name.empty()) return true;
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(fs::absolute(fs::path(from.source->name()), ec).parent_path(), ec);
  const fs::path written(p.program.name);
  const auto refuse = [&](std::string why) {
    error(from, p.program.pos, fmt::format("PROGRAM '{}' {}", p.program.name, why),
          "PROGRAM names a program file (.rsp) beside this description, relative to its folder");
    return false;
  };
  if (written.is_absolute()) return refuse("is an absolute path");
  const fs::path beside = fs::absolute(fs::path(from.source->name()), ec).parent_path() / written;
  if (!fs::exists(fs::symlink_status(beside, ec))) return refuse("does not exist");
  const fs::path target = fs::weakly_canonical(beside, ec);
  if (ec) return refuse("cannot be followed");
  const auto [f, t] = std::mismatch(folder.begin(), folder.end(), target.begin(), target.end());
  if (f != folder.end()) return refuse("leads outside the folder of this description");
  if (!fs::is_regular_file(target, ec)) return refuse("is not a regular file");
  r.program = beside.lexically_normal().string();
  r.programPos = p.program.pos;
  return programFitsRobot(r, from);
}

// A PROGRAM that is a compiled image must have been compiled for this
// robot's motors (a source is compiled for it when it runs, its errors in
// its own file).
bool Library::programFitsRobot(const workcell::PlacedRobot& r, const DescriptionFile& from) {
  constexpr std::size_t kMaxImageBytes = 64u << 20;  // as the loader's limit on a program file
  diag::Result<std::string> bytes = diag::readInput(r.program, kMaxImageBytes, "cannot read the PROGRAM");
  if (!bytes || !vm::looksLikeImage(*bytes)) return true;  // a source, or unreadable: the run says so
  const diag::Result<vm::Image> image = vm::loadImage(*bytes, r.program);
  const std::string written = fs::path(r.program).filename().string();
  if (!image) {
    error(from, r.programPos, fmt::format("PROGRAM '{}' is a damaged image: {}", written, image.failure().message),
          "compile the program again: robotsim compile PROG --cell CELL --robot LABEL");
    return false;
  }
  const std::vector<vm::MotorSpec> motors = motorTable(r.robot);
  if (image->motors == motors) return true;
  error(from, r.programPos,
        image->motors.size() != motors.size()
            ? fmt::format("PROGRAM '{}' was compiled for robot '{}' with {} motors, but robot '{}' ({}) has {}",
                          written, image->robotName, image->motors.size(), r.labelOf(), r.robot.name, motors.size())
            : fmt::format("PROGRAM '{}' was compiled for robot '{}', whose motors differ from those of robot '{}' ({})",
                          written, image->robotName, r.labelOf(), r.robot.name),
        fmt::format("compile its source for this robot: robotsim compile PROG --cell CELL --robot {}", r.labelOf()));
  return false;
}

// docs/models.md, "Collisions": a robot that overlaps something at its
// home pose is reported when its workcell is built, at its placement.
void Library::reportHomeCollisions(const workcell::Workcell& cell, const WorkcellDef& def, const DescriptionFile& from) {
  const workcell::PlacedRobot* driven = cell.drivenRobot();
  if (!driven) return;
  const std::vector<workcell::Contact> contacts = workcell::checkAtHome(cell);
  if (contacts.empty()) return;
  diag::Pos at = def.pos;
  for (const PlacementDef& p : def.placements)
    if (p.isRobot) {
      at = p.what.pos;
      break;
    }
  const workcell::CollisionModel model(cell);
  constexpr std::size_t kShown = 5;
  for (std::size_t i = 0; i < contacts.size() && i < kShown; ++i) {
    std::string message = fmt::format("robot '{}' collides at its home pose: {} overlaps {}", driven->robot.name,
                                      model.describe(contacts[i].a), model.describe(contacts[i].b));
    if (i + 1 == kShown && contacts.size() > kShown) message += fmt::format(" (and {} more)", contacts.size() - kShown);
    diagnostics_.push_back({from.source->name(), at, diag::Severity::Warning, std::move(message), "home-collision",
                            "move the robot or the object, or give the part a COLLIDE statement; "
                            "'robotsim render CELL --collision-shapes' draws what is checked"});
  }
}

// Two robots that overlap at their home poses (issue 36): each pair, the
// first robot against the second's links and gripper as if they were
// fixed objects, through the one home check (checkAtHome). A warning at
// the second robot's line naming both, so that check --strict fails it.
// Only the first kMaxRobots robots are paired: a bounded cost.
void Library::reportRobotOverlaps(const workcell::Workcell& cell, const DescriptionFile& from) {
  constexpr std::size_t kMaxRobots = 16;
  const std::size_t n = std::min(cell.robots.size(), kMaxRobots);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const workcell::PlacedRobot& a = cell.robots[i];
      const workcell::PlacedRobot& b = cell.robots[j];
      if (!a.robot.chain) continue;
      workcell::Workcell pair;
      pair.floor.reset();
      pair.robots.push_back(a);
      const auto add = [&](const workcell::Shape& shape) {
        if (!shape.collision.empty()) pair.objects.emplace_back(shape, b.F_world_design);
      };
      for (const workcell::Shape& link : b.robot.links) add(link);
      if (b.robot.hasGripper) add(b.robot.gripper.base), add(b.robot.gripper.finger2), add(b.robot.gripper.finger3);
      const workcell::CollisionModel model(pair);
      for (const workcell::Contact& c : workcell::checkAtHome(pair)) {
        if (c.b.kind != workcell::BodyKind::Object || c.a.kind == workcell::BodyKind::Object) continue;
        diagnostics_.push_back(
            {from.source->name(), b.pos, diag::Severity::Warning,
             fmt::format("robots '{}' and '{}' overlap at their home poses: {} of '{}' overlaps {} of '{}'", a.labelOf(),
                         b.labelOf(), model.describe(c.a), a.labelOf(),
                         pair.objects[static_cast<std::size_t>(c.b.index)].shape.name, b.labelOf()),
             "home-collision", "move one of the robots (its AT) so that they stand apart at home"});
        break;
      }
    }
}
}  // namespace rs::compiler
