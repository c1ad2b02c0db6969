#include "model/workcell/line_path.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

#include "model/workcell/line_plan_cache.h"

#include "model/kinematics/forward_kinematics.h"
#include "model/kinematics/joint_values.h"

namespace rs::workcell {

namespace {

using kinematics::IkErrorKind;
using kinematics::JointType;

// A knot's joints may turn at most this far from the knot before (degrees):
// more, however short the step, is the arm flipping (an elbow or a wrist
// passing through its straight pose), not following the line.
constexpr double kMaxKnotTurn = 5.0;
// The shortest step the planner halves to, as a fraction of the line: where
// a problem is found it is reported to within this.
constexpr double kMinStep = 1.0 / 65536.0;
// The longest first step and the most a step grows after a good one.
constexpr double kMaxStep = 0.25;
// The chord check samples each step at these fractions, against this share
// of the tolerance (the deviation peaks between samples a little higher).
constexpr double kChordSamples[] = {0.25, 0.5, 0.75};
constexpr double kChordShare = 0.8;
// Joint values this close are the same configuration (degrees, length units).
constexpr double kSameJoints = 1e-3;

// How far `p` is from the segment a..b.
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The tool frame in frame 0 from the last forward kinematics (frame n, or
// the chain's tool frame in it).
Eigen::Isometry3d toolIn0(const kinematics::ChainModel& chain, const kinematics::ChainData& data) {
  return chain.hasTool() ? data.F_0_i.back() * chain.F_n_tool() : data.F_0_i.back();
}

std::string percentAlong(double s) { return fmt::format("{:.1f}%", 100.0 * s); }

}  // namespace

struct LinePlanner::Line {
  Eigen::Vector3d p0, p1;      // the tool centre point's ends, frame 0
  Eigen::Quaterniond r0, r1;  // the tool's orientation at the ends, frame 0
  bool toPoint = false;        // the end's joint values are known (MOVES)
};

LinePath::LinePath(const LinePlanner& planner)
    : motors_(planner.motorCount()), data_(planner.chain()), prevData_(planner.chain()) {
  const auto n = static_cast<std::size_t>(planner.chain().size());
  for (std::vector<double>* v : {&q0_, &q1_, &prev_, &next_, &ref_, &mid_}) v->assign(n, 0.0);
  counts_.assign(std::max<std::size_t>(motors_, static_cast<std::size_t>(planner.chain().encoderCount())), 0.0);
}

LinePlanner::LinePlanner(const PlacedRobot& robot, LinePlanCache* cache)
    : robot_(robot),
      ik_(*robot.robot.chain),
      F_world_0_(robot.F_world_design * robot.robot.frames.front()),
      motors_(robot.robot.joints.size() + (robot.robot.hasGripper ? 1 : 0)),
      fullOrientation_(ik_.family() == kinematics::IkFamily::Articulated6 ||
                       ik_.family() == kinematics::IkFamily::Spherical6),
      cache_(cache) {
  if (cache_) armId_ = cache_->armId(armDescription());
}

namespace {

std::uint64_t word(double v) { return std::bit_cast<std::uint64_t>(v); }

void appendFrame(std::vector<std::uint64_t>& out, const Eigen::Isometry3d& F) {
  const Eigen::Matrix<double, 3, 4> m = F.affine();
  for (int i = 0; i < 12; ++i) out.push_back(word(m.data()[i]));
}

}  // namespace

// What plan() reads of the arm: the chain (its D-H rows and drives, the
// base), each joint's range and letter (the out-of-range check and its
// words), the base in the world (a problem's position) and the motors.
std::vector<std::uint64_t> LinePlanner::armDescription() const {
  std::vector<std::uint64_t> out{motors_, fullOrientation_ ? 1u : 0u};
  appendFrame(out, chain().F_world_0());
  appendFrame(out, F_world_0_);
  for (const kinematics::Joint& j : chain().joints()) {
    out.push_back(static_cast<std::uint64_t>(j.type()));
    for (const double v : {j.dh.theta, j.dh.alpha, j.dh.a, j.dh.d, j.precision}) out.push_back(word(v));
    out.push_back(static_cast<std::uint64_t>(j.encoder) << 1 | (j.coupling ? 1u : 0u));
  }
  for (const JointSpec& spec : robot_.robot.joints) {
    out.push_back(static_cast<std::uint64_t>(spec.type) << 8 | static_cast<unsigned char>(spec.letter));
    out.push_back(word(spec.precision));
    out.push_back(static_cast<std::uint64_t>(static_cast<std::uint32_t>(spec.min)) << 32 |
                  static_cast<std::uint32_t>(spec.max));
    out.push_back(spec.coupling ? 1u : 0u);
  }
  return out;
}

// A line's plan from the cache, or planned by `plan` and remembered. The
// key: the arm, the kind of line, the instruction's name, every motor at
// the start, and the end (every motor's target, or the distance).
template <typename Plan>
std::optional<LineProblem> LinePlanner::cached(std::uint64_t kind, std::span<const std::int32_t> start,
                                               std::span<const std::int32_t> end, double distance,
                                               std::string_view what, LinePath& path, Plan&& plan) const {
  if (!cache_) return plan();
  std::vector<std::uint64_t>& key = path.key_;
  key.clear();
  key.push_back(armId_);
  key.push_back(kind << 32 | what.size());
  for (std::size_t i = 0; i < what.size(); i += 8) {
    std::uint64_t w = 0;
    std::memcpy(&w, what.data() + i, std::min<std::size_t>(8, what.size() - i));
    key.push_back(w);
  }
  key.push_back(start.size() << 32 | end.size());
  for (const std::int32_t v : start) key.push_back(static_cast<std::uint32_t>(v));
  for (const std::int32_t v : end) key.push_back(static_cast<std::uint32_t>(v));
  key.push_back(word(distance));
  LinePlanCache::Plan found;
  if (cache_->find(key, found)) {
    path.knots_ = std::move(found.knots);
    path.leads_ = std::move(found.leads);
    return found.problem;
  }
  std::optional<LineProblem> problem = plan();
  cache_->remember(key, {path.knots_, path.leads_, problem});
  return problem;
}

Eigen::Vector3d LinePlanner::tcpOf(std::span<const double> q, LinePath& path) const {
  kinematics::forwardKinematics(chain(), path.data_, q);
  return toolIn0(chain(), path.data_).translation();
}

int LinePlanner::countsOf(std::span<const double> q, LinePath& path) const {
  const auto joints = chain().joints();
  int outside = -1;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const kinematics::Joint& j = joints[i];
    double raw = q[i];
    if (i > 0 && joints[i - 1].coupling) raw += q[i - 1] - joints[i - 1].home;
    const double count = std::round((raw - j.home) / j.precision);
    const JointSpec& spec = robot_.robot.joints[static_cast<std::size_t>(j.encoder)];
    if (outside < 0 && (count < spec.min || count > spec.max)) outside = static_cast<int>(i);
    path.counts_[static_cast<std::size_t>(j.encoder)] = count;
  }
  return outside;
}

std::string LinePlanner::configName(std::uint8_t config) const {
  std::uint8_t used = 0;
  for (const std::uint8_t c : ik_.configurations()) used |= c;
  std::string out;
  const auto add = [&](std::uint8_t bit, const char* on, const char* off) {
    if (!(used & bit)) return;
    out += fmt::format("{}{}", out.empty() ? "" : ", ", (config & bit) ? on : off);
  };
  add(kinematics::kShoulderBack, "reaching back", "facing the point");
  add(kinematics::kElbowDown, "elbow down", "elbow up");
  add(kinematics::kWristFlip, "wrist flipped", "wrist not flipped");
  return out.empty() ? std::string("its one configuration") : out;
}

// The joint values at fraction s of the line, in configuration `config`,
// each revolute joint turned by whole turns nearest the knot before
// (path.prev_): into path.next_.
bool LinePlanner::solveAt(const Line& line, double s, std::uint8_t config, LinePath& path,
                          kinematics::IkError& error) const {
  const auto n = path.next_.size();
  for (std::size_t i = 0; i < n; ++i)
    path.ref_[i] = line.toPoint ? path.q0_[i] + s * (path.q1_[i] - path.q0_[i]) : path.q0_[i];
  kinematics::ToolTarget target;
  target.position = line.p0 + s * (line.p1 - line.p0);
  if (fullOrientation_) {
    target.rotation = line.r0.slerp(s, line.r1).toRotationMatrix();
    target.approachGiven = target.normalGiven = true;
  } else {
    // What the arm keeps of its orientation (a SCARA's heading, a five-axis
    // arm's pitch and roll) turns with the joints that set it, evenly.
    kinematics::forwardKinematics(chain(), path.data_, path.ref_);
    target.rotation = toolIn0(chain(), path.data_).linear();
  }
  const kinematics::IkSolutions solved = ik_.solveConfig(target, path.ref_, config);
  if (!solved.ok()) {
    error = solved.error;
    return false;
  }
  const auto joints = chain().joints();
  for (std::size_t i = 0; i < n; ++i) {
    double v = solved.solutions[0].q[i];
    if (joints[i].type() == JointType::Revolute) v += 360.0 * std::round((path.prev_[i] - v) / 360.0);
    path.next_[i] = v;
  }
  return true;
}

std::optional<LineProblem> LinePlanner::planTo(std::span<const std::int32_t> start, std::span<const std::int32_t> end,
                                               LinePath& path, std::string_view what) const {
  return cached(0, start, end, 0.0, what, path, [&] {
    kinematics::jointValuesFromEncoders(chain(), start, path.q0_);
    kinematics::jointValuesFromEncoders(chain(), end, path.q1_);
    Line line;
    line.toPoint = true;
    kinematics::forwardKinematics(chain(), path.data_, path.q0_);
    line.p0 = toolIn0(chain(), path.data_).translation();
    line.r0 = Eigen::Quaterniond(toolIn0(chain(), path.data_).linear());
    kinematics::forwardKinematics(chain(), path.data_, path.q1_);
    line.p1 = toolIn0(chain(), path.data_).translation();
    line.r1 = Eigen::Quaterniond(toolIn0(chain(), path.data_).linear());
    return plan(line, start, path, end, what);
  });
}

std::optional<LineProblem> LinePlanner::planAlongTool(std::span<const std::int32_t> start, double distance,
                                                      LinePath& path, std::string_view what) const {
  return cached(1, start, {}, distance, what, path, [&] {
    kinematics::jointValuesFromEncoders(chain(), start, path.q0_);
    path.q1_ = path.q0_;
    Line line;
    kinematics::forwardKinematics(chain(), path.data_, path.q0_);
    const Eigen::Isometry3d F = toolIn0(chain(), path.data_);
    line.p0 = F.translation();
    line.p1 = line.p0 + distance * F.linear().col(2);
    line.r0 = line.r1 = Eigen::Quaterniond(F.linear());
    return plan(line, start, path, {}, what);
  });
}

std::optional<LineProblem> LinePlanner::plan(const Line& line, std::span<const std::int32_t> start, LinePath& path,
                                             std::span<const std::int32_t> end, std::string_view what) const {
  path.knots_.clear();
  path.leads_.clear();
  const auto n = path.next_.size();
  const auto problem = [&](double s, std::string message, std::string hint, std::string_view code) {
    LineProblem p;
    p.fraction = s;
    p.position = F_world_0_ * (line.p0 + s * (line.p1 - line.p0));
    p.message = std::move(message);
    p.hint = std::move(hint);
    p.code = code;
    return p;
  };
  // A MOVES can go round through a via point; APPRO and DEPART are one
  // segment along the tool's approach axis, which no via point moves.
  const std::string viaHint =
      line.toPoint ? std::string("go through a via point the arm reaches on the way (a MOVES to it first), or make "
                                 "this move a joint move (MOVEP)")
                   : fmt::format("{} is one straight segment along the tool's approach axis, which no via point "
                                 "changes: start it from another pose, or make this move a joint move (MOVEP)",
                                 what);
  const auto ikProblem = [&](double s, const kinematics::IkError& e) {
    const bool singular = e.kind == IkErrorKind::Singular;
    const char* what2 = singular ? "passes near a singular pose"
                        : e.kind == IkErrorKind::OrientationFixed ? "asks for an orientation the arm cannot take"
                                                                  : "leaves the arm's reach";
    const Eigen::Vector3d at = F_world_0_ * (line.p0 + s * (line.p1 - line.p0));
    return problem(s,
                   fmt::format("{} {} {} along the line, at ({:.4g}, {:.4g}, {:.4g}): {}", what, what2, percentAlong(s),
                               at.x(), at.y(), at.z(), e.message),
                   viaHint, singular ? "line-singular" : "line-unreachable");
  };

  // The configuration the arm starts in: the one whose solution at the
  // start is where the arm is.
  path.prev_ = path.q0_;
  std::optional<std::uint8_t> config;
  kinematics::IkError firstError;
  bool anySolution = false;
  for (const std::uint8_t c : ik_.configurations()) {
    kinematics::IkError e;
    if (!solveAt(line, 0.0, c, path, e)) {
      if (firstError.message.empty()) firstError = e;
      continue;
    }
    anySolution = true;
    double diff = 0;
    for (std::size_t i = 0; i < n; ++i) diff = std::max(diff, std::abs(path.next_[i] - path.q0_[i]));
    if (diff < kSameJoints) {
      config = c;
      break;
    }
  }
  if (!config) {
    if (!anySolution) return ikProblem(0.0, firstError);
    return problem(0.0, fmt::format("{} cannot start here: no configuration of the arm's solutions is its pose", what),
                   "make this move a joint move (MOVEP)", "line-configuration");
  }
  // MOVES: the point's pose in the same configuration, or the line would
  // end in a flip.
  if (line.toPoint) {
    kinematics::IkError e;
    path.prev_ = path.q1_;
    bool same = solveAt(line, 1.0, *config, path, e);
    if (same)
      for (std::size_t i = 0; i < n; ++i) same = same && std::abs(path.next_[i] - path.q1_[i]) < kSameJoints;
    if (!same) {
      std::optional<std::uint8_t> endConfig;
      for (const std::uint8_t c : ik_.configurations()) {
        if (!solveAt(line, 1.0, c, path, e)) continue;
        double diff = 0;
        for (std::size_t i = 0; i < n; ++i) diff = std::max(diff, std::abs(path.next_[i] - path.q1_[i]));
        if (diff < kSameJoints) {
          endConfig = c;
          break;
        }
      }
      return problem(1.0,
                     fmt::format("{} would change the arm's configuration: it starts {}, and the point's pose is {}",
                                 what, configName(*config),
                                 endConfig ? configName(*endConfig) : std::string("in another configuration")),
                     "teach the point in the configuration the arm starts in, or move there with a joint move (MOVEP)",
                     "line-configuration");
    }
  }

  path.prev_ = path.q0_;
  bool prevFramed = false;  // path.prevData_ holds prev_'s frames
  const Eigen::Vector3d& a = line.p0;
  const Eigen::Vector3d& b = line.p1;
  const Eigen::Vector3d forward = (b - a).norm() > 0 ? Eigen::Vector3d((b - a).normalized()) : Eigen::Vector3d::Zero();
  double s = 0, ds = kMaxStep;
  while (s < 1.0) {
    const double s1 = std::min(1.0, s + ds);
    const bool canHalve = ds > kMinStep;
    kinematics::IkError e;
    if (!solveAt(line, s1, *config, path, e)) {
      if (canHalve) { ds /= 2; continue; }
      return ikProblem(s1, e);
    }
    const auto joints = chain().joints();
    double turn = 0;
    std::size_t turned = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (joints[i].type() == JointType::Revolute && std::abs(path.next_[i] - path.prev_[i]) > turn)
        turn = std::abs(path.next_[i] - path.prev_[i]), turned = i;
    if (turn > kMaxKnotTurn) {
      if (canHalve) { ds /= 2; continue; }
      return problem(s1,
                     fmt::format("{} would flip the arm {} along the line: joint {} turns {:.4g} degrees within {} "
                                 "of the line (an elbow or a wrist passing straight)",
                                 what, percentAlong(s1), turned + 1, turn, percentAlong(ds)),
                     viaHint, "line-configuration");
    }
    if (const int out = countsOf(path.next_, path); out >= 0) {
      if (canHalve) { ds /= 2; continue; }
      const kinematics::Joint& j = joints[static_cast<std::size_t>(out)];
      const JointSpec& spec = robot_.robot.joints[static_cast<std::size_t>(j.encoder)];
      const Eigen::Vector3d at = F_world_0_ * (line.p0 + s1 * (line.p1 - line.p0));
      return problem(s1,
                     fmt::format("{} takes motor {} to {}, outside its range {}..{}, {} along the line, at ({:.4g}, "
                                 "{:.4g}, {:.4g})",
                                 what, spec.letter, path.counts_[static_cast<std::size_t>(j.encoder)], spec.min,
                                 spec.max, percentAlong(s1), at.x(), at.y(), at.z()),
                     viaHint, "line-out-of-range");
    }
    // Each motor's share of the knot, as far as it moves the tool on its
    // own: the most a motor running ahead of the others (a controller that
    // moves each motor at its own speed) takes the tool off the lock-step path.
    // Which motors lead: in the first half of the line those that carry
    // the tool forward (it never falls back behind where it started: a
    // block lifted off a pallet does not dip into it), in the second half
    // those that carry it back (it never runs past where it ends: a block
    // set down does not sink into what it lands on).
    // The checks below either pass or halve the step (unless it is the
    // shortest, which is taken whatever they say), so their order changes
    // no knot: the shares first, as they fail most, each from the frames of
    // the knot before (the same bits as a whole forward pass), and the sum
    // of the shares abandoned once it is past the bound.
    const bool firstHalf = s + s1 < 1.0;
    if (!prevFramed) kinematics::forwardKinematics(chain(), path.prevData_, path.prev_), prevFramed = true;
    const Eigen::Vector3d here = path.prevData_.F_0_i.back().translation();
    double travel = 0;
    std::uint32_t lead = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d share = kinematics::positionWithJoint(chain(), path.prevData_, i, path.next_[i]) - here;
      travel += share.norm();
      if (travel > kKnotTravel && canHalve) break;
      const auto motor = static_cast<unsigned>(joints[i].encoder);
      const double along = share.dot(forward);
      if ((firstHalf ? along > 0 : along < 0) && motor < 32) lead |= 1u << motor;
    }
    if (travel > kKnotTravel && canHalve) { ds /= 2; continue; }
    bool close = true;
    for (const double f : kChordSamples) {
      if (!canHalve) break;  // the shortest step is taken whatever the chord
      for (std::size_t i = 0; i < n; ++i) path.mid_[i] = path.prev_[i] + f * (path.next_[i] - path.prev_[i]);
      if (distanceToSegment(tcpOf(path.mid_, path), a, b) > kChordShare * kLineTolerance) close = false;
      if (!close) break;  // the step is halved whatever the rest say
    }
    if (!close) { ds /= 2; continue; }
    // The knot: the end exactly, else the joints rounded to counts (the
    // gripper keeps its opening).
    if (path.size() >= kMaxLineKnots)
      return problem(s1, fmt::format("{} needs more than {} small moves to stay on the line", what, kMaxLineKnots),
                     viaHint, "line-too-long");
    if (s1 >= 1.0 && !end.empty()) {
      const std::size_t first = path.knots_.size();
      path.knots_.insert(path.knots_.end(), start.begin(), start.begin() + static_cast<long>(motors_));
      for (std::size_t i = 0; i < n; ++i) {
        const auto e2 = static_cast<std::size_t>(joints[i].encoder);
        path.knots_[first + e2] = end[e2];
      }
    } else {
      countsOf(path.next_, path);
      const std::size_t first = path.knots_.size();
      path.knots_.insert(path.knots_.end(), start.begin(), start.begin() + static_cast<long>(motors_));
      for (std::size_t i = 0; i < n; ++i) {
        const auto e2 = static_cast<std::size_t>(joints[i].encoder);
        path.knots_[first + e2] = static_cast<std::int32_t>(path.counts_[e2]);
      }
      // A knot the whole counts leave where the one before is: no move.
      const std::int32_t* before = first >= motors_ ? path.knots_.data() + first - motors_ : start.data();
      if (std::equal(before, before + motors_, path.knots_.data() + first)) path.knots_.resize(first);
    }
    if (path.leads_.size() < path.size()) path.leads_.push_back(lead);
    path.prev_ = path.next_;
    prevFramed = false;
    s = s1;
    ds = std::min(kMaxStep, ds * 2);
  }
  return std::nullopt;
}

}  // namespace rs::workcell
