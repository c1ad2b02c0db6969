#include "runtime/cell/robot_sight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "runtime/cell/box_geometry.h"

namespace rs::runtime {

namespace {

Eigen::AlignedBox3d grown(const Eigen::AlignedBox3d& b, double by) {
  if (b.isEmpty()) return b;
  const Eigen::Vector3d d = Eigen::Vector3d::Constant(by);
  return {b.min() - d, b.max() + d};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool seesParts(const workcell::Sensor& s) { return s.sees != workcell::Sensor::Sees::Robots; }
bool seesRobot(const workcell::Sensor& s) { return s.sees != workcell::Sensor::Sees::Parts; }

}  // namespace

// One look at the robot: its motors at time t, the box round the carried
// part (empty: none), the box round each piece of the robot (when a sensor
// sees robots), and what each sensor sees of them.
struct RobotSight::Probe {
  vm::Micros t = 0;
  std::vector<std::int32_t> encoders;
  Eigen::AlignedBox3d part;
  std::array<Eigen::Vector3d, 8> corners;  // the carried part's design box's corners, placed
  std::vector<Eigen::AlignedBox3d> pieces;
  std::vector<bool> sees;
};

RobotSight::RobotSight(const workcell::Workcell& cell, const World& world, std::size_t motors, std::size_t robot)
    : cell_(cell), world_(world), motors_(motors), robot_(robot) {
  if (robot >= cell.robots.size() || !cell.robots[robot].robot.chain || cell.devices.sensors.empty()) return;
  for (const workcell::Sensor& s : cell.devices.sensors) seesRobots_ |= seesRobot(s);
  model_ = std::make_unique<workcell::CollisionModel>(cell, robot);
  data_ = std::make_unique<workcell::CollisionData>(*model_);
  carried_.assign(motors_, 0.0);
  pool_.resize(kDepth);
  matters_ = model_->movable();
}

RobotSight::~RobotSight() = default;

std::optional<std::size_t> RobotSight::carriedPart() const {
  // A part two hands hold stays put: the devices see it where it rests.
  const std::optional<std::size_t> held = world_.held(robot_);
  return held && !world_.shared(*held) ? held : std::nullopt;
}

void RobotSight::probe(vm::Micros t, const MotorsAt& at, Probe& p) {
  p.t = t;
  p.encoders.assign(motors_, 0);
  at(t, p.encoders);
  look(p);
}

void RobotSight::look(Probe& p) {
  const workcell::Devices& d = cell_.devices;
  p.part = Eigen::AlignedBox3d();
  if (const std::optional<std::size_t> held = carriedPart()) {
    const Eigen::AlignedBox3d design = workcell::boundsOf(cell_.objects[*held].shape);
    const Eigen::Isometry3d pose = world_.objectPose(*held, p.encoders, INT64_MAX, robot_);
    for (int c = 0; c < 8 && !design.isEmpty(); ++c) {
      p.corners[static_cast<std::size_t>(c)] = pose * design.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
      p.part.extend(p.corners[static_cast<std::size_t>(c)]);
    }
  }
  p.pieces.clear();
  if (seesRobots_) {
    data_->poseOnly(p.encoders);
    const auto bodies = model_->robotBodies();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const std::size_t first = p.pieces.size();
      p.pieces.resize(first + bodies[b].pieces.size());
      workcell::pieceBoxes(bodies[b], data_->robotPose(b), p.pieces.data() + first);
    }
  }
  p.sees.assign(d.sensors.size(), false);
  for (std::size_t s = 0; s < d.sensors.size(); ++s) {
    const workcell::Sensor& sensor = d.sensors[s];
    bool on = seesParts(sensor) && sensorTouches(sensor, p.part);
    if (seesRobot(sensor))
      for (std::size_t i = 0; i < p.pieces.size() && !on; ++i) on = sensorTouches(sensor, p.pieces[i]);
    p.sees[s] = on;
  }
}

void RobotSight::sees(std::span<const std::int32_t> encoders, std::vector<bool>& out) {
  out.assign(cell_.devices.sensors.size(), false);
  if (!matters_) return;
  Probe p;
  p.encoders.assign(motors_, 0);
  std::copy_n(encoders.begin(), std::min(encoders.size(), motors_), p.encoders.begin());
  look(p);
  out = p.sees;
}

// Whether nothing any sensor sees of the robot can change between a and b:
// no point of the carried part moves farther than `part`, none of the
// robot farther than `robot`, so a box that misses a sensor by more stays
// off it, and one that touches it even when shrunk by that stays on it.
namespace {

// Where the carried part's box can be between two looks, each of its
// corners having gone at most `reach` along its way from its place at a to
// its place at b: within the ellipsoid with those two foci whose axes add
// up to `reach`. `outer` holds every box it can be, `inner` lies in all of
// them (empty when none is common). A part lifted straight up keeps its
// x and z exactly, however far it goes: what a beam it stopped against
// needs to be seen to stay broken.
void carriedBounds(const std::array<Eigen::Vector3d, 8>& a, const std::array<Eigen::Vector3d, 8>& b, double reach,
                   Eigen::AlignedBox3d& outer, Eigen::AlignedBox3d& inner) {
  Eigen::Vector3d outerLo = Eigen::Vector3d::Constant(kInfinity), outerHi = -outerLo;
  Eigen::Vector3d innerLo = outerLo, innerHi = -outerLo;  // innerLo: least of the highs; innerHi: most of the lows
  for (std::size_t c = 0; c < 8; ++c) {
    const Eigen::Vector3d centre = (a[c] + b[c]) / 2, span = b[c] - a[c];
    const double d = span.norm(), r = std::max(reach, d);
    const double along = r / 2, across = std::sqrt(std::max(0.0, r * r - d * d)) / 2;
    const Eigen::Vector3d u = d > 0 ? Eigen::Vector3d(span / d) : Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      const double cosine = d > 0 ? u[k] : 0.0;
      const double half = d > 0 ? std::sqrt(along * along * cosine * cosine + across * across * (1 - cosine * cosine))
                                : r;
      outerLo[k] = std::min(outerLo[k], centre[k] - half), outerHi[k] = std::max(outerHi[k], centre[k] + half);
      innerLo[k] = std::min(innerLo[k], centre[k] + half), innerHi[k] = std::max(innerHi[k], centre[k] - half);
    }
  }
  outer = {outerLo, outerHi};
  inner = (innerLo.array() <= innerHi.array()).all() ? Eigen::AlignedBox3d(innerLo, innerHi) : Eigen::AlignedBox3d();
}

}  // namespace

