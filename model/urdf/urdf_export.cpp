#include "model/urdf/urdf_export.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "model/kinematics/angles.h"
#include "model/kinematics/dh.h"
#include "model/urdf/urdf_export_geometry.h"
#include "model/urdf/urdf_xml.h"
#include "model/workcell/ega_palette.h"

namespace rs::urdf {

std::string jointName(int joint) { return "joint_" + std::to_string(joint); }
std::string linkName(int joint) { return "link_" + std::to_string(joint); }

namespace {

using kinematics::JointType;
using Attributes = XmlWriter::Attributes;

// Where a URDF link's frame is: base_link (the design coordinates, turned
// and scaled) or a frame given in design coordinates.
struct LinkFrame {
  std::optional<Eigen::Isometry3d> F_design_link;  // empty: base_link
};

// A joint's limits in URDF's units (radians or metres, per second).
struct Limits {
  double lower = 0, upper = 0, velocity = 0;
};

class Exporter {
 public:
  Exporter(const workcell::Robot& robot, const ExportOptions& options)
      : robot_(robot), chain_(*robot.chain), n_(chain_.size()), design_(options.millimetresPerUnit, options.up),
        options_(options) {
    homeFrames();
    // D-H frame 0 gets a link of its own where it is not base_link's frame:
    // a reader finds it there (model/urdf/urdf_dh.h), as it could not from
    // joint 1's axis alone (where on the axis, which way x_0 points).
    const Eigen::Isometry3d& F0 = F_[0];
    frame0Link_ = n_ > 0 && (!(upTurn(options.up) * F0.linear() - Eigen::Matrix3d::Identity()).isZero(1e-12) ||
                             !F0.translation().isZero(1e-12));
  }

  std::string write() {
    xml_.declaration();
    xml_.open("robot", {{"name", robot_.name}});
    header();
    materials();
    link(std::string(kBaseLink), robot_.links.empty() ? nullptr : &robot_.links[0], {});
    if (frame0Link_) frame0();
    for (int i = 1; i <= n_; ++i) armJoint(i);
    if (robot_.hasGripper) gripper();
    tool();
    xml_.close();
    return xml_.take();
  }

 private:
  // J_[i]: link i's URDF frame at home, on joint i's axis (the D-H frame
  // i-1 turned by θ_i and moved by d_i); F_[i]: the D-H frame i. Built from
  // the D-H table as forward kinematics builds them: F_i = J_i · Tx(a_i) · Rx(α_i).
  void homeFrames() {
    J_.assign(static_cast<std::size_t>(n_) + 1, Eigen::Isometry3d::Identity());
    F_.assign(static_cast<std::size_t>(n_) + 1, chain_.F_world_0());
    for (int i = 1; i <= n_; ++i) {
      const kinematics::DhRow& row = chain_.joint(i).dh;
      const auto k = static_cast<std::size_t>(i);
      J_[k] = F_[k - 1] * kinematics::dhTransform({row.type, row.theta, 0, 0, row.d}, row.home());
      F_[k] = J_[k] * kinematics::dhTransform({JointType::Revolute, 0, row.alpha, row.a, 0}, 0);
    }
  }

  LinkFrame armLink(int i) const {
    if (i == 0) return frame0Link_ ? LinkFrame{F_[0]} : LinkFrame{};
    return {J_[static_cast<std::size_t>(i)]};
  }

  // The link joint 1 hangs from.
  std::string armParent(int i) const {
    if (i > 0) return linkName(i);
    return frame0Link_ ? linkName(0) : std::string(kBaseLink);
  }

  // link_0, D-H frame 0, fixed to base_link (where it is not base_link's frame).
  void frame0() {
    xml_.blank();
    xml_.comment("D-H frame 0, where joint 1's axis is its z: the frame the D-H table starts from");
    joint({jointName(0), "fixed", std::string(kBaseLink), linkName(0), place({}, F_[0]), {}, {}, {}, 1});
    xml_.element("link", {{"name", linkName(0)}});
  }

