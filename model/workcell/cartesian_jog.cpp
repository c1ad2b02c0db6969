#include "model/workcell/cartesian_jog.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/number_text.h"
#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/kinematics/joint_values.h"

namespace rs::workcell {

namespace {

using kinematics::IkFamily;
using kinematics::JointType;

// F_0_n for joint values q (the jog's own forward kinematics: the D-H product).
Eigen::Isometry3d jogChainFrame(const kinematics::ChainModel& chain, std::span<const double> q) {
  Eigen::Isometry3d F = Eigen::Isometry3d::Identity();
  for (int i = 1; i <= chain.size(); ++i)
    F = F * kinematics::dhTransform(chain.joint(i).dh, q[static_cast<std::size_t>(i - 1)]);
  return F;
}

// How far apart two joint values are, a revolute joint's modulo whole turns.
double jointGap(JointType type, double a, double b) {
  if (type != JointType::Revolute) return std::abs(a - b);
  return std::abs(kinematics::normalizeDegrees(a - b));
}

constexpr const char* kAxisLetters[3] = {"X", "Y", "Z"};
constexpr const char* kToolAxisWords[3] = {"x (the normal)", "y", "z (the approach)"};

// The frame axis (0..2) that `u` lies along, or -1.
int alongFrameAxis(const Eigen::Matrix3d& frame, const Eigen::Vector3d& u) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(frame.col(k).dot(u)) > 1.0 - 1e-9) return k;
  return -1;
}

// The limit a line's problem (LineProblem::code) is, in a jog's words.
JogLimit lineLimit(std::string_view code) {
  if (code == "line-unreachable") return JogLimit::Reach;
  if (code == "line-out-of-range") return JogLimit::Range;
  if (code == "line-too-long") return JogLimit::Step;
  return JogLimit::Singularity;  // line-singular, and line-configuration: a flip, which passes a singular pose
}

}  // namespace

std::string_view jogFrameName(JogFrame frame) { return frame == JogFrame::World ? "world" : "tool"; }

std::string_view jogLimitName(JogLimit limit) {
  switch (limit) {
    case JogLimit::Range: return "range";
    case JogLimit::Reach: return "reach";
    case JogLimit::Singularity: return "singularity";
    case JogLimit::Collision: return "collision";
    case JogLimit::Axis: return "axis";
    case JogLimit::Step: return "step";
  }
  return "range";
}

CartesianJog::CartesianJog(const PlacedRobot& robot)
    : robot_(robot),
      ik_(*robot.robot.chain),
      F_world_0_(robot.F_world_design * robot.robot.frames.front()),
      line_(robot) {}

JogPose CartesianJog::poseAt(std::span<const std::int32_t> encoders) const {
  const kinematics::ChainModel& chain = ik_.model();
  JogPose p;
  p.encoders.assign(encoders.begin(), encoders.end());
  std::vector<double> counts(encoders.begin(), encoders.end());
  counts.resize(std::max<std::size_t>(counts.size(), static_cast<std::size_t>(chain.encoderCount())), 0.0);
  p.q.assign(static_cast<std::size_t>(chain.size()), 0.0);
  kinematics::jointValuesFromEncoders(chain, std::span<const double>(counts), p.q);
  const Eigen::Isometry3d F_0_n = jogChainFrame(chain, p.q);
  p.tool = F_world_0_ * F_0_n;
  // The configuration: that of the solution of this very pose nearest these joint values.
  kinematics::ToolTarget here;
  here.position = F_0_n.translation();
  here.rotation = F_0_n.linear();
  here.approachGiven = here.normalGiven = true;
  const kinematics::IkSolutions all = ik_.solve(here, p.q);
  double nearest = INFINITY;
  for (const kinematics::IkSolution& s : all.view()) {
    double gap = 0;
    for (std::size_t i = 0; i < p.q.size(); ++i) gap += jointGap(chain.joints()[i].type(), s.q[i], p.q[i]);
    if (gap < nearest) nearest = gap, p.config = s.config, p.configKnown = true;
  }
  return p;
}

