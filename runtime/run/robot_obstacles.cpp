#include "runtime/run/robot_obstacles.h"

#include <fmt/format.h>

#include <algorithm>

namespace rs::runtime {

// One other robot: its own collision model (its parts in the order of
// robotBodies()), a workspace to pose it, and per motor how far a point of
// it, or of a part it carries, moves per count.
struct RobotObstacles::Other {
  Other(const workcell::Workcell& cell, std::size_t robot, double carried)
      : index(robot), model(cell, robot), data(model), weights(model.motorWeights().size()) {
    model.motorWeightsCarrying(carried, weights);
  }
  std::size_t index;
  workcell::CollisionModel model;
  workcell::CollisionData data;
  std::vector<double> weights;
  const SimMachine* machine = nullptr;
  std::vector<std::int32_t> motors;
};

RobotObstacles::RobotObstacles(const workcell::Workcell& cell, std::size_t robot) : view_(cell) {
  first_ = view_.objects.size();
  const double carried = workcell::carriedReach(cell);
  const workcell::CollisionModel self(cell, robot);
  for (std::size_t r = 0; r < cell.robots.size(); ++r) {
    if (r == robot || !cell.robots[r].robot.chain) continue;
    auto other = std::make_unique<Other>(cell, r, carried);
    if (self.movable() && (self.baseOrigin() - other->model.baseOrigin()).norm() >
                              self.reachCarrying(carried) + other->model.reachCarrying(carried))
      continue;  // they never meet
    const workcell::Robot& body = cell.robots[r].robot;
    const std::string& label = cell.robots[r].labelOf();
    for (const workcell::CollisionBody& b : other->model.robotBodies()) {
      const workcell::Shape* shape = nullptr;
      switch (b.ref.kind) {
        case workcell::BodyKind::Link: shape = &body.links[static_cast<std::size_t>(b.ref.index)]; break;
        case workcell::BodyKind::GripperBase: shape = &body.gripper.base; break;
        case workcell::BodyKind::Finger2: shape = &body.gripper.finger2; break;
        case workcell::BodyKind::Finger3: shape = &body.gripper.finger3; break;
        default: break;
      }
      workcell::PlacedObject part(shape ? *shape : workcell::Shape{}, cell.robots[r].F_world_design);
      part.kind = workcell::ObjectKind::Fixture;
      part.robotPart = fmt::format("{} of robot '{}'", other->model.describe(b.ref), label);
      view_.objects.push_back(std::move(part));
    }
    other->motors.assign(body.joints.size() + (body.hasGripper ? 1 : 0), 0);
    others_.push_back(std::move(other));
  }
}

RobotObstacles::~RobotObstacles() = default;

void RobotObstacles::machine(std::size_t r, const SimMachine* machine) {
  for (auto& o : others_)
    if (o->index == r) o->machine = machine;
}

double RobotObstacles::travel(vm::Micros t0, vm::Micros t1) {
  double most = 0;
  for (const auto& o : others_) {
    if (!o->machine) continue;
    double moved = 0;
    for (std::size_t m = 0; m < o->weights.size() && m < o->machine->motors().size(); ++m)
      moved += o->weights[m] * static_cast<double>(o->machine->coveredBetween(m, t0, t1));
    most = std::max(most, moved);
  }
  return most;
}

std::span<const std::int32_t> RobotObstacles::motorsAt(std::size_t robot, vm::Micros t) {
  for (auto& o : others_)
    if (o->index == robot && o->machine) {
      for (std::size_t m = 0; m < o->motors.size() && m < o->machine->motors().size(); ++m)
        o->motors[m] = o->machine->positionAt(m, t);
      return o->motors;
    }
  return {};
}

void RobotObstacles::pose(vm::Micros at, std::span<Eigen::Isometry3d> poses) {
  std::size_t next = 0;
  for (auto& o : others_) {
    if (o->machine)
      for (std::size_t m = 0; m < o->motors.size() && m < o->machine->motors().size(); ++m)
        o->motors[m] = o->machine->positionAt(m, at);
    o->data.poseOnly(o->motors);
    for (std::size_t b = 0; b < o->model.robotBodies().size() && next < poses.size(); ++b, ++next)
      poses[next] = o->data.robotPose(b);
  }
}

}  // namespace rs::runtime
