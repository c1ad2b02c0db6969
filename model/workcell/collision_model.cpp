#include "model/workcell/collision_model.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/gripper.h"
#include "model/kinematics/joint_values.h"
#include "model/workcell/gjk.h"

namespace rs::workcell {

namespace {

using Eigen::Vector3d;

// A BOX piece's corners are ordered x, y, z bit by bit (index 4i + 2j + k);
// each face moves in by the tolerance along the box's own axes, a side
// shorter than twice the tolerance to its middle.
std::vector<Vector3d> insetBox(const std::vector<Vector3d>& c) {
  const std::array<Vector3d, 3> edge{c[4] - c[0], c[2] - c[0], c[1] - c[0]};
  std::vector<Vector3d> out(8);
  for (int corner = 0; corner < 8; ++corner) {
    Vector3d p = c[static_cast<std::size_t>(corner)];
    for (int axis = 0; axis < 3; ++axis) {
      const double length = edge[static_cast<std::size_t>(axis)].norm();
      if (length == 0) continue;
      const double step = std::min(kContactTolerance, length / 2);
      const bool far = (corner >> (2 - axis)) & 1;
      p += (far ? -step : step) / length * edge[static_cast<std::size_t>(axis)];
    }
    out[static_cast<std::size_t>(corner)] = p;
  }
  return out;
}

// Any other hull: each point moves the tolerance towards the points' mean.
std::vector<Vector3d> insetHull(const std::vector<Vector3d>& points) {
  Vector3d mean = Vector3d::Zero();
  for (const Vector3d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  std::vector<Vector3d> out;
  out.reserve(points.size());
  for (const Vector3d& p : points) {
    const double d = (p - mean).norm();
    out.push_back(d <= kContactTolerance ? mean : Vector3d(p + (mean - p) * (kContactTolerance / d)));
  }
  return out;
}

CollisionBody makeBody(BodyRef ref, const Shape& shape, int frame) {
  CollisionBody body{ref, shape.name, frame, {}};
  for (const ConvexPiece& piece : shape.collision) {
    if (piece.points.empty()) continue;
    CollisionPiece p;
    p.points = piece.box && piece.points.size() == 8 ? insetBox(piece.points) : insetHull(piece.points);
    body.pieces.push_back(std::move(p));
  }
  return body;
}

// The largest distance from `origin` of the body's points moved by `T`.
double reachOf(const CollisionBody& body, const Eigen::Isometry3d& T, const Vector3d& origin = Vector3d::Zero()) {
  double r = 0;
  for (const CollisionPiece& piece : body.pieces)
    for (const Vector3d& p : piece.points) r = std::max(r, (T * p - origin).norm());
  return r;
}

double distanceToLine(const Vector3d& p, const kinematics::Line& line) {
  const Vector3d u = line.direction.normalized();
  const Vector3d d = p - line.point;
  return (d - d.dot(u) * u).norm();
}

}  // namespace

CollisionModel::CollisionModel(const Workcell& cell, std::size_t robot) : cell_(&cell), robot_(robot) {
  for (std::size_t o = 0; o < cell.objects.size(); ++o)
    objectBodies_.push_back(makeBody({BodyKind::Object, static_cast<int>(o)}, cell.objects[o].shape, -1));
  if (robot >= cell.robots.size()) return;
  const PlacedRobot& placed = cell.robots[robot];
  const Robot& r = placed.robot;
  const int n = r.chain ? r.chain->size() : 0;
  const int last = n;
  for (std::size_t i = 0; i < r.links.size(); ++i)
    robotBodies_.push_back(makeBody({BodyKind::Link, static_cast<int>(i)}, r.links[i], std::min(static_cast<int>(i), last)));
  if (r.hasGripper) {
    robotBodies_.push_back(makeBody({BodyKind::GripperBase, 0}, r.gripper.base, last));
    robotBodies_.push_back(makeBody({BodyKind::Finger2, 0}, r.gripper.finger2, last));
    robotBodies_.push_back(makeBody({BodyKind::Finger3, 0}, r.gripper.finger3, last));
  }
  if (!r.chain) return;
  const Eigen::Isometry3d F_world_0 = placed.F_world_design * r.frames.front();
  baseOrigin_ = F_world_0.translation();
  chain_.emplace(r.chain->placedAt(F_world_0));
  kinematics::ChainData home(*chain_);
  M_.resize(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    M_[static_cast<std::size_t>(i)] =
        (F_world_0 * home.F_0_i[static_cast<std::size_t>(i)]).inverse(Eigen::Isometry) * placed.F_world_design;

  // dq/de: joint values are home + C·e, so C's columns are q(unit e) − home.
  const std::size_t motors = static_cast<std::size_t>(chain_->encoderCount());
  std::vector<double> e(motors, 0.0), q0(static_cast<std::size_t>(n)), q1(static_cast<std::size_t>(n));
  kinematics::jointValuesFromEncoders(*chain_, std::span<const double>(e), q0);
  dqde_.assign(static_cast<std::size_t>(n), std::vector<double>(motors, 0.0));
  for (std::size_t m = 0; m < motors; ++m) {
    e[m] = 1;
    kinematics::jointValuesFromEncoders(*chain_, std::span<const double>(e), q1);
    e[m] = 0;
    for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) dqde_[j][m] = std::abs(q1[j] - q0[j]);
  }
  // Bounds on each D-H translation over the joint ranges (a prismatic d
  // over every encoder value its motors allow).
  std::vector<double> length(static_cast<std::size_t>(n) + 1, 0.0);
  jointScale_.assign(static_cast<std::size_t>(n), 1.0);
  for (int i = 1; i <= n; ++i) {
    const kinematics::Joint& joint = chain_->joint(i);
    const std::size_t j = static_cast<std::size_t>(i - 1);
    double d = std::abs(joint.dh.d);
    if (joint.type() == kinematics::JointType::Prismatic) {
      d = std::abs(joint.home);
      for (std::size_t m = 0; m < motors && m < r.joints.size(); ++m)
        d += dqde_[j][m] * std::max(std::abs(double(r.joints[m].min)), std::abs(double(r.joints[m].max)));
    } else {
      jointScale_[j] = M_PI / 180.0;
    }
    length[static_cast<std::size_t>(i)] = std::hypot(joint.dh.a, d);
  }
  // The reach of each body from the origin of its own frame.
  std::vector<double> bodyReach(robotBodies_.size(), 0.0), fingerWeights(robotBodies_.size(), 0.0);
  const kinematics::GripperModel& g = r.gripper.model;
  for (std::size_t b = 0; b < robotBodies_.size(); ++b) {
    const CollisionBody& body = robotBodies_[b];
    const Eigen::Isometry3d& M = M_[static_cast<std::size_t>(body.frame)];
    if (body.ref.kind == BodyKind::Finger2 || body.ref.kind == BodyKind::Finger3) {
      const kinematics::Line& axis = body.ref.kind == BodyKind::Finger2 ? g.r2 : g.r3;
      bodyReach[b] = (M * axis.point).norm() + reachOf(body, Eigen::Isometry3d::Identity(), axis.point);
      double aroundAxis = 0;
      for (const CollisionPiece& piece : body.pieces)
        for (const Vector3d& p : piece.points) aroundAxis = std::max(aroundAxis, distanceToLine(p, axis));
      fingerWeights[b] = std::abs(g.precision) * M_PI / 180.0 * aroundAxis;
      fingerWeight_ = std::max(fingerWeight_, fingerWeights[b]);
    } else {
      bodyReach[b] = reachOf(body, M);
    }
  }
  std::vector<double> toFrame0(length.size(), 0.0);  // Σ lengths 1..f: frame f's origin from frame 0's
  for (std::size_t f = 1; f < length.size(); ++f) toFrame0[f] = toFrame0[f - 1] + length[f];
  for (std::size_t b = 0; b < robotBodies_.size(); ++b)
    reach_ = std::max(reach_, toFrame0[static_cast<std::size_t>(robotBodies_[b].frame)] + bodyReach[b]);
  gripperMotor_ = motors;
  hasGripper_ = r.hasGripper;
  const std::size_t columns = motors + (r.hasGripper ? 1 : 0);
  bodyWeights_.assign(robotBodies_.size() * columns, 0.0);
  bodyRadii_.assign(robotBodies_.size() * static_cast<std::size_t>(n), 0.0);
  fingerWeights_ = fingerWeights;
  revolute_.assign(static_cast<std::size_t>(n), 0);
  jointRates_.assign(static_cast<std::size_t>(n) * motors, 0.0);
  for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
    revolute_[j] = jointScale_[j] != 1.0;
    for (std::size_t m = 0; m < motors; ++m) jointRates_[j * motors + m] = dqde_[j][m] * jointScale_[j];
  }
  staticRho_.assign(static_cast<std::size_t>(n), 0.0);
  toReach_.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 1; i <= n; ++i) {
    const std::size_t j = static_cast<std::size_t>(i - 1);
    double fromAxis = 0;  // Σ lengths i..f, growing with f
    std::vector<double> toFrame(static_cast<std::size_t>(n) + 1, 0.0);
    for (int f = i; f <= n; ++f) fromAxis += length[static_cast<std::size_t>(f)], toFrame[static_cast<std::size_t>(f)] = fromAxis;
    toReach_[j] = toFrame[static_cast<std::size_t>(n)];
    for (std::size_t b = 0; b < robotBodies_.size(); ++b) {
      if (robotBodies_[b].frame < i) continue;
      const double rho = toFrame[static_cast<std::size_t>(robotBodies_[b].frame)] + bodyReach[b];
      bodyRadii_[b * static_cast<std::size_t>(n) + j] = rho;
      staticRho_[j] = std::max(staticRho_[j], rho);
      // This body alone: joint i moves it by |dq| times its own distance from the axis.
      const double perUnit = jointScale_[j] != 1.0 ? jointScale_[j] * rho : 1.0;
      for (std::size_t m = 0; m < motors; ++m) bodyWeights_[b * columns + m] += dqde_[j][m] * perUnit;
    }
  }
  if (r.hasGripper)
    for (std::size_t b = 0; b < robotBodies_.size(); ++b) bodyWeights_[b * columns + motors] = fingerWeights[b];
  motorWeights_.assign(columns, 0.0);
  motorWeightsCarrying(0.0, motorWeights_);
}

