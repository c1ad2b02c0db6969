#include "runtime/cell/robot_sight.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
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

// Whether the arm's turns never change a point's height (y): every
// revolute axis is vertical (turns about vertical axes keep them so), and
// every sliding joint is driven by one motor, so a point's height moves
// one way over a move, and a carried part's box keeps its height: a
// SCARA's (the adept-one's).
bool turnsKeepHeight(const workcell::CollisionModel& model, workcell::CollisionData& data, std::size_t motors) {
  data.poseOnly(std::vector<std::int32_t>(motors, 0));
  for (std::size_t j = 0; j < model.jointCount(); ++j) {
    const Eigen::Vector3d axis = data.frame(j).linear().col(2);
    if (model.revolute(j) ? std::abs(axis.y()) < 1 - 1e-12 : false) return false;
    const auto rates = model.jointRates(j);
    if (!model.revolute(j) && std::count_if(rates.begin(), rates.end(), [](double r) { return r != 0; }) > 1)
      return false;
  }
  return true;
}

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
  levelTurns_ = turnsKeepHeight(*model_, *data_, motors_);
  pool_.resize(kDepth);
  guess_.resize(3);
  matters_ = model_->movable();
}

RobotSight::~RobotSight() = default;

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
  // Nothing carried and no sensor that sees the robot: nothing to show
  // (what look() would find, without posing the arm).
  if (!matters_ || (!seesRobots_ && !carriedPart())) return;
  Probe& p = pool_[0];  // free between searches; no allocation once warm
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

// The box's signed gaps to what a sensor covers, a pair per axis (its
// low face past the region's high, the region's low past its high): all
// at most 0 while they touch, but for the touch slack. A beam along an
// axis covers a box of no width; any other beam has none (false).
bool faceGaps(const workcell::Sensor& s, const Eigen::AlignedBox3d& b, std::array<double, 6>& out) {
  Eigen::AlignedBox3d region = s.zone;
  if (s.shape == workcell::Sensor::Shape::Beam) {
    const Eigen::Vector3d e = s.b - s.a;
    if ((e.array() != 0).count() > 1) return false;
    region = Eigen::AlignedBox3d(s.a.cwiseMin(s.b), s.a.cwiseMax(s.b));
  }
  for (int k = 0; k < 3; ++k) {
    out[static_cast<std::size_t>(2 * k)] = b.min()[k] - region.max()[k];
    out[static_cast<std::size_t>(2 * k + 1)] = region.min()[k] - b.max()[k];
  }
  return true;
}

