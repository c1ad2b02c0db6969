#include "runtime/sim/sweep_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rs::runtime {

namespace {

// How much of a gap a part may not use: the bounds are computed in
// floating point, and a part that moved exactly its gap would touch.
constexpr double kGapMargin = 1e-6;
constexpr std::size_t kAnyWay = SIZE_MAX;

}  // namespace

MotionBounds::MotionBounds(const workcell::CollisionModel& model) : model_(model), joints_(model.jointCount()) {
  const std::size_t bodies = model.robotBodies().size(), parts = bodies + 1;
  partFrame_.assign(parts, 0);
  radii_.assign(parts * joints_, 0.0);
  nearAxes_.assign(parts * joints_, 0.0);
  fingers_.assign(parts, 0.0);
  for (std::size_t b = 0; b < bodies && model.movable(); ++b) {
    partFrame_[b] = std::min(static_cast<std::size_t>(model.robotBodies()[b].frame), joints_);
    const std::span<const double> r = model.bodyRadii(b);
    std::copy(r.begin(), r.end(), radii_.begin() + static_cast<std::ptrdiff_t>(b * joints_));
    fingers_[b] = model.fingerWeight(b);
  }
  need_.assign(parts, 0.0);
  turns_.assign(joints_, 0.0);
  skew_.assign(joints_ * joints_, 0.0);
  lean_.assign(joints_ * joints_, 0.0);
  tilt_.assign(joints_ * (joints_ + 1), 0.0);
  facing_.assign(parts * workcell::PartClearance::kGaps * joints_, 0.0);
  scratch_.assign(joints_, 0.0);
  limits_.reserve(parts * (workcell::PartClearance::kGaps + 1));
}

void MotionBounds::startMove(std::optional<double> carriedReach) {
  const std::size_t carried = partFrame_.size() - 1;
  partFrame_[carried] = carriedReach ? joints_ : 0;  // it moves with the last frame; nothing: nothing moves
  if (carriedReach) model_.carriedRadii(*carriedReach, std::span<double>(&radii_[carried * joints_], joints_));
}

double MotionBounds::mostTravel(std::size_t part, std::span<const std::int32_t> from,
                                std::span<const std::int32_t> to) const {
  double sum = 0;
  for (std::size_t j = 0; j < partFrame_[part]; ++j) {
    const std::span<const double> rates = model_.jointRates(j);
    double turn = 0;
    for (std::size_t m = 0; m < rates.size() && m < from.size() && m < to.size(); ++m)
      turn += std::abs(rates[m]) * std::abs(static_cast<double>(to[m]) - from[m]);
    sum += turn * (model_.revolute(j) ? radii_[part * joints_ + j] : 1.0);
  }
  const std::optional<std::size_t> g = model_.gripperMotor();
  if (g && *g < from.size() && *g < to.size()) sum += fingers_[part] * std::abs(static_cast<double>(to[*g]) - from[*g]);
  return sum;
}

void MotionBounds::setCheck(std::span<const std::int32_t> at, std::span<const std::int32_t> end) {
  at_ = at, end_ = end;
  data_ = nullptr;
}

// Turning joint i tilts axis j (i < j) by at most the turn times
// |u_i × u_j|, and that sine changes only with the joints between them
// (turning u_j about u_i keeps their angle): lean(i, j) <= skew(i, j) +
// Σ_{i<k<j} turn_k · lean(k, j).
void MotionBounds::jointTravel(std::span<const std::int32_t> to) {
  for (std::size_t j = 0; j < joints_; ++j) {
    const std::span<const double> rates = model_.jointRates(j);
    double q = 0;
    for (std::size_t m = 0; m < rates.size() && m < to.size() && m < at_.size(); ++m)
      q += rates[m] * std::abs(static_cast<double>(to[m]) - at_[m]);
    turns_[j] = q;
  }
  for (std::size_t j = 0; j < joints_; ++j) {
    for (std::size_t i = j; i-- > 0;) {
      double lean = 0;
      if (model_.revolute(i)) {
        lean = skew_[i * joints_ + j];
        for (std::size_t k = i + 1; k < j; ++k)
          if (model_.revolute(k)) lean += turns_[k] * lean_[k * joints_ + j];
        lean = std::min(1.0, lean);
      }
      lean_[i * joints_ + j] = lean;
    }
    double* tilt = &tilt_[j * (joints_ + 1)];
    tilt[0] = 0;
    for (std::size_t i = 0; i < joints_; ++i) tilt[i + 1] = tilt[i] + (i < j ? turns_[i] * lean_[i * joints_ + j] : 0.0);
  }
  const std::optional<std::size_t> g = model_.gripperMotor();
  gripperTurn_ = g && *g < to.size() && *g < at_.size() ? std::abs(static_cast<double>(to[*g]) - at_[*g]) : 0.0;
}

