#include "model/urdf/urdf_chain.h"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

#include "model/kinematics/angles.h"

namespace rs::urdf {

namespace {

using ::urdf::Joint;
using ::urdf::JointConstSharedPtr;
using ::urdf::LinkConstSharedPtr;

// The turn that stands a z-up URDF robot up in a y-up design.
const Eigen::Matrix3d& turn() {
  static const Eigen::Matrix3d m = (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished();
  return m;
}

bool moving(const Joint& j) { return j.type != Joint::FIXED; }

bool finite(const ::urdf::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finitePose(const ::urdf::Pose& p) {
  const ::urdf::Rotation& r = p.rotation;
  return finite(p.position) && std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.z) && std::isfinite(r.w);
}

Eigen::Vector3d vec(const ::urdf::Vector3& v) { return {v.x, v.y, v.z}; }

// The joint's own motion at value q (radians or metres).
Eigen::Isometry3d motion(const Joint& j, double q) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  if (q == 0.0) return m;
  const Eigen::Vector3d axis = vec(j.axis).normalized();
  if (j.type == Joint::PRISMATIC) m.translation() = q * axis;
  else if (j.type == Joint::REVOLUTE || j.type == Joint::CONTINUOUS) m.linear() = Eigen::AngleAxisd(q, axis).toRotationMatrix();
  return m;
}

double homeValue(const Joint& j) { return j.mimic ? j.mimic->offset : 0.0; }

const char* typeName(const Joint& j) {
  switch (j.type) {
    case Joint::REVOLUTE: return "revolute";
    case Joint::CONTINUOUS: return "continuous";
    case Joint::PRISMATIC: return "prismatic";
    case Joint::FLOATING: return "floating";
    case Joint::PLANAR: return "planar";
    case Joint::FIXED: return "fixed";
    default: return "unknown";
  }
}

// Every number of a joint must be finite, and a moving joint's axis long
// enough to have a direction.
bool checkJoint(const Joint& j, std::vector<ChainProblem>& problems) {
  bool ok = true;
  if (!finitePose(j.parent_to_joint_origin_transform) || !finite(j.axis) ||
      (j.limits && !(std::isfinite(j.limits->lower) && std::isfinite(j.limits->upper) &&
                     std::isfinite(j.limits->velocity))) ||
      (j.mimic && !(std::isfinite(j.mimic->multiplier) && std::isfinite(j.mimic->offset)))) {
    problems.push_back({true, j.name, fmt::format("joint '{}' has a number that is not finite (nan or inf)", j.name),
                        "write a finite number in its origin, axis, limit or mimic"});
    ok = false;
  } else if ((j.type == Joint::REVOLUTE || j.type == Joint::CONTINUOUS || j.type == Joint::PRISMATIC) &&
             vec(j.axis).norm() < 1e-12) {
    problems.push_back({true, j.name, fmt::format("joint '{}' has an axis of zero length", j.name),
                        "give its <axis xyz=\"...\"/> a direction, e.g. 0 0 1"});
    ok = false;
  }
  if (ok && j.limits && j.type != Joint::CONTINUOUS && moving(j) && j.limits->lower > j.limits->upper) {
    problems.push_back({true, j.name,
                        fmt::format("joint '{}' has its lower limit {} above its upper limit {}", j.name,
                                    j.limits->lower, j.limits->upper),
                        "swap them"});
    ok = false;
  }
  return ok;
}

}  // namespace

Eigen::Vector3d designPoint(const Eigen::Vector3d& metres) { return turn() * (1000.0 * metres); }
Eigen::Vector3d designDirection(const Eigen::Vector3d& direction) { return turn() * direction; }

Eigen::Isometry3d designFrame(const Eigen::Isometry3d& F_root_x) {
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  f.linear() = turn() * F_root_x.linear();
  f.translation() = designPoint(F_root_x.translation());
  return f;
}

Eigen::Isometry3d transformOf(const ::urdf::Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const ::urdf::Rotation& r = pose.rotation;
  t.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  t.translation() = vec(pose.position);
  return t;
}

bool UrdfChain::ok() const {
  for (const ChainProblem& p : problems)
    if (!p.warning) return false;
  return true;
}

UrdfChain extractChain(const ::urdf::ModelInterface& model, const std::string& tipName) {
  UrdfChain chain;
  const LinkConstSharedPtr root = model.getRoot();
  if (!root) {
    chain.problems.push_back({false, "", "the URDF has no root link", "every link but one must be a joint's child"});
    return chain;
  }
  chain.root = root->name;
  chain.F_design_root = designFrame(Eigen::Isometry3d::Identity());
  // Home frames of every link, root first (iteratively: a long chain must
  // not run out of stack), and each link's parent link.
  std::map<std::string, Eigen::Isometry3d> F_root;
  std::map<std::string, std::size_t> movingAbove;  // moving joints between the root and the link
  std::vector<LinkConstSharedPtr> order{root};
  F_root[root->name] = Eigen::Isometry3d::Identity();
  movingAbove[root->name] = 0;
  bool numbersOk = true;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const LinkConstSharedPtr link = order[k];  // a copy: order grows below
    for (const auto& j : link->child_joints) {
      if (!j) continue;
      if (!checkJoint(*j, chain.problems)) {
        numbersOk = false;
        continue;
      }
      const LinkConstSharedPtr child = model.getLink(j->child_link_name);
      if (!child || F_root.contains(child->name)) continue;
      F_root[child->name] = F_root[link->name] * transformOf(j->parent_to_joint_origin_transform) * motion(*j, homeValue(*j));
      movingAbove[child->name] = movingAbove[link->name] + (moving(*j) ? 1 : 0);
      order.push_back(child);
    }
  }
  if (!numbersOk) return chain;
  // The tip: as asked, or the one leaf that moving joints lead to.
  LinkConstSharedPtr tip;
  if (!tipName.empty()) {
    tip = model.getLink(tipName);
    if (!tip) {
      chain.problems.push_back({false, "", fmt::format("there is no link '{}' to end the chain at (--tip)", tipName),
                                "name one of the file's <link> elements"});
      return chain;
    }
  } else {
    std::vector<LinkConstSharedPtr> leaves;
    for (const LinkConstSharedPtr& l : order)
      if (l->child_joints.empty() && movingAbove[l->name] > 0) leaves.push_back(l);
    if (leaves.empty()) {
      chain.problems.push_back({false, root->name, fmt::format("no moving joint leads from the root link '{}'", root->name),
                                "a robot needs a revolute, continuous or prismatic joint"});
      return chain;
    }
    if (leaves.size() > 1) {
      // Name the joints where the paths to the first two leaves part.
      std::vector<JointConstSharedPtr> a, b;
      for (LinkConstSharedPtr l = leaves[0]; l && l->parent_joint; l = l->getParent()) a.insert(a.begin(), l->parent_joint);
      for (LinkConstSharedPtr l = leaves[1]; l && l->parent_joint; l = l->getParent()) b.insert(b.begin(), l->parent_joint);
      std::size_t i = 0;
      while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
      const std::string ja = i < a.size() ? a[i]->name : "", jb = i < b.size() ? b[i]->name : "";
      std::string names;
      for (const LinkConstSharedPtr& l : leaves) names += fmt::format("{}'{}'", names.empty() ? "" : ", ", l->name);
      chain.problems.push_back({true, ja,
                                fmt::format("the tree branches at joints '{}' and '{}': {} leaves ({}) could end the chain",
                                            ja, jb, leaves.size(), names),
                                fmt::format("give --tip LINK, e.g. --tip {}", leaves[0]->name)});
      return chain;
    }
    tip = leaves[0];
  }
  chain.tip = tip->name;
  // The path, root to tip.
  std::vector<LinkConstSharedPtr> path;
  for (LinkConstSharedPtr l = tip; l; l = l->getParent()) path.insert(path.begin(), l);
  std::map<std::string, std::size_t> indexOnPath;  // robotsim link of each link of the path
  std::size_t index = 0;
  std::map<std::string, std::size_t> jointIndex;  // chain joints by name, 0-based
  for (const LinkConstSharedPtr& l : path) {
    const JointConstSharedPtr& j = l->parent_joint;
    if (j && moving(*j)) {
      if (j->type == Joint::FLOATING || j->type == Joint::PLANAR || j->type == Joint::UNKNOWN) {
        chain.problems.push_back({true, j->name,
                                  fmt::format("joint '{}' is {}: robotsim's joints turn or slide along one axis",
                                              j->name, typeName(*j)),
                                  "a robot's chain has revolute, continuous, prismatic and fixed joints only"});
        continue;
      }
      ChainJoint cj;
      cj.name = j->name;
      cj.type = j->type == Joint::PRISMATIC ? kinematics::JointType::Prismatic : kinematics::JointType::Revolute;
      cj.continuous = j->type == Joint::CONTINUOUS;
      const Eigen::Isometry3d F_joint = F_root[l->getParent()->name] * transformOf(j->parent_to_joint_origin_transform);
      cj.point = designPoint(F_joint.translation());
      cj.direction = designDirection(F_joint.linear() * vec(j->axis).normalized()).normalized();
      cj.F_design_child = designFrame(F_root[l->name]);
      cj.F_design_parent = designFrame(F_root[l->getParent()->name]);
      if (j->limits) {
        cj.hasLimits = true;
        cj.lower = j->limits->lower, cj.upper = j->limits->upper, cj.velocity = j->limits->velocity;
      }
      jointIndex[j->name] = chain.joints.size();
      chain.joints.push_back(cj);
      ++index;
    }
    indexOnPath[l->name] = index;
  }
  if (!chain.ok()) return chain;
  if (chain.joints.empty()) {
    chain.problems.push_back({false, tip->name,
                              fmt::format("no moving joint between the root link '{}' and the tip '{}'", root->name, tip->name),
                              "end the chain at a link that a revolute, continuous or prismatic joint moves"});
    return chain;
  }
  // Mimic joints of the chain: COUPLING where it says the same.
  for (std::size_t k = 0; k < chain.joints.size(); ++k) {
    const JointConstSharedPtr j = model.getJoint(chain.joints[k].name);
    if (!j || !j->mimic) continue;
    const ::urdf::JointMimic& m = *j->mimic;
    const auto master = jointIndex.find(m.joint_name);
    const bool previous = master != jointIndex.end() && master->second + 1 == k;
    if (!previous || std::abs(m.multiplier + 1.0) > 1e-12 || chain.joints[k - 1].type != chain.joints[k].type) {
      chain.problems.push_back(
          {true, j->name,
           fmt::format("joint '{}' mimics '{}' with multiplier {}, which robotsim's COUPLING cannot say", j->name,
                       m.joint_name, m.multiplier),
           "COUPLING makes a joint turn back by the motion of the joint just before it on the chain (a mimic of "
           "that joint with multiplier -1, of the same type)"});
      continue;
    }
    chain.joints[k - 1].coupling = true;
    chain.joints[k].mimics = true;
  }
  // Every link drawn with the chain link it hangs from; moving joints off
  // the chain are held at home.
  std::set<std::string> heldWarned;
  for (const LinkConstSharedPtr& l : order) {
    LinkConstSharedPtr at = l;
    std::vector<JointConstSharedPtr> held;
    while (at && !indexOnPath.contains(at->name)) {
      if (at->parent_joint && moving(*at->parent_joint)) held.push_back(at->parent_joint);
      at = at->getParent();
    }
    if (!at) continue;
    for (const JointConstSharedPtr& h : held)
      if (heldWarned.insert(h->name).second)
        chain.problems.push_back({true, h->name,
                                  fmt::format("joint '{}' is not on the chain from '{}' to '{}': its links are drawn "
                                              "at its zero pose, fixed to the chain",
                                              h->name, chain.root, chain.tip),
                                  "", true});
    const std::size_t i = indexOnPath[at->name];
    if (chain.links.size() <= i) chain.links.resize(i + 1);
    chain.links[i].push_back({l, F_root[l->name]});
  }
  chain.links.resize(chain.joints.size() + 1);
  chain.F_design_tip = designFrame(F_root[tip->name]);
  return chain;
}

}  // namespace rs::urdf