  // Frame X, given in design coordinates, in link `in`.
  Origin place(const LinkFrame& in, const Eigen::Isometry3d& X) const {
    return in.F_design_link ? design_.relative(*in.F_design_link, X) : design_.inBase(X);
  }

  void origin(const Origin& o) {
    xml_.element("origin", {{"xyz", xmlNumbers(o.xyz.x(), o.xyz.y(), o.xyz.z())},
                            {"rpy", xmlNumbers(o.rpy.x(), o.rpy.y(), o.rpy.z())}});
  }

  void header() {
    xml_.comment("Robot '" + robot_.name + "' written as URDF by robotsim's export.");
    xml_.comment("Metres (1 length unit of the description = " + xmlNumber(options_.millimetresPerUnit) +
                 " mm) and radians; z up (the description's " +
                 (options_.up == UpAxis::Y ? "y up turned by +90 degrees about x" : "z up, not turned") +
                 "). base_link is the description's design coordinates; link_i turns about (or slides along) its "
                 "own z axis; tool0 is the tool centre point (x = the normal n, z = the approach a). Every motor "
                 "at encoder 0 (home) is the zero pose. robotsim models no forces or masses: effort 0, no "
                 "inertial.");
  }

  // One material per EGA colour the geometry uses, by colour number.
  void materials() {
    std::set<int> used;
    const auto collect = [&](const workcell::Shape& s) {
      for (const SolidBox& b : solidsOf(s, thin())) used.insert(static_cast<int>(b.color));
    };
    for (const workcell::Shape& s : robot_.links) collect(s);
    if (robot_.hasGripper)
      for (const workcell::Shape* s : {&robot_.gripper.base, &robot_.gripper.finger2, &robot_.gripper.finger3})
        collect(*s);
    for (const int c : used) {
      const workcell::Rgb rgb = workcell::kEga[static_cast<std::size_t>(c)];
      const auto part = [](std::uint8_t v) { return xmlNumber(std::round(v / 255.0 * 10000) / 10000); };
      xml_.open("material", {{"name", std::string(workcell::colorName(static_cast<workcell::Color>(c)))}});
      xml_.element("color", {{"rgba", part(rgb.r) + ' ' + part(rgb.g) + ' ' + part(rgb.b) + " 1"}});
      xml_.close();
    }
  }

  double thin() const { return kThinBoxMetres * 1000 / options_.millimetresPerUnit; }

  // A link with the boxes of `shape` (none for a null shape) in its frame.
  void link(const std::string& name, const workcell::Shape* shape, const LinkFrame& frame) {
    xml_.blank();
    if (shape == nullptr) {
      xml_.element("link", {{"name", name}});
      return;
    }
    xml_.comment("drawn as " + shape->name);
    const std::vector<SolidBox> solids = solidsOf(*shape, thin());
    if (solids.empty()) {
      xml_.element("link", {{"name", name}});
      return;
    }
    xml_.open("link", {{"name", name}});
    for (const SolidBox& b : solids) {
      xml_.open("visual");
      origin(place(frame, b.F_design_box));
      xml_.open("geometry");
      const Eigen::Vector3d size = design_.metres(b.size);
      xml_.element("box", {{"size", xmlNumbers(size.x(), size.y(), size.z())}});
      xml_.close();
      xml_.element("material", {{"name", std::string(workcell::colorName(b.color))}});
      xml_.close();
    }
    xml_.close();
  }

  struct JointXml {
    std::string name, type, parent, child;
    Origin origin;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    std::optional<Limits> limits;
    std::string mimic;  // the joint it mimics, multiplier `multiplier`
    double multiplier = 1;
  };