std::span<const double> CollisionModel::bodyWeights(std::size_t body) const {
  const std::size_t columns = motorWeights_.size();
  return std::span<const double>(bodyWeights_).subspan(body * columns, columns);
}

std::span<const double> CollisionModel::jointRates(std::size_t j) const {
  const std::size_t motors = static_cast<std::size_t>(gripperMotor_);
  return std::span<const double>(jointRates_).subspan(j * motors, motors);
}

std::span<const double> CollisionModel::bodyRadii(std::size_t body) const {
  const std::size_t joints = revolute_.size();
  return std::span<const double>(bodyRadii_).subspan(body * joints, joints);
}

void CollisionModel::carriedRadii(double reach, std::span<double> out) const {
  for (std::size_t j = 0; j < toReach_.size() && j < out.size(); ++j) out[j] = toReach_[j] + reach;
}

void CollisionModel::carriedWeights(double reach, std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t j = 0; j < dqde_.size(); ++j) {
    const double perUnit = jointScale_[j] != 1.0 ? jointScale_[j] * (toReach_[j] + reach) : 1.0;
    for (std::size_t m = 0; m < dqde_[j].size() && m < out.size(); ++m) out[m] += dqde_[j][m] * perUnit;
  }
}

void CollisionModel::motorWeightsCarrying(double reach, std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t j = 0; j < dqde_.size(); ++j) {
    const bool revolute = jointScale_[j] != 1.0;
    const double rho = revolute ? jointScale_[j] * std::max(staticRho_[j], reach > 0 ? toReach_[j] + reach : 0.0) : 1.0;
    for (std::size_t m = 0; m < dqde_[j].size() && m < out.size(); ++m) out[m] += dqde_[j][m] * rho;
  }
  if (hasGripper_ && gripperMotor_ < out.size()) out[gripperMotor_] = fingerWeight_;
}

