#include "runtime/render/scene.h"

#include <algorithm>

#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/gripper.h"
#include "model/kinematics/joint_values.h"

namespace rs::render {

namespace {

void addShape(std::vector<Line3>& out, const workcell::Shape& shape, const Eigen::Isometry3d& T, Part part) {
  for (const workcell::Segment& s : shape.segments) out.push_back({T * s.a, T * s.b, s.color, part});
}

void addAxes(std::vector<Line3>& out, const Eigen::Isometry3d& F, int robot, int frame, double length) {
  const Eigen::Vector3d o = F.translation();
  for (int k = 0; k < 3; ++k)
    out.push_back({o, o + length * F.linear().col(k), kAxisColors[k], {PartKind::Axis, robot, frame, k}});
}

}  // namespace

CellPoser::CellPoser(const workcell::Workcell& cell)
    : cell_(&cell), robots_(cell.robots.size()), sensorsOn_(cell.devices.sensors.size(), false) {
  for (const workcell::PlacedObject& o : cell.objects) objects_.push_back(o.F_world_design);
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    const workcell::PlacedRobot& placed = cell.robots[r];
    RobotState& s = robots_[r];
    const Eigen::Isometry3d F_design_0 =
        placed.robot.frames.empty() ? Eigen::Isometry3d::Identity() : placed.robot.frames.front();
    const Eigen::Isometry3d F_world_0 = placed.F_world_design * F_design_0;
    if (placed.robot.chain) {
      s.chain.emplace(placed.robot.chain->placedAt(F_world_0));
      s.data.emplace(*s.chain);  // filled with the home pose
    }
    const std::size_t frames = s.chain ? static_cast<std::size_t>(s.chain->size()) + 1 : 1;
    s.F_world_i.assign(frames, F_world_0);
    s.M.assign(frames, Eigen::Isometry3d::Identity());
    std::size_t motors = frames - 1 + (placed.robot.hasGripper ? 1 : 0);
    s.encoders.assign(motors, 0);
    s.q.assign(frames - 1, 0.0);
    pose(r);
    for (std::size_t i = 0; i < frames; ++i) s.M[i] = s.F_world_i[i].inverse(Eigen::Isometry) * placed.F_world_design;
  }
  std::vector<Line3> home;
  lines(home);
  homePoints_.reserve(2 * home.size());
  for (const Line3& l : home) homePoints_.push_back(l.a), homePoints_.push_back(l.b);
}

void CellPoser::setEncoders(std::size_t robot, std::span<const std::int32_t> encoders) {
  RobotState& s = robots_[robot];
  for (std::size_t i = 0; i < s.encoders.size(); ++i) s.encoders[i] = i < encoders.size() ? encoders[i] : 0;
  pose(robot);
}

void CellPoser::pose(std::size_t robot) {
  RobotState& s = robots_[robot];
  if (!s.chain) return;
  if (!kinematics::jointValuesFromEncoders(*s.chain, std::span<const std::int32_t>(s.encoders), s.q)) return;
  if (!kinematics::forwardKinematics(*s.chain, *s.data, s.q)) return;
  for (std::size_t i = 0; i < s.F_world_i.size(); ++i) s.F_world_i[i] = s.chain->F_world_0() * s.data->F_0_i[i];
}

bool CellPoser::hasToolMark(std::size_t robot) const {
  const workcell::Robot& r = cell_->robots[robot].robot;
  return r.chain && (r.chain->size() > 0 || r.hasGripper);
}

void CellPoser::lines(std::vector<Line3>& out, double axisLength) const {
  out.clear();
  for (std::size_t r = 0; r < robots_.size(); ++r) {
    const RobotState& s = robots_[r];
    const workcell::Robot& robot = cell_->robots[r].robot;
    const int owner = static_cast<int>(r);
    const std::size_t last = s.F_world_i.size() - 1;
    for (std::size_t i = 0; i < robot.links.size(); ++i) {
      const std::size_t f = std::min(i, last);
      addShape(out, robot.links[i], s.F_world_i[f] * s.M[f], {PartKind::Link, owner, static_cast<int>(i)});
    }
    if (robot.hasGripper) {
      const Eigen::Isometry3d T = s.F_world_i[last] * s.M[last];
      const double encoder = s.encoders.empty() ? 0.0 : s.encoders.back();
      const kinematics::FingerTransforms fingers = kinematics::fingerTransforms(robot.gripper.model, encoder);
      const int n = static_cast<int>(last);
      addShape(out, robot.gripper.base, T, {PartKind::GripperBase, owner, n});
      addShape(out, robot.gripper.finger2, T * fingers.finger2, {PartKind::Finger2, owner, n});
      addShape(out, robot.gripper.finger3, T * fingers.finger3, {PartKind::Finger3, owner, n});
    }
    if (axisLength > 0)
      for (std::size_t i = 0; i <= last; ++i) addAxes(out, s.F_world_i[i], owner, static_cast<int>(i), axisLength);
  }
  for (std::size_t o = 0; o < cell_->objects.size(); ++o) {
    const workcell::PlacedObject& object = cell_->objects[o];
    if (objects_[o].translation().y() < kNotInCellBelow) continue;
    addShape(out, object.shape, objects_[o], {PartKind::Object, static_cast<int>(o), 0});
  }
  for (std::size_t s = 0; s < sensorsOn_.size(); ++s) {
    if (!sensorsOn_[s]) continue;
    const workcell::Sensor& sensor = cell_->devices.sensors[s];
    const Part part{PartKind::Sensor, static_cast<int>(s), 0};
    if (sensor.shape == workcell::Sensor::Shape::Beam) {
      out.push_back({sensor.a, sensor.b, kSensorOnColor, part});
      continue;
    }
    // The zone's twelve edges: from each corner, along each axis its bit is 0 in.
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 3; ++k)
        if (!(c & (1 << k)))
          out.push_back({sensor.zone.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)),
                         sensor.zone.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c | (1 << k))),
                         kSensorOnColor, part});
  }
}

}  // namespace rs::render