  void joint(const JointXml& j) {
    xml_.open("joint", {{"name", j.name}, {"type", j.type}});
    origin(j.origin);
    xml_.element("parent", {{"link", j.parent}});
    xml_.element("child", {{"link", j.child}});
    if (j.type != "fixed") xml_.element("axis", {{"xyz", xmlNumbers(j.axis.x(), j.axis.y(), j.axis.z())}});
    if (j.limits)
      xml_.element("limit", {{"lower", xmlNumber(j.limits->lower)},
                             {"upper", xmlNumber(j.limits->upper)},
                             {"effort", "0"},
                             {"velocity", xmlNumber(j.limits->velocity)}});
    if (!j.mimic.empty())
      xml_.element("mimic", {{"joint", j.mimic}, {"multiplier", xmlNumber(j.multiplier)}, {"offset", "0"}});
    xml_.close();
  }

  // A joint value (degrees, or length units) in URDF's units.
  double urdfValue(JointType type, double value) const {
    return type == JointType::Revolute ? kinematics::kDegToRad * value : design_.metres(value);
  }

  Limits motorLimits(int i) const {
    const workcell::JointSpec& spec = robot_.joints[static_cast<std::size_t>(i - 1)];
    const double p = spec.precision;
    const double a = urdfValue(spec.type, p * spec.min), b = urdfValue(spec.type, p * spec.max);
    return {std::min(a, b), std::max(a, b), urdfValue(spec.type, std::abs(p) * spec.speed)};
  }

  // How much of motor k's own motion joint i makes (coupling, cascading as
  // kinematics::jointValuesFromEncoders applies it): c[i][i] = 1, and with
  // COUPLING ON on joint i-1, c[i][k] -= c[i-1][k].
  std::vector<double> couplingRow(int i) const {
    std::vector<double> c(static_cast<std::size_t>(i) + 1, 0.0);
    c[static_cast<std::size_t>(i)] = 1;
    if (i > 1 && chain_.joint(i - 1).coupling) {
      const std::vector<double> previous = couplingRow(i - 1);
      for (std::size_t k = 1; k < previous.size(); ++k) c[k] -= previous[k];
    }
    return c;
  }

  void armJoint(int i) {
    const workcell::JointSpec& spec = robot_.joints[static_cast<std::size_t>(i - 1)];
    const std::string type = spec.type == JointType::Revolute ? "revolute" : "prismatic";
    const std::string unitName = spec.type == JointType::Revolute ? "degrees" : "length units";
    xml_.blank();
    std::string motor = "joint " + std::to_string(i) + ": motor " + spec.letter + ", " + type + ", " +
                        xmlNumber(spec.precision) + " " + unitName + " per count, range " + std::to_string(spec.min) +
                        ".." + std::to_string(spec.max) + " counts, speed " + std::to_string(spec.speed) +
                        " counts/s";
    if (spec.acceleration > 0)
      motor += ", acceleration " + std::to_string(spec.acceleration) + " counts/s^2 (URDF has no acceleration limit)";
    xml_.comment(motor);
    // Joint i's motion is its own motor's plus, with coupling, a share of
    // earlier motors': one mimic joint on the same axis for each share,
    // then the joint itself. Turns (or slides) about one axis add up, so
    // the sum is exact in any order.
    const std::vector<double> c = couplingRow(i);
    std::string parent = armParent(i - 1);
    Origin at = place(armLink(i - 1), J_[static_cast<std::size_t>(i)]);
    for (int k = 1; k < i; ++k) {
      const double share = c[static_cast<std::size_t>(k)];
      if (share == 0) continue;
      xml_.comment("COUPLING ON: joint " + std::to_string(i) + " also moves by " + xmlNumber(share) +
                   " times joint " + std::to_string(k) + "'s own motion: the mimic joint below says so");
      const std::string name = jointName(i) + "_coupling_" + std::to_string(k);
      const std::string child = linkName(i) + "_coupling_" + std::to_string(k);
      const Limits own = motorLimits(k);
      const double a = share * own.lower, b = share * own.upper;
      joint({name, type, parent, child, at, Eigen::Vector3d::UnitZ(),
             Limits{std::min(a, b), std::max(a, b), std::abs(share) * own.velocity}, jointName(k), share});
      xml_.element("link", {{"name", child}});
      parent = child;
      at = Origin{};
    }
    joint({jointName(i), type, parent, linkName(i), at, Eigen::Vector3d::UnitZ(), motorLimits(i), {}, 1});
    const std::size_t shape = static_cast<std::size_t>(i);
    const workcell::Shape* drawn = shape < robot_.links.size()    ? &robot_.links[shape]
                                   : robot_.hasGripper && i == n_ ? &robot_.gripper.base
                                                                  : nullptr;
    link(linkName(i), drawn, armLink(i));
  }