double CollisionModel::countStep() const {
  double w = 0;
  for (double v : motorWeights_) w = std::max(w, v);
  return w;
}

std::string_view CollisionModel::nameOf(const BodyRef& ref) const {
  if (ref.kind == BodyKind::Floor) return "";
  if (ref.kind == BodyKind::Object) return objectBodies_[static_cast<std::size_t>(ref.index)].name;
  for (const CollisionBody& b : robotBodies_)
    if (b.ref == ref) return b.name;
  return "";
}

std::string CollisionModel::describe(const BodyRef& ref) const {
  const std::string_view name = nameOf(ref);
  switch (ref.kind) {
    case BodyKind::Link: return fmt::format("link {} ({})", ref.index, name);
    case BodyKind::GripperBase: return fmt::format("the gripper's base ({})", name);
    case BodyKind::Finger2: return fmt::format("finger 2 ({})", name);
    case BodyKind::Finger3: return fmt::format("finger 3 ({})", name);
    case BodyKind::Object: {
      const std::size_t o = static_cast<std::size_t>(ref.index);
      if (o < cell_->objects.size() && !cell_->objects[o].robotPart.empty()) return cell_->objects[o].robotPart;
      return fmt::format("object {} ({})", ref.index + 1, name);
    }
    case BodyKind::Floor: return "the floor";
  }
  return "";
}

