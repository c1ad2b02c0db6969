// What the KDL comparison tests share: a URDF document read by Orocos KDL's
// own URDF parser (kdl_parser) into a chain, its forward kinematics, the
// values of KDL's chain joints (a mimic joint, which KDL holds as a joint of
// its own, set from the joint it follows, as urdfdom reads the file), and an
// independent reading of the file's joints (tinyxml2, the XML as written)
// for a forward kinematics computed here with Eigen.
#pragma once

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace rs::kdltest {

/// KDL's chain from `root` to `tip` of a URDF document, and the name of
/// each of its moving joints in chain order.
struct KdlChain {
  KDL::Chain chain;
  std::vector<std::string> joints;
};

inline KdlChain kdlChain(const std::string& xml, const std::string& root, const std::string& tip) {
  KDL::Tree tree;
  REQUIRE(kdl_parser::treeFromString(xml, tree));
  KdlChain c;
  REQUIRE(tree.getChain(root, tip, c.chain));
  for (unsigned i = 0; i < c.chain.getNrOfSegments(); ++i) {
    const KDL::Joint& j = c.chain.getSegment(i).getJoint();
    if (j.getType() != KDL::Joint::None) c.joints.push_back(j.getName());
  }
  return c;
}

inline Eigen::Isometry3d toEigen(const KDL::Frame& f) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T.linear()(r, c) = f.M(r, c);
    T.translation()(r) = f.p(r);
  }
  return T;
}

/// A mimic joint as urdfdom reads it: value = multiplier × followed + offset.
struct Mimic {
  std::string joint, followed;
  double multiplier = 1, offset = 0;
};

inline std::vector<Mimic> mimicsOf(const std::string& xml) {
  const ::urdf::ModelInterfaceSharedPtr model = ::urdf::parseURDF(xml);
  REQUIRE(model);
  std::vector<Mimic> mimics;
  for (const auto& [name, joint] : model->joints_)
    if (joint->mimic) mimics.push_back({name, joint->mimic->joint_name, joint->mimic->multiplier, joint->mimic->offset});
  return mimics;
}

/// `values` (every joint that moves on its own, by name) completed with
/// the mimic joints.
inline std::map<std::string, double> withMimics(const std::vector<Mimic>& mimics, std::map<std::string, double> values) {
  for (const Mimic& m : mimics) {
    REQUIRE(values.count(m.followed) == 1);
    values[m.joint] = m.multiplier * values.at(m.followed) + m.offset;
  }
  return values;
}

/// KDL's tip pose for the joint values by name.
inline Eigen::Isometry3d kdlTip(const KdlChain& c, const std::map<std::string, double>& values) {
  KDL::JntArray q(static_cast<unsigned>(c.joints.size()));
  for (std::size_t i = 0; i < c.joints.size(); ++i) {
    INFO("joint " << c.joints[i]);
    REQUIRE(values.count(c.joints[i]) == 1);
    q(static_cast<unsigned>(i)) = values.at(c.joints[i]);
  }
  KDL::ChainFkSolverPos_recursive fk(c.chain);
  KDL::Frame tip;
  REQUIRE(fk.JntToCart(q, tip) >= 0);
  return toEigen(tip);
}

/// One joint as the XML writes it.
struct XmlJoint {
  std::string name, type, parent, child;
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // URDF's default
  double lower = 0, upper = 0;
  std::string mimic;
  double multiplier = 1, offset = 0;
};

inline Eigen::Vector3d threeNumbers(const char* text, const Eigen::Vector3d& otherwise) {
  if (text == nullptr) return otherwise;
  std::istringstream in(text);
  Eigen::Vector3d v;
  in >> v.x() >> v.y() >> v.z();
  REQUIRE(!in.fail());
  return v;
}

/// The joints of a URDF document, read with tinyxml2 as written.
inline std::vector<XmlJoint> xmlJoints(const std::string& xml) {
  tinyxml2::XMLDocument doc;
  REQUIRE(doc.Parse(xml.c_str()) == tinyxml2::XML_SUCCESS);
  std::vector<XmlJoint> joints;
  for (const tinyxml2::XMLElement* e = doc.RootElement()->FirstChildElement("joint"); e;
       e = e->NextSiblingElement("joint")) {
    XmlJoint j;
    j.name = e->Attribute("name"), j.type = e->Attribute("type");
    j.parent = e->FirstChildElement("parent")->Attribute("link");
    j.child = e->FirstChildElement("child")->Attribute("link");
    if (const auto* o = e->FirstChildElement("origin")) {
      j.xyz = threeNumbers(o->Attribute("xyz"), j.xyz);
      j.rpy = threeNumbers(o->Attribute("rpy"), j.rpy);
    }
    if (const auto* a = e->FirstChildElement("axis")) j.axis = threeNumbers(a->Attribute("xyz"), j.axis);
    if (const auto* l = e->FirstChildElement("limit")) j.lower = l->DoubleAttribute("lower"), j.upper = l->DoubleAttribute("upper");
    if (const auto* m = e->FirstChildElement("mimic")) {
      j.mimic = m->Attribute("joint");
      j.multiplier = m->DoubleAttribute("multiplier", 1.0);
      j.offset = m->DoubleAttribute("offset", 0.0);
    }
    joints.push_back(j);
  }
  return joints;
}

/// The joints from the root to `tip`, root first.
inline std::vector<XmlJoint> pathTo(const std::vector<XmlJoint>& joints, const std::string& tip) {
  std::vector<XmlJoint> path;
  for (std::string link = tip;;) {
    const XmlJoint* up = nullptr;
    for (const XmlJoint& j : joints)
      if (j.child == link) up = &j;
    if (up == nullptr) break;
    path.insert(path.begin(), *up);
    link = up->parent;
    REQUIRE(path.size() <= joints.size());
  }
  return path;
}

/// R = Rz(yaw)·Ry(pitch)·Rx(roll), URDF's fixed-axis convention.
inline Eigen::Matrix3d fromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// The tip pose by composing each joint's origin and motion along `path`
/// (mimic joints set from `values` as the file says).
inline Eigen::Isometry3d eigenTip(const std::vector<XmlJoint>& path, std::map<std::string, double> values) {
  for (const XmlJoint& j : path)
    if (!j.mimic.empty()) values[j.name] = j.multiplier * values.at(j.mimic) + j.offset;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (const XmlJoint& j : path) {
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
    origin.linear() = fromRpy(j.rpy);
    origin.translation() = j.xyz;
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    const Eigen::Vector3d axis = j.axis.normalized();
    if (j.type == "revolute" || j.type == "continuous") motion.linear() = Eigen::AngleAxisd(values.at(j.name), axis).toRotationMatrix();
    else if (j.type == "prismatic") motion.translation() = values.at(j.name) * axis;
    else REQUIRE(j.type == "fixed");
    T = T * origin * motion;
  }
  return T;
}

/// The largest difference between two poses' positions, and between their
/// rotation matrices' entries.
struct PoseError {
  double position = 0, rotation = 0;
};

inline PoseError poseError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return {(a.translation() - b.translation()).norm(), (a.linear() - b.linear()).cwiseAbs().maxCoeff()};
}

}  // namespace rs::kdltest
