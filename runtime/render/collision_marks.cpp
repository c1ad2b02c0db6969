#include "runtime/render/collision_marks.h"

#include "model/workcell/grasp.h"

namespace rs::render {

namespace {

workcell::CollisionQuery queryAt(const workcell::Workcell& cell, workcell::CollisionData& data,
                                 std::span<const std::int32_t> encoders, std::span<const Eigen::Isometry3d> poses,
                                 std::optional<std::size_t> held) {
  workcell::CollisionQuery q;
  q.objectPoses = poses;
  data.findContact(encoders, q);  // poses the robot: the tool frame
  if (held && *held < poses.size()) {  // carried: where it is, in the gripper's frame
    q.held = held;
    q.heldOffset = data.toolFrame().inverse(Eigen::Isometry) * poses[*held];
  }
  const Eigen::Vector3d tcp = data.toolFrame().translation();
  double best = 0;
  for (std::size_t o = 0; o < cell.objects.size() && o < poses.size(); ++o) {
    const Eigen::AlignedBox3d box = workcell::boundsOf(cell.objects[o].shape);
    if (box.isEmpty()) continue;
    const Eigen::Vector3d local = poses[o].inverse(Eigen::Isometry) * tcp;
    const Eigen::AlignedBox3d slack(box.min().array() - 1e-6, box.max().array() + 1e-6);
    if (slack.contains(local) && (!q.exempt || box.volume() < best)) q.exempt = o, best = box.volume();
  }
  return q;
}

// `robot`: the robot (its Part::owner) whose bodies the contact's robot bodies are.
bool samePart(const Part& p, const workcell::BodyRef& b, int robot) {
  switch (b.kind) {
    case workcell::BodyKind::Link: return p.kind == PartKind::Link && p.owner == robot && p.index == b.index;
    case workcell::BodyKind::GripperBase: return p.kind == PartKind::GripperBase && p.owner == robot;
    case workcell::BodyKind::Finger2: return p.kind == PartKind::Finger2 && p.owner == robot;
    case workcell::BodyKind::Finger3: return p.kind == PartKind::Finger3 && p.owner == robot;
    case workcell::BodyKind::Object: return p.kind == PartKind::Object && p.owner == b.index;
    case workcell::BodyKind::Floor: return false;
  }
  return false;
}

Part partOf(const workcell::BodyRef& b, int lastFrame, int robot) {
  switch (b.kind) {
    case workcell::BodyKind::Link: return {PartKind::Link, robot, b.index, 0};
    case workcell::BodyKind::GripperBase: return {PartKind::GripperBase, robot, lastFrame, 0};
    case workcell::BodyKind::Finger2: return {PartKind::Finger2, robot, lastFrame, 0};
    case workcell::BodyKind::Finger3: return {PartKind::Finger3, robot, lastFrame, 0};
    case workcell::BodyKind::Object: return {PartKind::Object, b.index, 0, 0};
    case workcell::BodyKind::Floor: break;
  }
  return {};
}

void pieceLines(std::vector<Line3>& out, const workcell::CollisionPiece& piece, const Eigen::Isometry3d& T, Part part) {
  const auto& p = piece.points;
  const auto add = [&](std::size_t i, std::size_t k) { out.push_back({T * p[i], T * p[k], kCollisionShapeColor, part}); };
  if (p.size() == 8) {  // a box: corners ordered x, y, z bit by bit
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t bit : {4u, 2u, 1u})
        if (!(i & bit)) add(i, i | bit);
    return;
  }
  if (p.size() <= 12) {
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t k = i + 1; k < p.size(); ++k) add(i, k);
    return;
  }
  for (std::size_t i = 0; i + 1 < p.size(); ++i) add(i, i + 1);
}

}  // namespace

std::vector<workcell::Contact> contactsAt(const workcell::Workcell& cell, std::span<const std::int32_t> encoders,
                                          std::span<const Eigen::Isometry3d> objectPoses,
                                          std::optional<std::size_t> held, std::size_t robot) {
  const workcell::CollisionModel model(cell, robot);
  workcell::CollisionData data(model);
  const workcell::CollisionQuery q = queryAt(cell, data, encoders, objectPoses, held);
  return data.allContacts(encoders, q);
}

std::vector<Line3> collisionShapeLines(const workcell::Workcell& cell, std::span<const std::int32_t> encoders,
                                       std::span<const Eigen::Isometry3d> objectPoses, std::size_t robot) {
  const workcell::CollisionModel model(cell, robot);
  workcell::CollisionData data(model);
  const workcell::CollisionQuery q = queryAt(cell, data, encoders, objectPoses, std::nullopt);
  const int owner = static_cast<int>(robot);
  data.findContact(encoders, q);
  std::vector<Line3> out;
  int lastFrame = 0;
  for (const workcell::CollisionBody& b : model.robotBodies()) lastFrame = std::max(lastFrame, b.frame);
  for (std::size_t b = 0; b < model.robotBodies().size(); ++b)
    for (const workcell::CollisionPiece& piece : model.robotBodies()[b].pieces)
      pieceLines(out, piece, data.robotPose(b), partOf(model.robotBodies()[b].ref, lastFrame, owner));
  for (std::size_t o = 0; o < model.objectBodies().size() && o < objectPoses.size(); ++o)
    for (const workcell::CollisionPiece& piece : model.objectBodies()[o].pieces)
      pieceLines(out, piece, objectPoses[o], partOf(model.objectBodies()[o].ref, lastFrame, owner));
  return out;
}

void addLines(Picture& picture, std::span<const Line3> lines) {
  const Projection project(picture.camera, picture.fit);
  for (const Line3& l : lines) picture.lines.push_back({project(l.a), project(l.b), l.color, l.part});
}

void markColliding(Picture& picture, std::span<const workcell::Contact> contacts, std::size_t robot) {
  const int owner = static_cast<int>(robot);
  for (Line2& line : picture.lines)
    for (const workcell::Contact& c : contacts)
      if (line.part.kind != PartKind::Axis && (samePart(line.part, c.a, owner) || samePart(line.part, c.b, owner)))
        line.color = kCollidingColor, line.colliding = true;
}

}  // namespace rs::render