CollisionData::CollisionData(const CollisionModel& model) : model_(model) {
  const std::size_t frames = model.chain_ ? static_cast<std::size_t>(model.chain_->size()) + 1 : 1;
  if (model.chain_) chainData_.emplace(*model.chain_);
  q_.assign(frames - 1, 0.0);
  encoders_.assign(model.chain_ ? static_cast<std::size_t>(model.chain_->encoderCount()) : 0, 0);
  F_world_i_.assign(frames, Eigen::Isometry3d::Identity());
  robotPoses_.assign(model.robotBodies_.size(), Eigen::Isometry3d::Identity());
  for (const CollisionBody& b : model.robotBodies_) robotBoxes_.emplace_back(b.pieces.size());
  std::size_t most = 0;
  for (const CollisionBody& b : model.objectBodies_) most = std::max(most, b.pieces.size()), objectBoxes_.emplace_back(b.pieces.size());
  objectBoxPose_.assign(model.objectBodies_.size(), Eigen::Isometry3d::Identity());
  objectBoxOk_.assign(model.objectBodies_.size(), 0);
  heldBoxes_.assign(most, Eigen::AlignedBox3d());
  heldRaisedBoxes_.assign(most, Eigen::AlignedBox3d());
  robotHull_.assign(model.robotBodies_.size(), Eigen::AlignedBox3d());
  objectHull_.assign(model.objectBodies_.size(), Eigen::AlignedBox3d());
  outOfReach_.assign(model.objectBodies_.size(), 0);
  if (model.robot_ < model.cell_->robots.size() && !model.chain_) {  // a bare base: where it was placed
    const PlacedRobot& placed = model.cell_->robots[model.robot_];
    for (Eigen::Isometry3d& p : robotPoses_) p = placed.F_world_design;
  }
}

void CollisionData::pose(std::span<const std::int32_t> encoders) {
  if (!model_.chain_) return;
  const kinematics::ChainModel& chain = *model_.chain_;
  for (std::size_t m = 0; m < encoders_.size(); ++m) encoders_[m] = m < encoders.size() ? encoders[m] : 0;
  kinematics::jointValuesFromEncoders(chain, std::span<const std::int32_t>(encoders_), q_);
  kinematics::forwardKinematics(chain, *chainData_, q_);
  for (std::size_t i = 0; i < F_world_i_.size(); ++i) F_world_i_[i] = chain.F_world_0() * chainData_->F_0_i[i];
  const Robot& robot = model_.cell_->robots[model_.robot_].robot;
  const std::size_t gripper = static_cast<std::size_t>(chain.size());
  const double g = robot.hasGripper && gripper < encoders.size() ? encoders[gripper] : 0.0;
  const kinematics::FingerTransforms fingers =
      robot.hasGripper ? kinematics::fingerTransforms(robot.gripper.model, g) : kinematics::FingerTransforms{};
  for (std::size_t b = 0; b < robotPoses_.size(); ++b) {
    const CollisionBody& body = model_.robotBodies_[b];
    const std::size_t f = static_cast<std::size_t>(body.frame);
    robotPoses_[b] = F_world_i_[f] * model_.M_[f];
    if (body.ref.kind == BodyKind::Finger2) robotPoses_[b] = robotPoses_[b] * fingers.finger2;
    if (body.ref.kind == BodyKind::Finger3) robotPoses_[b] = robotPoses_[b] * fingers.finger3;
  }
}

