#include "tools/teach/pendant_state.h"

#include <fmt/format.h>

#include "runtime/render/animation.h"
#include "runtime/run/rig.h"
#include "vm/io_lines.h"

namespace rs::teach {

namespace {

using Json = nlohmann::ordered_json;

using render::frameJson;

Json lines(vm::IoMask mask) {
  Json a = Json::array();
  for (int line = 1; line <= vm::kIoCount; ++line) a.push_back(vm::lineIsOn(mask, line));
  return a;
}

std::string_view kindName(vm::JointKind k) {
  switch (k) {
    case vm::JointKind::Revolute: return "revolute";
    case vm::JointKind::Prismatic: return "prismatic";
    case vm::JointKind::Gripper: return "gripper";
  }
  return "revolute";
}

Json objectPoses(const std::vector<Eigen::Isometry3d>& poses, const std::vector<Eigen::Isometry3d>& placed) {
  Json a = Json::array();
  for (std::size_t o = 0; o < poses.size() && o < placed.size(); ++o)
    a.push_back(frameJson(poses[o] * placed[o].inverse(Eigen::Isometry)));
  return a;
}

}  // namespace

std::string_view gripperName(GripperState g) {
  switch (g) {
    case GripperState::None: return "none";
    case GripperState::Open: return "open";
    case GripperState::Closed: return "closed";
    case GripperState::Between: return "between";
  }
  return "none";
}

GripperState gripperState(const std::vector<vm::MotorSpec>& motors, const std::vector<std::int32_t>& encoders) {
  for (std::size_t i = 0; i < motors.size() && i < encoders.size(); ++i)
    if (motors[i].kind == vm::JointKind::Gripper)
      return encoders[i] == motors[i].min   ? GripperState::Open
             : encoders[i] == motors[i].max ? GripperState::Closed
                                            : GripperState::Between;
  return GripperState::None;
}

void addDeviceStates(const workcell::Workcell& cell, const runtime::CellDevices* devices, PendantState& state) {
  if (!devices) return;
  for (std::size_t i = 0; i < cell.devices.sensors.size(); ++i)
    state.sensors.push_back({cell.devices.sensors[i].name, devices->sensorOn(i), devices->sensorCount(i)});
  for (std::size_t i = 0; i < cell.devices.conveyors.size(); ++i)
    state.conveyors.push_back({cell.devices.conveyors[i].name, devices->running(i), devices->carried(i)});
  for (std::size_t i = 0; i < cell.devices.feeders.size(); ++i)
    state.feeders.push_back({cell.devices.feeders[i].name, false, devices->fed(i)});
}

Json pendantJson(const PendantState& s, const std::vector<Eigen::Isometry3d>& placed) {
  Json motors = Json::array();
  for (const vm::MotorSpec& m : s.motors)
    motors.push_back({{"letter", std::string(1, m.letter)},
                      {"kind", kindName(m.kind)},
                      {"min", m.min},
                      {"max", m.max},
                      {"speed", m.speed}});
  Json objects = Json::array();
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    const PendantObject& ob = s.objects[o];
    const Eigen::Isometry3d P = o < placed.size() ? placed[o] : Eigen::Isometry3d::Identity();
    objects.push_back({{"name", ob.name},
                       {"pose", frameJson(ob.pose * P.inverse(Eigen::Isometry))},
                       {"held", ob.held},
                       {"moved", ob.moved},
                       {"present", ob.present}});
  }
  Json sensors = Json::array(), conveyors = Json::array(), feeders = Json::array();
  for (const PendantDevice& d : s.sensors) sensors.push_back({{"name", d.name}, {"on", d.on}, {"count", d.count}});
  for (const PendantDevice& d : s.conveyors)
    conveyors.push_back({{"name", d.name}, {"running", d.on}, {"carried", d.count}});
  for (const PendantDevice& d : s.feeders) feeders.push_back({{"name", d.name}, {"fed", d.count}});
  Json points = Json::array();
  for (const PendantPoint& p : s.points)
    points.push_back({{"name", p.name}, {"values", p.values}, {"line", p.line}, {"readable", p.readable}, {"pose", p.pose}});
  Json motion = Json::array();
  for (const MotionFrame& f : s.motion)
    motion.push_back({{"at", f.at}, {"encoders", f.encoders}, {"objects", objectPoses(f.objects, placed)}});
  const auto triple = [](const std::optional<std::array<double, 3>>& v) {
    Json j = nullptr;
    if (v) j = {(*v)[0], (*v)[1], (*v)[2]};
    return j;
  };
  const auto axes = [](const std::vector<PendantJogAxis>& list) {
    Json a = Json::array();
    for (const PendantJogAxis& x : list) a.push_back({{"name", x.name}, {"rotation", x.rotation}, {"help", x.help}});
    return a;
  };
  return {{"revision", s.revision},
          {"program", s.program},
          {"cell", s.cell},
          {"device", s.device},
          {"motors", motors},
          {"encoders", s.encoders},
          {"tcp", triple(s.tcp)},
          {"approach", triple(s.approach)},
          {"normal", triple(s.normal)},
          {"jogAxes", {{"world", axes(s.worldAxes)}, {"tool", axes(s.toolAxes)}}},
          {"gripper", gripperName(s.gripper)},
          {"inputs", lines(s.inputs)},
          {"outputs", lines(s.outputs)},
          {"objects", objects},
          {"devices", {{"sensors", sensors}, {"conveyors", conveyors}, {"feeders", feeders}}},
          {"points", points},
          {"clock", s.clock},
          {"motion", motion},
          {"message", s.message},
          {"failed", s.failed},
          {"limit", s.limit},
          {"fault", s.fault},
          {"fileHash", fmt::format("{:016x}", s.fileHash)}};
}

}  // namespace rs::teach