bool RobotSight::stays(const Probe& a, const Probe& b) const {
  double part = 0, robot = 0;
  const auto weights = model_->motorWeights();
  for (std::size_t m = 0; m < motors_; ++m) {
    const double counts = std::abs(static_cast<double>(b.encoders[m]) - a.encoders[m]);
    part += carried_[m] * counts;
    if (m < weights.size()) robot += weights[m] * counts;
  }
  Eigen::AlignedBox3d outer, inner;
  if (!a.part.isEmpty()) carriedBounds(a.corners, b.corners, part, outer, inner);
  const workcell::Devices& d = cell_.devices;
  for (std::size_t s = 0; s < d.sensors.size(); ++s) {
    const workcell::Sensor& sensor = d.sensors[s];
    const bool partCounts = seesParts(sensor) && !a.part.isEmpty();
    const bool robotCounts = seesRobot(sensor);
    if (!a.sees[s]) {
      if (partCounts && sensorTouches(sensor, outer)) return false;
      if (robotCounts)
        for (const Eigen::AlignedBox3d& box : a.pieces)
          if (sensorTouches(sensor, grown(box, robot))) return false;
      continue;
    }
    bool held = partCounts && sensorTouches(sensor, inner);
    if (robotCounts)
      for (std::size_t i = 0; i < a.pieces.size() && !held; ++i) held = sensorTouches(sensor, grown(a.pieces[i], -robot));
    if (!held) return false;
  }
  return true;
}

std::optional<vm::Micros> RobotSight::search(const Probe& a, const Probe& b, const std::vector<bool>& start,
                                             const MotorsAt& at, int& budget, std::size_t depth) {
  if (stays(a, b)) return std::nullopt;
  if (b.t - a.t <= 1) return b.sees != start ? std::optional<vm::Micros>(b.t) : std::nullopt;
  const vm::Micros mid = a.t + (b.t - a.t) / 2;
  if (--budget <= 0 || depth >= kDepth) return mid;
  Probe& m = pool_[depth];  // the looks of one halving, kept: no allocation once warm
  probe(mid, at, m);
  if (std::optional<vm::Micros> left = search(a, m, start, at, budget, depth + 1)) return left;
  if (m.sees != start) return mid;  // only where the budget ran out on the left
  return search(m, b, start, at, budget, depth + 1);
}

bool RobotSight::remembers(const Last& last, vm::Micros from, vm::Micros to, const Probe& end,
                           const std::optional<std::size_t>& carried) const {
  if (last.to != to || from < last.from || (last.change && from >= *last.change) || last.carried != carried ||
      last.end != end.encoders)
    return false;
  return !carried || last.offset == world_.heldOffset(robot_).affine();
}

std::optional<vm::Micros> RobotSight::firstChange(vm::Micros from, vm::Micros to, const MotorsAt& at) {
  if (!matters_ || to <= from) return std::nullopt;
  const std::optional<std::size_t> held = carriedPart();
  if (!held && !seesRobots_) return std::nullopt;  // nothing carried, and no sensor sees the robot
  Probe& a = pool_[0];
  Probe& b = pool_[1];
  b.t = to;
  b.encoders.assign(motors_, 0);
  at(to, b.encoders);
  if (last_ && remembers(*last_, from, to, b, held)) return last_->change;
  if (held) {
    // How far the carried part's points lie from the tool centre point.
    const Eigen::AlignedBox3d box = workcell::boundsOf(cell_.objects[*held].shape);
    double reach = 0;
    for (int c = 0; c < 8; ++c)
      reach = std::max(reach, (world_.heldOffset(robot_) * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c))).norm());
    model_->carriedWeights(reach, carried_);
  } else {
    std::fill(carried_.begin(), carried_.end(), 0.0);
  }
  look(b);
  probe(from, at, a);
  start_ = a.sees;
  int budget = kMaxProbes;
  const std::optional<vm::Micros> change = search(a, b, start_, at, budget, 2);
  if (budget > 0) {
    last_ = Last{from, to, change, b.encoders, held, Eigen::Matrix<double, 3, 4>::Zero()};
    if (held) last_->offset = world_.heldOffset(robot_).affine();
  } else {
    last_.reset();
  }
  return change;
}

}  // namespace rs::runtime