void pieceBoxes(const CollisionBody& body, const Eigen::Isometry3d& T, Eigen::AlignedBox3d* out) {
  for (std::size_t i = 0; i < body.pieces.size(); ++i) {
    Eigen::AlignedBox3d box;
    for (const Vector3d& p : body.pieces[i].points) box.extend(T * p);
    out[i] = box;
  }
}

bool isFinger(const CollisionBody& b) { return b.ref.kind == BodyKind::Finger2 || b.ref.kind == BodyKind::Finger3; }

bool isGripperPart(const CollisionBody& b) {
  return b.ref.kind == BodyKind::GripperBase || b.ref.kind == BodyKind::Finger2 || b.ref.kind == BodyKind::Finger3;
}

namespace {

bool bodiesOverlap(const CollisionBody& a, const Eigen::Isometry3d& Ta, const Eigen::AlignedBox3d* boxesA,
                   const CollisionBody& b, const Eigen::Isometry3d& Tb, const Eigen::AlignedBox3d* boxesB) {
  for (std::size_t i = 0; i < a.pieces.size(); ++i)
    for (std::size_t k = 0; k < b.pieces.size(); ++k) {
      if (!boxesA[i].intersects(boxesB[k])) continue;
      if (hullsOverlap({a.pieces[i].points, &Ta}, {b.pieces[k].points, &Tb})) return true;
    }
  return false;
}

// A point of the body below the floor (the boxes' lowest y is exact).
bool belowFloor(const CollisionBody& body, const Eigen::AlignedBox3d* boxes, double floor) {
  for (std::size_t i = 0; i < body.pieces.size(); ++i)
    if (!boxes[i].isEmpty() && boxes[i].min().y() < floor) return true;
  return false;
}

}  // namespace

// Objects rarely move: their boxes (and the union of them) are kept until
// their pose changes.
const Eigen::AlignedBox3d* CollisionData::objectBoxes(std::size_t o, const Eigen::Isometry3d& pose) {
  // Bit for bit (a memcmp: every check of every move asks, for every object).
  if (!objectBoxOk_[o] ||
      std::memcmp(objectBoxPose_[o].matrix().data(), pose.matrix().data(), sizeof(double) * 16) != 0) {
    pieceBoxes(model_.objectBodies_[o], pose, objectBoxes_[o].data());
    objectHull_[o].setEmpty();
    for (const Eigen::AlignedBox3d& box : objectBoxes_[o]) objectHull_[o].extend(box);
    objectBoxPose_[o] = pose;
    objectBoxOk_[o] = 1;
  }
  return objectBoxes_[o].data();
}