std::vector<JogAxis> CartesianJog::axes(const JogPose& pose, JogFrame frame) const {
  const bool world = frame == JogFrame::World;
  const Eigen::Matrix3d axesOf = world ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(pose.tool.linear());
  const auto where = [&](int k) {
    return world ? fmt::format("the world's {}", kAxisLetters[k]) : fmt::format("the tool's {}", kToolAxisWords[k]);
  };
  std::vector<JogAxis> out;
  for (int k = 0; k < 3; ++k) out.push_back({kAxisLetters[k], false, axesOf.col(k), "along " + where(k)});
  // A rotation about a fixed axis of the arm, named by the frame's axis it lies along (else by `name`).
  const auto about = [&](const Eigen::Vector3d& u, const std::string& name, const std::string& what) {
    const int k = alongFrameAxis(axesOf, u);
    if (k >= 0)
      out.push_back(
          {fmt::format("R{}", kAxisLetters[k]), true, axesOf.col(k), fmt::format("about {}, {}", where(k), what)});
    else
      out.push_back({name, true, u.normalized(), "about the joints' axis, " + what});
  };
  const kinematics::ChainModel& chain = ik_.model();
  switch (ik_.family()) {
    case IkFamily::Articulated6:
    case IkFamily::Spherical6:
      for (int k = 0; k < 3; ++k)
        out.push_back({fmt::format("R{}", kAxisLetters[k]), true, axesOf.col(k), "about " + where(k)});
      break;
    case IkFamily::Articulated5: {
      // Pitch: about the axis the pitch joints share (z_1), through the tool centre point; roll: about the approach.
      const Eigen::Vector3d z1 =
          F_world_0_.linear() * kinematics::dhTransform(chain.joint(1).dh, pose.q[0]).linear().col(2);
      out.push_back({"PITCH", true, z1.normalized(), "pitch: about the axis of the arm's pitch joints"});
      out.push_back({"ROLL", true, pose.tool.linear().col(2), "roll: about the tool's z (the approach)"});
      break;
    }
    case IkFamily::Scara:
      if (ik_.shape().run.revolutes == 3) about(F_world_0_.linear().col(2), "HEADING", "the heading");
      break;
    case IkFamily::Cartesian:
    case IkFamily::Numeric: break;
  }
  return out;
}