  // The fingers, each on its own branch from the link that carries the
  // gripper: finger 2 turns about r2 by the gripper motor's angle, finger 3
  // about r3 by the same angle (a mimic of finger 2).
  void gripper() {
    const workcell::Gripper& g = robot_.gripper;
    const double p = g.model.precision;
    const double a = kinematics::kDegToRad * p * g.min, b = kinematics::kDegToRad * p * g.max;
    Limits limits{std::min(a, b), std::max(a, b), kinematics::kDegToRad * std::abs(p) * g.speed};
    std::string speed = "speed " + std::to_string(g.speed) + " counts/s";
    if (g.actuation > 0) {
      limits.velocity = (limits.upper - limits.lower) / (g.actuation / 1e6);
      speed = "every move takes " + xmlNumber(g.actuation / 1e6) + " s (ACTUATION): the velocity is its range in that time";
    }
    xml_.blank();
    xml_.comment("gripper " + g.name + ": motor " + g.letter + ", " + xmlNumber(p) +
                 " degrees of finger rotation per count, range " + std::to_string(g.min) + ".." +
                 std::to_string(g.max) + " counts (" + std::to_string(g.min) + " open), " + speed);
    const LinkFrame carrier = armLink(n_);
    const Eigen::Matrix3d carrierAxes =
        carrier.F_design_link ? Eigen::Matrix3d(carrier.F_design_link->linear()) : Eigen::Matrix3d::Identity();
    const auto finger = [&](int number, const kinematics::Line& axis, const workcell::Shape& shape) {
      Eigen::Isometry3d F_design_finger = Eigen::Isometry3d::Identity();
      F_design_finger.linear() = carrierAxes;
      F_design_finger.translation() = axis.point;
      const std::string name = "finger_" + std::to_string(number);
      joint({name + "_joint", "revolute", linkName(n_), name, place(carrier, F_design_finger),
             design_.directionIn(F_design_finger, axis.direction), limits, number == 3 ? "finger_2_joint" : "", 1});
      link(name, &shape, {F_design_finger});
    };
    finger(2, g.model.r2, g.finger2);
    finger(3, g.model.r3, g.finger3);
  }

  void tool() {
    xml_.blank();
    xml_.comment("the tool centre point (ROS-Industrial's tool0)");
    const std::string parent = n_ == 0 ? std::string(kBaseLink) : linkName(n_);
    joint({std::string(kToolLink) + "_joint", "fixed", parent, std::string(kToolLink),
           place(armLink(n_), F_[static_cast<std::size_t>(n_)]), {}, {}, {}, 1});
    xml_.element("link", {{"name", std::string(kToolLink)}});
  }

  const workcell::Robot& robot_;
  const kinematics::ChainModel& chain_;
  const int n_;
  DesignToUrdf design_;
  ExportOptions options_;
  std::vector<Eigen::Isometry3d> J_, F_;
  bool frame0Link_ = false;  // link_0 is written
  XmlWriter xml_;
};

}  // namespace

diag::Result<std::string> exportUrdf(const workcell::Robot& robot, const ExportOptions& options) {
  if (!robot.chain) return diag::refusal("robot '" + robot.name + "' has no kinematic chain to export");
  if (!(options.millimetresPerUnit > 0) || !std::isfinite(options.millimetresPerUnit))
    return diag::refusal("the length unit must be a positive number of millimetres");
  return Exporter(robot, options).write();
}

}  // namespace rs::urdf
