#include "model/workcell/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/kinematics/joint_values.h"

namespace rs::workcell {

namespace {

using kinematics::ChainModel;
using kinematics::IkSolution;
using kinematics::JointType;

// Two directions at right angles within this cosine are taken as meant to be.
constexpr double kPerpendicular = 1e-3;

Eigen::Isometry3d toolFrame(const ChainModel& chain, std::span<const double> q) {
  Eigen::Isometry3d F = Eigen::Isometry3d::Identity();
  for (int i = 1; i <= chain.size(); ++i) F = F * kinematics::dhTransform(chain.joint(i).dh, q[static_cast<std::size_t>(i - 1)]);
  return F;
}

// One solution made into encoder counts, each revolute joint turned by whole
// turns to the value nearest the previous point's that its motor can reach.
struct Candidate {
  std::vector<double> q;
  std::vector<std::int64_t> counts;  // per arm motor
  int outside = -1;                  // first joint (0-based) out of range, -1 if none
  double seconds = 0, travel = 0;    // the move from the previous point
  std::uint8_t config = 0;
};

}  // namespace

PoseSolver::PoseSolver(const PlacedRobot& robot)
    : robot_(robot),
      ik_(*robot.robot.chain),
      F_world_0_(robot.F_world_design * robot.robot.frames.front()),
      F_design_0_(robot.robot.frames.front()) {}

PoseSolver::Kept PoseSolver::kept(std::span<const std::int32_t> reference, std::span<const double> referenceQ) const {
  const ChainModel& chain = ik_.model();
  const auto n = static_cast<std::size_t>(chain.size());
  Kept k;
  k.refQ.assign(n, 0.0);
  k.refEncoders.assign(reference.begin(), reference.end());
  k.refEncoders.resize(std::max<std::size_t>(k.refEncoders.size(), static_cast<std::size_t>(chain.encoderCount())), 0.0);
  kinematics::jointValuesFromEncoders(chain, std::span<const double>(k.refEncoders), k.refQ);
  if (referenceQ.size() == n) k.refQ.assign(referenceQ.begin(), referenceQ.end());
  k.R_ref = toolFrame(chain, k.refQ).linear();
  return k;
}

PoseResult PoseSolver::solve(const PoseRequest& request, std::span<const std::int32_t> reference,
                             std::span<const double> referenceQ) const {
  const Kept k = kept(reference, referenceQ);
  kinematics::ToolTarget target;
  if (std::optional<PoseProblem> problem = targetOf(request, k, target)) {
    PoseResult result;
    result.problem = std::move(problem);
    return result;
  }
  return solveTarget(request, target, k, reference);
}

std::optional<PoseProblem> PoseSolver::targetOf(const PoseRequest& request, const Kept& k,
                                                kinematics::ToolTarget& target) const {
  const auto fail = [](PoseField field, std::string message, std::string hint, std::string_view code) {
    return std::optional<PoseProblem>(PoseProblem{field, std::move(message), std::move(hint), code});
  };
  const Eigen::Matrix3d& R_ref = k.R_ref;
  // The target in frame 0; what is not written comes from the previous point.
  const Eigen::Isometry3d& F_X_0 = frame0(request.robotFrame);
  target.position = F_X_0.inverse() * request.position;
  Eigen::Vector3d a = R_ref.col(2), nrm = R_ref.col(0);
  if (request.approach) {
    if (request.approach->norm() < 1e-9) return fail(PoseField::Approach, "APPROACH is a zero vector", "give a direction, e.g. APPROACH 0 0 -1", "pose-vector");
    a = F_X_0.linear().transpose() * request.approach->normalized();
    target.approachGiven = true;
  }
  if (request.normal) {
    if (request.normal->norm() < 1e-9) return fail(PoseField::Normal, "NORMAL is a zero vector", "give a direction, e.g. NORMAL 1 0 0", "pose-vector");
    nrm = F_X_0.linear().transpose() * request.normal->normalized();
    target.normalGiven = true;
  }
  if (target.approachGiven && target.normalGiven && std::abs(a.dot(nrm)) > kPerpendicular)
    return fail(PoseField::Normal,
                fmt::format("NORMAL must be at right angles to APPROACH; they are {:.4g} degrees apart",
                            std::acos(std::clamp(a.dot(nrm), -1.0, 1.0)) * kinematics::kRadToDeg),
                "the normal is the direction the fingers close along, across the approach", "pose-vector");
  // Made exactly perpendicular, keeping the written axis (the approach when both are).
  if (target.normalGiven && !target.approachGiven) {
    a -= a.dot(nrm) * nrm;
    if (a.norm() < 1e-9) a = nrm.cross(R_ref.col(1));
    a.normalize();
  } else {
    nrm -= nrm.dot(a) * a;
    if (nrm.norm() < 1e-9) nrm = R_ref.col(1).cross(a);
    nrm.normalize();
  }
  target.rotation.col(0) = nrm;
  target.rotation.col(1) = a.cross(nrm);
  target.rotation.col(2) = a;
  return std::nullopt;
}

std::string PoseSolver::orientationWords(const PoseRequest& request, const Eigen::Matrix3d& R_0) const {
  const Eigen::Matrix3d R = frame0(request.robotFrame).linear() * R_0;
  const char* sep = request.optionWords ? "," : " ";
  const auto axis = [&](int c) {
    const auto num = [](double v) { return fmt::format("{:.4g}", std::abs(v) < 5e-5 ? 0.0 : v); };
    return fmt::format("{}{}{}{}{}", num(R(0, c)), sep, num(R(1, c)), sep, num(R(2, c)));
  };
  return request.optionWords ? fmt::format("--approach {} --normal {}", axis(2), axis(0))
                             : fmt::format("APPROACH {} NORMAL {}", axis(2), axis(0));
}

PoseResult PoseSolver::solveTarget(const PoseRequest& request, const kinematics::ToolTarget& target, const Kept& from,
                                   std::span<const std::int32_t> reference) const {
  PoseResult result;
  const ChainModel& chain = ik_.model();
  const Robot& robot = robot_.robot;
  const auto n = static_cast<std::size_t>(chain.size());
  const auto fail = [&](PoseField field, std::string message, std::string hint, std::string_view code) {
    result.problem = PoseProblem{field, std::move(message), std::move(hint), code};
    return result;
  };
  const std::vector<double>& refQ = from.refQ;
  const std::vector<double>& refEncoders = from.refEncoders;
  const kinematics::IkSolutions solved =
      request.configuration ? ik_.solveConfig(target, refQ, *request.configuration) : ik_.solve(target, refQ);
  if (!solved.ok()) {
    const PoseField field = solved.error.kind != kinematics::IkErrorKind::OrientationFixed ? PoseField::Position
                            : request.approach                                         ? PoseField::Approach
                                                                                       : PoseField::Normal;
    const kinematics::IkErrorKind kind = solved.error.kind;
    std::string hint = solved.error.hint;
    if (kind == kinematics::IkErrorKind::OrientationFixed) {
      // What the arm does reach at this point, in the request's coordinates.
      kinematics::ToolTarget free = target;
      free.approachGiven = free.normalGiven = false;
      const kinematics::IkSolutions near = ik_.solve(free, refQ);
      if (near.ok()) {
        const std::vector<double> q(near.solutions[0].q.begin(), near.solutions[0].q.begin() + static_cast<long>(n));
        hint = "here it reaches " + orientationWords(request, toolFrame(chain, q).linear());
      }
    }
    return fail(field, solved.error.message, hint,
                kind == kinematics::IkErrorKind::Singular           ? "pose-singular"
                : kind == kinematics::IkErrorKind::OrientationFixed ? "pose-orientation"
                                                                     : "pose-unreachable");
  }
  result.solutions = solved.count;

  // Each solution in encoder counts; the quickest move in range wins.
  std::vector<Candidate> candidates;
  for (const IkSolution& s : solved.view()) {
    Candidate c;
    c.config = s.config;
    c.q.assign(s.q.begin(), s.q.begin() + static_cast<long>(n));
    c.counts.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const kinematics::Joint& j = chain.joints()[i];
      const JointSpec& spec = robot.joints[static_cast<std::size_t>(j.encoder)];
      const auto countOf = [&](double qi) {
        double raw = qi;
        if (i > 0 && chain.joints()[i - 1].coupling) raw += c.q[i - 1] - chain.joints()[i - 1].home;
        return std::llround((raw - j.home) / j.precision);
      };
      if (j.type() == JointType::Revolute) {
        // Whole turns: the in-range value nearest the previous point's, else the nearest.
        double best = c.q[i];
        bool bestIn = false;
        for (int k = -2; k <= 2; ++k) {
          const double v = c.q[i] + 360.0 * k;
          const std::int64_t e = countOf(v);
          const bool in = e >= spec.min && e <= spec.max;
          if ((in && !bestIn) || (in == bestIn && std::abs(v - refQ[i]) < std::abs(best - refQ[i]))) best = v, bestIn = in;
        }
        c.q[i] = best;
      }
      c.counts[i] = countOf(c.q[i]);
      if (c.outside < 0 && (c.counts[i] < spec.min || c.counts[i] > spec.max)) c.outside = static_cast<int>(i);
      const double delta = std::abs(static_cast<double>(c.counts[i]) - refEncoders[static_cast<std::size_t>(j.encoder)]);
      c.seconds = std::max(c.seconds, delta / std::max(1, spec.speed));
      c.travel += delta;
    }
    candidates.push_back(std::move(c));
  }
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates) {
    if (c.outside >= 0) continue;
    ++result.inRange;
    if (!best || c.seconds < best->seconds - 1e-12 || (std::abs(c.seconds - best->seconds) <= 1e-12 && c.travel < best->travel))
      best = &c;
  }
  if (!best) {
    const Candidate& c = candidates.front();
    const auto i = static_cast<std::size_t>(c.outside);
    const kinematics::Joint& j = chain.joints()[i];
    const JointSpec& spec = robot.joints[static_cast<std::size_t>(j.encoder)];
    return fail(PoseField::Position,
                fmt::format("the pose needs motor {} at {} (joint {} at {:.4g} {}), outside its range {}..{}",
                            spec.letter, c.counts[i], i + 1, c.q[i],
                            j.type() == JointType::Revolute ? "degrees" : "length units", spec.min, spec.max),
                fmt::format("{} solution{} of this pose {} tried, and each puts a motor out of its range: move the "
                            "point",
                            candidates.size(), candidates.size() == 1 ? "" : "s",
                            candidates.size() == 1 ? "was" : "were"),
                "pose-out-of-range");
  }
  result.q = best->q;
  result.config = best->config;
  result.encoders.assign(motorCount(), 0);
  for (std::size_t i = 0; i < n; ++i)
    result.encoders[static_cast<std::size_t>(chain.joints()[i].encoder)] = static_cast<std::int32_t>(best->counts[i]);
  if (robot.hasGripper) {
    const std::size_t g = result.encoders.size() - 1;
    std::int32_t grip = g < reference.size() ? reference[g] : 0;
    if (request.grip) {
      grip = *request.grip;
      if (grip < robot.gripper.min || grip > robot.gripper.max)
        return fail(PoseField::Grip,
                    fmt::format("GRIP {} for motor {} is outside its range {}..{}", grip, robot.gripper.letter,
                                robot.gripper.min, robot.gripper.max),
                    fmt::format("{} is open, {} closed", robot.gripper.min, robot.gripper.max), "pose-grip");
    }
    result.encoders[g] = grip;
  } else if (request.grip) {
    return fail(PoseField::Grip, fmt::format("robot {} has no gripper to set with GRIP", robot.name), "leave GRIP out", "pose-grip");
  }
  // How far the whole counts put the tool from the exact solution.
  std::vector<double> counts(result.encoders.begin(), result.encoders.end()), q(n);
  counts.resize(std::max<std::size_t>(counts.size(), static_cast<std::size_t>(chain.encoderCount())), 0.0);
  kinematics::jointValuesFromEncoders(chain, std::span<const double>(counts), q);
  result.rounding = (toolFrame(chain, q).translation() - target.position).norm();
  result.rotation = frame0(request.robotFrame).linear() * toolFrame(chain, result.q).linear();
  return result;
}

}  // namespace rs::workcell
