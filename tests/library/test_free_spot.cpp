// Every library workcell leaves a free spot on its table, pallet or
// conveyor that its robot can reach and put a block down on (issue 24).
// For each cell the test searches the tops of those objects on a grid for
// a place where a block (the library's, 40 on a side) would stand on the
// object (workcell::supportOf, what `describe` says), then asks the pose
// solver (the one points written as poses use) for the tool centre point
// at the block's centre, approach straight down, and checks that pose with
// the block held there against everything in the cell (the collision
// model the run uses, the new block added where it would rest): the robot
// can put it down without a collision. The search and the checks are the
// test's own; only the solver and the contact check are the product's.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compiler/description/library.h"
#include "model/workcell/collision_model.h"
#include "model/workcell/pose_solver.h"
#include "model/workcell/support.h"

namespace {

namespace fs = std::filesystem;
using rs::workcell::PlacedObject;
using rs::workcell::Workcell;

const fs::path kFreeSpotStdlib = fs::path(ROBOTSIM_SOURCE_DIR) / "stdlib";

std::vector<std::string> freeSpotCellNames() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kFreeSpotStdlib / "workcells"))
    if (e.path().extension() == ".rsd") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A table or a pallet, as the issue asks; a cell with neither (adept-cell:
// two conveyors) puts the block down on a conveyor's belt.
bool isWorkSurface(const Workcell& cell, const std::string& name) {
  const bool tableOrPallet = std::any_of(cell.objects.begin(), cell.objects.end(), [](const PlacedObject& o) {
    return o.shape.name == "table" || o.shape.name == "pallet";
  });
  return tableOrPallet ? name == "table" || name == "pallet" : name == "conveyor";
}

// The heights of a shape's level lines (both ends at one y) in the world:
// where a box can stand on it (supportOf decides whether it does).
std::vector<double> levelHeights(const PlacedObject& o) {
  std::vector<double> ys;
  for (const rs::workcell::Segment& s : o.shape.segments) {
    const Eigen::Vector3d a = o.F_world_design * s.a, b = o.F_world_design * s.b;
    if (std::abs(a.y() - b.y()) < 1e-9) ys.push_back(std::round(a.y() * 1e6) / 1e6);
  }
  std::sort(ys.begin(), ys.end());  // lowest first: a belt before its side guides' tops
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  return ys;
}

struct FreeSpot {
  std::size_t support = 0;
  Eigen::Vector3d centre;
  std::vector<std::int32_t> encoders;
};

// Can the robot hold a block with its centre at the tool centre point
// at `encoders` without a collision, the block resting at `blockPose`?
bool putsDownCleanly(const Workcell& cell, const PlacedObject& block, const Eigen::Isometry3d& blockPose,
                     const std::vector<std::int32_t>& encoders) {
  Workcell withBlock = cell;
  withBlock.objects.push_back({block.shape, blockPose});
  const std::size_t added = withBlock.objects.size() - 1;
  const rs::workcell::CollisionModel model(withBlock);
  rs::workcell::CollisionData data(model);
  std::vector<Eigen::Isometry3d> poses;
  for (const PlacedObject& o : withBlock.objects) poses.push_back(o.F_world_design);
  rs::workcell::CollisionQuery query;
  query.objectPoses = poses;
  query.exempt = added;
  if (data.findContact(encoders, query)) return false;  // the arm itself, the block only standing there
  query.held = added;
  query.heldOffset = data.toolFrame().inverse() * blockPose;
  return !data.findContact(encoders, query);
}

std::optional<FreeSpot> findFreeSpot(const Workcell& cell) {
  const auto blockAt = std::find_if(cell.objects.begin(), cell.objects.end(),
                                    [](const PlacedObject& o) { return o.shape.name == "block"; });
  if (blockAt == cell.objects.end()) return std::nullopt;
  const PlacedObject& block = *blockAt;
  const Eigen::AlignedBox3d local = rs::workcell::boundsOf(block.shape);
  const Eigen::Vector3d size = local.sizes();
  const rs::workcell::PlacedRobot& robot = cell.robots.front();
  const rs::workcell::PoseSolver solver(robot);
  const std::vector<std::int32_t> home(solver.motorCount(), 0);
  const double step = size.x() / 2;
  for (std::size_t s = 0; s < cell.objects.size(); ++s) {
    if (!isWorkSurface(cell, cell.objects[s].shape.name)) continue;
    const Eigen::AlignedBox3d top = rs::workcell::worldBoxOf(cell.objects[s].shape, cell.objects[s].F_world_design);
    for (double y : levelHeights(cell.objects[s]))
      for (double x = top.min().x(); x + size.x() <= top.max().x() + 1e-9; x += step)
        for (double z = top.min().z(); z + size.z() <= top.max().z() + 1e-9; z += step) {
          // The block unturned, its box's least corner at (x, y, z).
          const Eigen::Isometry3d pose(Eigen::Translation3d(Eigen::Vector3d(x, y, z) - local.min()));
          const Eigen::AlignedBox3d box = rs::workcell::worldBoxOf(block.shape, pose);
          const rs::workcell::Support on = rs::workcell::supportOf(box, cell.objects);
          if (on.kind != rs::workcell::Support::Kind::Object || on.object != s) continue;
          rs::workcell::PoseRequest request;
          request.position = box.center();
          request.approach = Eigen::Vector3d(0, -1, 0);
          if (robot.robot.hasGripper) request.grip = robot.robot.gripper.max;  // closed on the block
          rs::workcell::PoseResult solved = solver.solve(request, home);
          if (!solved.ok()) {  // an arm that does not turn its tool (a gantry, a SCARA's fixed approach)
            request.approach.reset();
            solved = solver.solve(request, home);
          }
          if (!solved.ok()) continue;
          if (!putsDownCleanly(cell, block, pose, solved.encoders)) continue;
          return FreeSpot{s, box.center(), solved.encoders};
        }
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("Every library workcell has a free spot its robot can reach and put a block down on", "[library][free-spot][slow]") {
  const std::vector<std::string> names = freeSpotCellNames();
  REQUIRE(names.size() >= 8);
  for (const std::string& name : names) {
    DYNAMIC_SECTION(name) {
      rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
      const std::optional<Workcell> cell = lib.workcell(name);
      REQUIRE(cell);
      const std::optional<FreeSpot> spot = findFreeSpot(*cell);
      INFO(name << ": no place on a table, pallet or conveyor where the robot can put a block down");
      REQUIRE(spot);
      // The spot found is where the solver put the tool: the forward
      // kinematics of the encoders (through the collision model's pose)
      // bring the tool centre point to the block's centre, pointing down.
      const rs::workcell::CollisionModel model(*cell);
      rs::workcell::CollisionData data(model);
      std::vector<Eigen::Isometry3d> poses;
      for (const PlacedObject& o : cell->objects) poses.push_back(o.F_world_design);
      rs::workcell::CollisionQuery query;
      query.objectPoses = poses;
      (void)data.findContact(spot->encoders, query);
      const Eigen::Isometry3d tool = data.toolFrame();
      INFO("spot centre " << spot->centre.transpose() << ", tool at " << tool.translation().transpose());
      CHECK((tool.translation() - spot->centre).norm() < 1.0);  // within the rounding to whole encoder counts
      CHECK(tool.linear().col(2).dot(Eigen::Vector3d(0, -1, 0)) > 0.99);
    }
  }
}

TEST_CASE("The free-spot search fails where there is none: scara-pick without its pallet", "[library][free-spot]") {
  // The SCARA stands on the table (frame 0 at y 750) and joint C takes the
  // tool centre point down to y 798 at most (encoder 350 x 0.12 below its
  // home 840): a block on the table would have its centre at 770, out of
  // reach. Only the pallet's deck (y 780, centres at 800) lifts a block
  // within reach, so without the pallet there is no spot.
  rs::compiler::Library lib(rs::compiler::librarySearchPath({}));
  std::optional<Workcell> cell = lib.workcell("scara-pick");
  REQUIRE(cell);
  REQUIRE(findFreeSpot(*cell));
  const auto pallet = std::find_if(cell->objects.begin(), cell->objects.end(),
                                   [](const PlacedObject& o) { return o.shape.name == "pallet"; });
  REQUIRE(pallet != cell->objects.end());
  // The blocks stay (a block is the shape the search puts down); they float
  // where the pallet was, which the search does not mind.
  cell->objects.erase(pallet);
  CHECK_FALSE(findFreeSpot(*cell));
}