// `on(contact)` returns true to stop. With `statics`, link 0 (frame 0) is
// checked against the floor and the objects too (the home check).
template <typename OnContact>
void CollisionData::scan(std::span<const std::int32_t> encoders, const CollisionQuery& query, OnContact&& on) {
  pose(encoders);
  const auto& robot = model_.robotBodies_;
  const auto& objects = model_.objectBodies_;
  for (std::size_t b = 0; b < robot.size(); ++b)
    pieceBoxes(robot[b], robotPoses_[b], robotBoxes_[b].data());
  const std::optional<double> floor = model_.cell_->floor;
  const bool statics = on.statics;
  const int last = static_cast<int>(F_world_i_.size()) - 1;
  const auto objectPose = [&](std::size_t o) -> const Eigen::Isometry3d& { return query.objectPoses[o]; };
  const auto objectBoxes = [&](std::size_t o) { return this->objectBoxes(o, query.objectPoses[o]); };
  for (std::size_t b = 0; b < robot.size(); ++b) {
    const CollisionBody& body = robot[b];
    if (body.pieces.empty() || (body.frame == 0 && !statics)) {
      // link 0 never moves: only other links can reach it (below)
    } else {
      if (floor && belowFloor(body, robotBoxes_[b].data(), *floor))
        if (on({body.ref, {BodyKind::Floor, 0}})) return;
      if (query.anyObject(objects.size(), [&](std::size_t o) {
            if (query.held == o || (isFinger(body) && query.exempt == o)) return false;
            return bodiesOverlap(body, robotPoses_[b], robotBoxes_[b].data(), objects[o], objectPose(o), objectBoxes(o)) &&
                   on({body.ref, objects[o].ref});
          }))
        return;
    }
    if (body.pieces.empty()) continue;
    for (std::size_t c = 0; c < robot.size(); ++c) {
      if (robot[c].frame > body.frame - 2 || robot[c].pieces.empty()) continue;
      if (bodiesOverlap(body, robotPoses_[b], robotBoxes_[b].data(), robot[c], robotPoses_[c], robotBoxes_[c].data()))
        if (on({body.ref, robot[c].ref})) return;
    }
  }
  if (!query.held || *query.held >= objects.size()) return;
  const CollisionBody& held = objects[*query.held];
  const Eigen::Isometry3d T = F_world_i_.back() * query.heldOffset, raised = raisedForRest(T);
  pieceBoxes(held, T, heldBoxes_.data());
  pieceBoxes(held, raised, heldRaisedBoxes_.data());
  if (floor && belowFloor(held, heldRaisedBoxes_.data(), *floor))
    if (on({held.ref, {BodyKind::Floor, 0}})) return;
  if (query.anyObject(objects.size(), [&](std::size_t o) {
        return o != *query.held &&
               bodiesOverlap(held, raised, heldRaisedBoxes_.data(), objects[o], objectPose(o), objectBoxes(o)) &&
               on({held.ref, objects[o].ref});
      }))
    return;
  for (std::size_t c = 0; c < robot.size(); ++c) {
    if (robot[c].frame > last - 2 || robot[c].pieces.empty()) continue;
    if (bodiesOverlap(held, T, heldBoxes_.data(), robot[c], robotPoses_[c], robotBoxes_[c].data()))
      if (on({held.ref, robot[c].ref})) return;
  }
}

namespace {

struct First {
  bool statics = false;
  std::optional<Contact>* found;
  bool operator()(const Contact& c) const { return *found = c, true; }
};

struct Every {
  bool statics = false;
  std::vector<Contact>* found;
  bool operator()(const Contact& c) const { return found->push_back(c), false; }
};

}  // namespace

std::optional<Contact> CollisionData::findContact(std::span<const std::int32_t> encoders, const CollisionQuery& query) {
  std::optional<Contact> found;
  scan(encoders, query, First{false, &found});
  return found;
}

std::vector<Contact> CollisionData::allContacts(std::span<const std::int32_t> encoders, const CollisionQuery& query,
                                               bool withStatic) {
  std::vector<Contact> found;
  scan(encoders, query, Every{withStatic, &found});
  return found;
}

std::vector<Contact> checkAtHome(const Workcell& cell) {
  if (!cell.drivenRobot()) return {};
  const CollisionModel model(cell);
  CollisionData data(model);
  std::vector<Eigen::Isometry3d> poses;
  for (const PlacedObject& o : cell.objects) poses.push_back(o.F_world_design);
  CollisionQuery query;
  query.objectPoses = poses;
  const std::vector<std::int32_t> home(model.motorWeights().size(), 0);
  return data.allContacts(home, query, true);
}

double carriedReach(const Workcell& cell) {
  double reach = 0;
  for (const PlacedObject& object : cell.objects) {
    if (object.kind == ObjectKind::Fixture) continue;
    Eigen::AlignedBox3d box;
    for (const Segment& s : object.shape.segments) box.extend(s.a), box.extend(s.b);
    for (const ConvexPiece& piece : object.shape.collision)
      for (const Vector3d& p : piece.points) box.extend(p);
    if (!box.isEmpty()) reach = std::max(reach, (1 + std::sqrt(3.0)) * box.diagonal().norm() / 2);
  }
  return reach;
}

}  // namespace rs::workcell