// Per the last helper: the part's heights between two looks lie between
// its heights at them, and the box keeps its height (all of it moves up or
// down together), so `outer` and `inner` can be no looser in y than the
// two boxes' hull and overlap (1e-9 of slack for rounding).
void keepHeight(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, Eigen::AlignedBox3d& outer,
                Eigen::AlignedBox3d& inner) {
  constexpr double kSlack = 1e-9;
  outer.min().y() = std::max(outer.min().y(), std::min(a.min().y(), b.min().y()) - kSlack);
  outer.max().y() = std::min(outer.max().y(), std::max(a.max().y(), b.max().y()) + kSlack);
  const double lo = std::max(a.min().y(), b.min().y()) + kSlack, hi = std::min(a.max().y(), b.max().y()) - kSlack;
  if (inner.isEmpty() || lo > hi) return;
  inner.min().y() = std::min(inner.min().y(), lo);
  inner.max().y() = std::max(inner.max().y(), hi);
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
  if (levelTurns_ && !a.part.isEmpty()) keepHeight(a.part, b.part, outer, inner);
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

// Where the carried part's box crosses the sensor face that a and b see
// on either side (the earliest by the chord), found on that face's gap
// down to one microsecond, then checked as search() would: the look after
// the crossing sees otherwise than `start`, the look before it the same,
// and stays() holds from a to it (nothing changed before). Any of these
// failing: none (search() then halves as before). The adept_hour lift out
// of its beam costs 8 looks and one stays() instead of 17 halvings, each
// with two stays().
std::optional<vm::Micros> RobotSight::locate(const Probe& a, const Probe& b, const std::vector<bool>& start,
                                             const MotorsAt& at, int& budget) {
  if (seesRobots_ || a.part.isEmpty() || b.part.isEmpty()) return std::nullopt;
  const workcell::Devices& d = cell_.devices;
  std::optional<std::pair<std::size_t, std::size_t>> face;  // sensor, gap
  double earliest = kInfinity;
  std::array<double, 6> ga{}, gb{};
  for (std::size_t s = 0; s < d.sensors.size(); ++s) {
    if (a.sees[s] == b.sees[s] || !faceGaps(d.sensors[s], a.part, ga) || !faceGaps(d.sensors[s], b.part, gb)) continue;
    for (std::size_t i = 0; i < 6; ++i) {
      if ((ga[i] <= 0) == (gb[i] <= 0)) continue;
      const double along = ga[i] / (ga[i] - gb[i]);
      if (along < earliest) earliest = along, face = std::pair(s, i);
    }
  }
  if (!face) return std::nullopt;
  const auto gap = [&](const Probe& p) {
    std::array<double, 6> g{};
    faceGaps(d.sensors[face->first], p.part, g);
    return g[face->second];
  };
  Probe* lo = &guess_[0];
  Probe* hi = &guess_[1];
  Probe* mid = &guess_[2];
  *lo = a, *hi = b;
  const double flo = gap(a), fhi = gap(b);
  // The chord's guess first. The part moves a whole encoder count at a
  // time, so the gap is a staircase and the guess is off by about a count:
  // then steps from it towards the other side, each 8 times the last,
  // until one crosses; then halvings.
  enum class Phase { Chord, Step, Halve } phase = Phase::Chord;
  vm::Micros step = 64, last = a.t;
  bool lastLow = true;
  while (hi->t - lo->t > 1) {
    if (--budget <= 0) return std::nullopt;
    vm::Micros t = lo->t + (hi->t - lo->t) / 2;
    if (phase == Phase::Chord)
      t = a.t + static_cast<vm::Micros>(std::llround(static_cast<double>(b.t - a.t) * flo / (flo - fhi)));
    else if (phase == Phase::Step)
      t = lastLow ? last + step : last - step;
    t = std::clamp(t, lo->t + 1, hi->t - 1);
    probe(t, at, *mid);
    const bool low = (gap(*mid) <= 0) == (flo <= 0);
    std::swap(low ? lo : hi, mid);
    if (phase == Phase::Step && low != lastLow) phase = Phase::Halve;
    if (phase == Phase::Step) step *= 8;
    if (phase == Phase::Chord) phase = Phase::Step;
    last = t, lastLow = low;
  }
  if (lo->sees != start || hi->sees == start || !stays(a, *lo)) return std::nullopt;
  return hi->t;
}

bool RobotSight::remembers(const Last& last, vm::Micros from, vm::Micros to, const Probe& end,
                           const std::optional<std::size_t>& carried) const {
  if (last.to != to || from < last.from || (last.change && from >= *last.change) || last.carried != carried ||
      last.end != end.encoders)
    return false;
  return !carried || last.offset == world_.heldOffset(robot_).affine();
}

// Written over the last one's storage: every move the robot makes while
// it carries a part asks.
void RobotSight::keepLast(vm::Micros from, vm::Micros to, std::optional<vm::Micros> change,
                          const std::vector<std::int32_t>& end, std::optional<std::size_t> held,
                          const std::vector<bool>& start) {
  if (!last_) last_ = Last{};
  Last& l = *last_;
  l.from = from, l.to = to, l.change = change, l.carried = held;
  l.end.assign(end.begin(), end.end());
  l.start = start;
  if (held) l.offset = world_.heldOffset(robot_).affine();
  else l.offset.setZero();
  asked_.emplace(from, to);
}

std::optional<vm::Micros> RobotSight::firstChange(vm::Micros from, vm::Micros to, const MotorsAt& at,
                                                  const MotionKey& motion) {
  asked_.reset();
  if (!matters_ || to <= from) return std::nullopt;
  const std::optional<std::size_t> held = carriedPart();
  if (!held && !seesRobots_) return std::nullopt;  // nothing carried, and no sensor sees the robot
  Probe& a = pool_[0];
  Probe& b = pool_[1];
  b.t = to;
  b.encoders.assign(motors_, 0);
  at(to, b.encoders);
  if (last_ && remembers(*last_, from, to, b, held)) {
    asked_.emplace(from, to);
    return last_->change;
  }
  key_.clear();
  const bool keyed = motion && motion(key_);
  if (keyed) {
    const std::size_t words = key_.size();
    key_.resize(words + 2 + (held ? 12 : 0));
    key_[words] = static_cast<std::uint64_t>(to - from);
    key_[words + 1] = held ? *held + 1 : 0;
    if (held) world_.writeHeldOffset(robot_, key_.data() + words + 2);
    if (const Answer* hit = memory_.find(key_)) {
      ++remembered_;
      const std::optional<vm::Micros> change = hit->after < 0 ? std::nullopt : std::optional<vm::Micros>(from + hit->after);
      // The answer holds as a search's would: a wake later in the move asks last_.
      keepLast(from, to, change, b.encoders, held, hit->start);
      return change;
    }
  }
  ++searched_;
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
  std::optional<vm::Micros> change = locate(a, b, start_, at, budget);
  if (!change) change = search(a, b, start_, at, budget, 2);
  if (budget > 0) {
    keepLast(from, to, change, b.encoders, held, start_);
    if (keyed) memory_.put(key_, Answer{change ? *change - from : -1, start_});
  } else {
    last_.reset();
  }
  return change;
}

bool RobotSight::seenAsAsked(vm::Micros now, vm::Micros to, std::vector<bool>& out) const {
  if (!last_ || !asked_ || asked_->first != now || asked_->second != to) return false;
  // What it carries and how, as when it was asked (nothing between moves it).
  const std::optional<std::size_t> held = carriedPart();
  if (last_->carried != held || (held && last_->offset != world_.heldOffset(robot_).affine())) return false;
  out = last_->start;
  return true;
}

}  // namespace rs::runtime