JogResult CartesianJog::jog(const JogPose& pose, JogFrame frame, std::string_view axisName, double amount) const {
  JogResult r;
  const auto refuse = [&](JogLimit limit, std::string message) {
    r.limit = limit;
    r.message = std::move(message);
    return r;
  };
  const std::vector<JogAxis> all = axes(pose, frame);
  const auto axis = std::find_if(all.begin(), all.end(), [&](const JogAxis& a) { return a.name == axisName; });
  if (axis == all.end()) {
    std::string names;
    for (const JogAxis& a : all) names += (names.empty() ? "" : " ") + a.name;
    return refuse(JogLimit::Axis, fmt::format("robot {} has no {} jog axis {} (it has {})", robot_.robot.name,
                                              jogFrameName(frame), axisName, names));
  }
  r.rotation = axis->rotation;
  if (axis->rotation && !(std::abs(amount) < kMaxTurn))
    return refuse(JogLimit::Step, fmt::format("a jog turns the tool less than {} degrees at a time (this one asks for "
                                              "{}): turn it in smaller steps",
                                              kMaxTurn, base::formatNumber(amount)));
  Eigen::Isometry3d wanted = pose.tool;
  if (axis->rotation)
    wanted.linear() =
        Eigen::AngleAxisd(amount * kinematics::kDegToRad, axis->direction).toRotationMatrix() * pose.tool.linear();
  else
    wanted.translation() += amount * axis->direction;

  const kinematics::ChainModel& chain = ik_.model();
  const Robot& robot = robot_.robot;
  const auto n = static_cast<std::size_t>(chain.size());
  const Eigen::Isometry3d F_0_tool = F_world_0_.inverse() * wanted;
  kinematics::ToolTarget target;
  target.position = F_0_tool.translation();
  target.rotation = F_0_tool.linear();
  // A six-axis arm keeps its whole orientation; the others keep what their family keeps (a five-axis arm its
  // pitch and roll, a SCARA its heading), and a turn writes the orientation it asks for.
  const bool six = ik_.family() == IkFamily::Articulated6 || ik_.family() == IkFamily::Spherical6;
  target.approachGiven = target.normalGiven = six || axis->rotation;
  const std::span<const std::uint8_t> configs = ik_.configurations();
  const bool known = pose.configKnown && std::find(configs.begin(), configs.end(), pose.config) != configs.end();
  const kinematics::IkSolutions solved =
      known ? ik_.solveConfig(target, pose.q, pose.config) : ik_.solve(target, pose.q);
  if (!solved.ok()) {
    const kinematics::IkErrorKind kind = solved.error.kind;
    const JogLimit limit = kind == kinematics::IkErrorKind::Singular           ? JogLimit::Singularity
                           : kind == kinematics::IkErrorKind::OrientationFixed ? JogLimit::Axis
                                                                               : JogLimit::Reach;
    return refuse(limit, solved.error.message);
  }
  // The solution nearest where the arm stands (the one, on its configuration), each revolute joint by whole
  // turns to the value nearest its present one.
  const kinematics::IkSolution* best = nullptr;
  double nearest = INFINITY;
  for (const kinematics::IkSolution& s : solved.view()) {
    double gap = 0;
    for (std::size_t i = 0; i < n; ++i) gap += jointGap(chain.joints()[i].type(), s.q[i], pose.q[i]);
    if (gap < nearest) nearest = gap, best = &s;
  }
  std::vector<double> q(best->q.begin(), best->q.begin() + static_cast<long>(n));
  for (std::size_t i = 0; i < n; ++i)
    if (chain.joints()[i].type() == JointType::Revolute) q[i] = pose.q[i] + kinematics::normalizeDegrees(q[i] - pose.q[i]);
  // Encoder counts (a coupled joint's motor also carries the joint before it), each within its motor's range.
  r.pose.encoders = pose.encoders;
  r.pose.encoders.resize(std::max<std::size_t>(r.pose.encoders.size(), static_cast<std::size_t>(chain.encoderCount())),
                         0);
  std::string outside;  // the first motor the end puts outside its range
  for (std::size_t i = 0; i < n; ++i) {
    const kinematics::Joint& j = chain.joints()[i];
    double raw = q[i];
    if (i > 0 && chain.joints()[i - 1].coupling) raw += q[i - 1] - chain.joints()[i - 1].home;
    const std::int64_t count =
        std::clamp<std::int64_t>(std::llround((raw - j.home) / j.precision), INT32_MIN, INT32_MAX);
    const JointSpec& spec = robot.joints[static_cast<std::size_t>(j.encoder)];
    if ((count < spec.min || count > spec.max) && outside.empty())
      outside = fmt::format("motor {} would go to {} (joint {} at {:.4g} {}), outside its range {}..{}", spec.letter,
                            count, i + 1, q[i], j.type() == JointType::Revolute ? "degrees" : "length units", spec.min,
                            spec.max);
    r.pose.encoders[static_cast<std::size_t>(j.encoder)] = static_cast<std::int32_t>(count);
  }
  // The way there: the straight line MOVES would run, checked as it checks
  // it (a singular pose, the reach, a motor's range or a flip on the way).
  // Near a singular pose the end's counts can be far off and out of range:
  // the line names the singular pose first; an end out of range is named
  // by the motor it leaves.
  LinePath path(line_);
  const std::optional<LineProblem> problem = line_.planTo(pose.encoders, r.pose.encoders, path, "the jog");
  if (problem && problem->code != "line-out-of-range") return refuse(lineLimit(problem->code), problem->message);
  if (!outside.empty()) return refuse(JogLimit::Range, std::move(outside));
  if (problem) return refuse(JogLimit::Range, problem->message);
  r.pose.q = q;
  r.pose.config = best->config;
  r.pose.configKnown = true;
  r.pose.tool = F_world_0_ * jogChainFrame(chain, q);
  return r;
}

}  // namespace rs::workcell