// What the pose says of the axes: the sine of the angle between each two,
// and each part's greatest distance from each axis (at a corner of its
// world box: the distance from a line is convex); then how far each part
// can still go.
void MotionBounds::posed(const workcell::CollisionData& data) {
  data_ = &data;
  for (std::size_t j = 0; j < joints_; ++j)
    for (std::size_t i = 0; i < j; ++i)
      skew_[i * joints_ + j] = data.frame(i).linear().col(2).cross(data.frame(j).linear().col(2)).norm();
  for (std::size_t p = 0; p < partFrame_.size(); ++p) {
    const Eigen::AlignedBox3d& box = data.partBox(p);
    for (std::size_t j = 0; j < partFrame_[p]; ++j) {
      double farthest = 0;
      if (!box.isEmpty()) {
        const Eigen::Vector3d o = data.frame(j).translation(), u = data.frame(j).linear().col(2);
        for (int corner = 0; corner < 8; ++corner) {
          const Eigen::Vector3d d = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) - o;
          farthest = std::max(farthest, (d - d.dot(u) * u).norm());
        }
      }
      nearAxes_[p * joints_ + j] = farthest;
    }
  }
  jointTravel(end_);
  for (std::size_t p = 0; p < partFrame_.size(); ++p) need_[p] = partTravel(p, 0, nullptr);
}

void MotionBounds::face(std::size_t p, const Eigen::Vector3d& n, std::size_t from, double* out) const {
  for (std::size_t j = from; j < partFrame_[p]; ++j) {
    const Eigen::Vector3d u = data_->frame(j).linear().col(2);
    out[j] = model_.revolute(j) ? n.cross(u).norm() : std::abs(n.dot(u));
  }
}

double MotionBounds::along(std::size_t part, const Eigen::Vector3d& normal, std::size_t from) {
  face(part, normal, from, scratch_.data());
  return partTravel(part, from, scratch_.data()) + others(part, from);
}

// From the part's frame down to `from`: each joint moves the part by its
// turn times the part's distance from the axis (the distance at the check
// plus what the joints above have moved it, within the model's bound),
// along a direction by that times the facing, raised by the axis's tilt.
double MotionBounds::partTravel(std::size_t p, std::size_t from, const double* facing) const {
  const double* radii = &radii_[p * joints_];
  const double* nearAxes = &nearAxes_[p * joints_];
  const double fingers = fingers_[p] * gripperTurn_;
  double above = fingers, sum = fingers;
  for (std::size_t j = partFrame_[p]; j-- > from;) {
    if (turns_[j] == 0) continue;
    const double reach = model_.revolute(j) ? std::min(radii[j], nearAxes[j] + above) : 1.0;
    const double* tilt = &tilt_[j * (joints_ + 1)];
    const double share = facing ? std::min(1.0, facing[j] + tilt[j] - tilt[from]) : 1.0;
    sum += turns_[j] * reach * share;
    above += turns_[j] * reach;
  }
  return sum;
}

bool MotionBounds::limit(std::span<const workcell::PartClearance> clearance) {
  limits_.clear();
  std::size_t used = 0;
  for (std::size_t p = 0; p < clearance.size() && p < partFrame_.size(); ++p) {
    if (need_[p] <= 0) continue;
    const workcell::PartClearance& c = clearance[p];
    double anyWay = std::numeric_limits<double>::infinity();
    if (c.elsewhere - kGapMargin < need_[p] + others(p, 0))
      anyWay = c.elsewhere >= workcell::kSweepStep ? c.elsewhere - kGapMargin : workcell::kSweepStep;
    // The gaps of kLookAhead or more were not counted: not that far.
    if (need_[p] + others(p, 0) > kLookAhead) anyWay = std::min(anyWay, kLookAhead - kGapMargin);
    for (std::size_t k = 0; k < c.count; ++k) {
      const workcell::Gap& gap = c.gaps[k];
      if (gap.distance < workcell::kSweepStep) {
        anyWay = std::min(anyWay, workcell::kSweepStep);
        continue;
      }
      face(p, gap.normal, gap.from, &facing_[used]);
      limits_.push_back({p, gap.from, used, gap.distance - kGapMargin});
      used += joints_;
    }
    if (anyWay < std::numeric_limits<double>::infinity()) limits_.push_back({p, 0, kAnyWay, anyWay});
  }
  return !limits_.empty();
}

double MotionBounds::used(std::span<const std::int32_t> to, double othersMoved) {
  jointTravel(to);
  double worst = 0;
  for (const Limit& l : limits_) {
    const double* facing = l.facing == kAnyWay ? nullptr : &facing_[l.facing];
    const double others = l.from == 0 ? othersMoved : 0.0;
    worst = std::max(worst, (partTravel(l.part, l.from, facing) + others) / l.allowed);
  }
  return worst;
}

}  // namespace rs::runtime
